// Types for `tsc -p jsconfig.json` (checkJs) that the pages' JavaScript cannot state
// itself (kept outside frontend/, which the app serves).

interface Window {
  /** plotly.js, once the bundle served at /vendor/plotly-basic-<version>.min.js has run. */
  Plotly?: any;
}
