// ESLint (flat config) over the pages' own JavaScript: the recommended rules, browser
// globals, ES modules. Run by `make check` and `make test` (target `jslint`) and by the
// pre-commit hook; the types of the same files are checked by `tsc -p jsconfig.json`.
import js from "@eslint/js";
import globals from "globals";

export default [
  { ignores: ["node_modules/", ".venv/", "var/", "frontend/vendor/"] },
  {
    files: ["frontend/**/*.js"],
    ...js.configs.recommended,
    languageOptions: {
      ecmaVersion: "latest",
      sourceType: "module",
      globals: globals.browser,
    },
    rules: {
      ...js.configs.recommended.rules,
      // every page module's types are checked (docs/decisions/0021-checkjs-scope.md)
      "no-warning-comments": ["error", { terms: ["@ts-nocheck", "@ts-ignore"], location: "start" }],
    },
  },
  {
    files: ["eslint.config.mjs"],
    ...js.configs.recommended,
    languageOptions: { ecmaVersion: "latest", sourceType: "module", globals: globals.node },
  },
];
