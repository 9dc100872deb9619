# Two commands on a fresh machine: `make run` serves the app, `make test` runs every check.
# Each installs what it needs into .venv from the hash-pinned requirements.lock, and the
# page's plotly.js bundle and the JavaScript tools (ESLint, TypeScript, axe-core) into
# node_modules/ from package-lock.json (npm, integrity-checked). `make check` is the fast tier.

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-$(shell cksum requirements.lock | cut -d' ' -f1)
NODE_STAMP := node_modules/.installed-$(shell cat package.json package-lock.json | cksum | cut -d' ' -f1)

.PHONY: install run test check lint typecheck jslint pytest bench lock messages api-types mechanisms clean

$(STAMP): requirements.lock
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check \
		--require-hashes --no-deps -r requirements.lock
	@# The package is used in place from backend/ (an editable install without a build backend).
	$(BIN)/python -c "import pathlib, sysconfig; \
		pathlib.Path(sysconfig.get_paths()['purelib'], 'actuator_selection.pth') \
		.write_text(str(pathlib.Path('backend').resolve()) + '\n')"
	rm -f $(VENV)/.installed-*
	touch $@

# npm ci installs exactly the lock (integrity hashes checked) into a fresh node_modules/
# and runs no package scripts.
$(NODE_STAMP): package.json package-lock.json
	npm ci --ignore-scripts --no-audit --no-fund
	touch $@

install: $(STAMP) $(NODE_STAMP)

## Serve on http://$HOST:$PORT (default 127.0.0.1:8000) with the embedded SQLite
## database (or $DATABASE_URL), migrated and seeded with the starter catalogue; a database
## without price lists gets the EXAMPLE one, and without SELLER_* quotes name an EXAMPLE seller.
run: install
	$(BIN)/python -m actuator_selection migrate
	$(BIN)/python -m actuator_selection seed --if-empty --examples
	$(BIN)/python -m actuator_selection serve --examples

## The whole suite: lint, format, strict types, the page's lint and types, and every test
## (unit, doctests, database, API, real server, fuzz, browser; SQLite and PostgreSQL).
test: install lint typecheck jslint pytest

## The fast tier, for every change (under 3 minutes on 2 idle cores): the same lint, format
## and type checks, and the tests that need neither a browser, a real server nor PostgreSQL
## (the core's unit tests and doctests, the database and the API on SQLite).
## `make test` stays the whole suite, and CI's.
FAST_TESTS := tests/test_purity.py tests/sizing tests/catalogue tests/sales tests/phrases tests/db tests/api backend/actuator_selection/sizing backend/actuator_selection/catalogue backend/actuator_selection/sales backend/actuator_selection/phrases backend/actuator_selection/i18n backend/actuator_selection/errors.py backend/actuator_selection/text.py backend/actuator_selection/documents/symbols.py

check: install lint typecheck jslint
	$(BIN)/python -m pytest -n auto -q -k "not postgresql" -m "not slow" $(FAST_TESTS)

lint: install
	$(BIN)/ruff check .
	$(BIN)/ruff format --check .

typecheck: install
	$(BIN)/mypy

## The page's JavaScript: ESLint's recommended rules (eslint.config.mjs) and TypeScript's
## checkJs over frontend/ (jsconfig.json), both from package-lock.json.
jslint: install
	node_modules/.bin/eslint .
	node_modules/.bin/tsc -p jsconfig.json

pytest: install
	$(BIN)/python -m pytest -n auto

## Throughput of the selection engine, and the engineer's page's cold load to both
## charts in headless Chromium (not part of the tests). Each bench adds its verdicts on
## issue 32's targets to BENCH_RESULTS; the last command prints them as the issue's table.
bench: export BENCH_RESULTS := $(abspath .bench-results.jsonl)
bench: install
	rm -f $(BENCH_RESULTS)
	$(BIN)/python -m bench.selection
	$(BIN)/python -m bench.fixed_cost
	$(BIN)/python -m bench.instructions
	$(BIN)/python -m bench.batch
	$(BIN)/python -m bench.ratio
	$(BIN)/python -m bench.catalogue
	$(BIN)/python -m bench.page
	$(BIN)/python -m bench.http
	$(BIN)/python -m bench.profile
	$(BIN)/python -m bench.jobs
	$(BIN)/python -m bench.targets $(BENCH_RESULTS)

## A longer fuzz run than the suite's (not part of `make test`): schemathesis gives every
## operation FUZZ_MAX_EXAMPLES requests and walks the OpenAPI links in stateful chains of
## FUZZ_MAX_STEPS calls (tests/fuzz), on SQLite and PostgreSQL; FUZZ_RANDOM=1 draws anew.
.PHONY: fuzz
fuzz: install
	FUZZ_STATEFUL=1 FUZZ_MAX_EXAMPLES=$${FUZZ_MAX_EXAMPLES:-100} $(BIN)/python -m pytest -n auto tests/fuzz

## Re-resolve requirements.lock from pyproject.toml (needs the registry).
lock: install
	$(BIN)/python -m pip install --quiet uv
	$(BIN)/uv pip compile pyproject.toml --extra dev --generate-hashes --python-version 3.11 \
		--python-platform x86_64-manylinux_2_28 --no-header --no-annotate -o requirements.lock
	@# The image's runtime dependencies alone (Dockerfile), resolved to the same versions.
	$(BIN)/uv pip compile pyproject.toml --generate-hashes --python-version 3.11 \
		--python-platform x86_64-manylinux_2_28 --no-header --no-annotate \
		--constraint requirements.lock -o requirements-runtime.lock

## The catalogue of words (docs/i18n.md): re-extract the server's messages (N_ in the code),
## keep the keyed words declared in the catalogue (msgctxt: the page's keys, document.*),
## merge both into backend/actuator_selection/i18n/locale/*/LC_MESSAGES/messages.po, and export
## the page's words to frontend/lib/messages.js (checked in; a test fails when it is stale).
## Then translate every new or fuzzy entry. The catalogs are read as .po at run time.
messages: install
	mkdir -p var
	$(BIN)/pybabel extract -F babel.cfg -k N_ --no-default-keywords --sort-output \
		--no-location --width 100 --project actuator-selection -o var/messages.pot backend
	$(BIN)/python -m actuator_selection.i18n.page_words template var/messages.pot
	@# The template has no locations (extract --no-location), so neither has the catalog.
	$(BIN)/pybabel update -i var/messages.pot -d backend/actuator_selection/i18n/locale -D messages \
		--ignore-obsolete --width 100
	$(BIN)/python -m actuator_selection.i18n.page_words export

## The page's types of the API's requests and answers (types/api.d.ts), generated from
## /openapi.json by openapi-typescript (package-lock.json); run after changing a schema:
## tests/api/test_generated_typescript.py fails while the file is stale.
api-types: install
	$(BIN)/python -m tests.api.test_generated_typescript

## The page's load kinds and their fields, written from the request models
## (schemas/mechanism_spec.py, also GET /api/v1/mechanisms); a test fails while it is stale.
mechanisms: install
	$(BIN)/python -m actuator_selection.schemas.mechanism_spec frontend/pages/engineer/mechanism-spec.js

clean:
	rm -rf $(VENV) node_modules var .mypy_cache .ruff_cache .pytest_cache
