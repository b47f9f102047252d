# Quick start (see README): `make demo` runs the flagship example, `make test` the test suite.
# Both create .venv (with the Python found below) and install sealsim into it when needed.
PYTHON ?= $(shell command -v python3.11 2>/dev/null || command -v python3)
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.sealsim-installed
DEMO_CASE := examples/rotary/speed_cycle.toml
DEMO_OUT  := results/speed_cycle

DOCS_STAMP := $(VENV)/.sealsim-docs-installed

.PHONY: demo test bench docs docs-install clean

# The first install takes about 2 minutes: say so, and let pip show what it is doing.
$(STAMP): pyproject.toml
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	@echo "installing sealsim and its dependencies into $(VENV) (first time: about 2 minutes)"
	$(BIN)/python -m pip install --progress-bar off --disable-pip-version-check -e ".[test]"
	@touch $(STAMP)

demo: $(STAMP)
	$(BIN)/sealsim rotary run $(DEMO_CASE) --out $(DEMO_OUT) --force

# pytest exits with 5 when it collected no tests: that must fail, not pass silently.
# --dist loadgroup: the browser tests (xdist group "browser") share one app server and browser.
test: $(STAMP)
	@$(BIN)/python -m pytest -n 2 --dist loadgroup -q; rc=$$?; \
	if [ $$rc -eq 5 ]; then echo "make test: pytest collected no tests" >&2; exit 1; fi; \
	exit $$rc

# The docs extra comes with the test extra, so this install also stands for $(STAMP): the CI
# (.ci/run) runs `make docs-install` first and then `make test` and `make docs` install nothing
# (one install instead of a second that rebuilds sealsim and resolves everything again).
$(DOCS_STAMP): pyproject.toml
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	@echo "installing sealsim with its test and docs extras into $(VENV)"
	$(BIN)/python -m pip install --progress-bar off --disable-pip-version-check -e ".[test,docs]"
	@touch $(DOCS_STAMP) $(STAMP)

docs-install: $(DOCS_STAMP)

# HTML into docs/_build/html; every warning is an error, nothing is downloaded, and -E plus the
# regenerated docs/_generated/ make each build start from the code as it is now. About 5-6
# minutes on 2 cores in a fresh clone (the gallery's examples compile the models first); -j auto
# reads and writes the pages in parallel: after a test run (numba caches warm) 70 s instead of
# 92 s, the same pages (measured 2026-11-28). Sphinx prints each stage as it goes.
docs: $(DOCS_STAMP)
	@echo "building the documentation (about 5-6 minutes; the gallery runs every example)"
	$(BIN)/python -m sphinx -j auto -b html -E -W --keep-going -d docs/_build/doctrees docs docs/_build/html
	@echo "documentation: docs/_build/html/index.html"

bench: $(STAMP)
	@for b in benchmarks/bench_*.py; do echo "== $$b"; $(BIN)/python $$b || exit 1; done

clean:
	rm -rf $(VENV) results .pytest_cache .hypothesis docs/_build docs/_generated
