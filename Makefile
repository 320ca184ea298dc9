# Build, test and benchmark the railtrack book and package.
#
#   make book    build the HTML book (every notebook re-executed) into _build/html
#   make test    pytest over tests/, then nbval over every notebook under book/
#   make bench   run benchmarks/bench.py
#   make clean   remove _build
#
# Everything is fetched when .venv is created (pip, from environment.txt,
# MathJax included); building and testing need no network.

SHELL := bash
.SHELLFLAGS := -eu -o pipefail -c
.DELETE_ON_ERROR:
.DEFAULT_GOAL := help

VENV        := .venv
PY          := $(VENV)/bin/python
STAMP       := $(VENV)/.stamp
# Python 3.11.x is required; python3 is accepted only if it is a 3.11.
# (Resolved here, before PATH is changed below to put .venv/bin first.)
ifeq ($(origin PYTHON),undefined)
PYTHON      := $(shell command -v python3.11 2>/dev/null || command -v python3 2>/dev/null)
endif

# MathJax 3.2.2 comes from the pinned PyPI package django-static-mathjax; its
# es5/ build is copied into book/_static/mathjax (git-ignored), which Sphinx
# copies to _build/html/_static/mathjax (see mathjax_path in _config.yml).
MATHJAX_DIR := book/_static/mathjax
MATHJAX     := $(MATHJAX_DIR)/tex-mml-svg.js

SANITIZE    := tests/nbval_sanitize.cfg
NB_TIMEOUT  := 120

# The kernel must be the venv's Python, whatever kernelspecs the user has.
export PATH := $(CURDIR)/$(VENV)/bin:$(PATH)
export JUPYTER_PREFER_ENV_PATH := 1
export PYDEVD_DISABLE_FILE_VALIDATION := 1
unexport VIRTUAL_ENV PYTHONPATH PYTHONHOME

.PHONY: help venv book test bench clean distclean

help:
	@echo "make book   - build the HTML book into _build/html (re-executes every notebook)"
	@echo "make test   - pytest over tests/ and nbval over book/**/*.ipynb"
	@echo "make bench  - run benchmarks/bench.py"
	@echo "make clean  - remove _build (make distclean also removes .venv and MathJax)"

# (Re)create the venv whenever the pins or the project metadata change.
$(STAMP): environment.txt pyproject.toml
	@if [ -z "$(PYTHON)" ]; then echo "error: python3.11 not found" >&2; exit 1; fi
	@$(PYTHON) -c 'import sys; sys.exit(0 if sys.version_info[:2] == (3, 11) else 1)' || \
	  { echo "error: $(PYTHON) is Python $$($(PYTHON) -c 'import platform; print(platform.python_version())'), 3.11.x is required" >&2; exit 1; }
	rm -rf $(VENV)
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --no-input --disable-pip-version-check -r environment.txt
	$(PY) -m pip install --no-input --disable-pip-version-check --no-deps --no-build-isolation -e .
	$(PY) -m pip check
	touch $@

$(MATHJAX): $(STAMP)
	rm -rf $(MATHJAX_DIR)
	mkdir -p $(dir $(MATHJAX_DIR))
	src=$$($(PY) -c 'import mathjax, pathlib; print(pathlib.Path(mathjax.__file__).parent / "static" / "mathjax" / "es5")'); \
	  test -f "$$src/tex-mml-svg.js"; \
	  cp -R "$$src" $(MATHJAX_DIR)
	touch $@

venv: $(STAMP) $(MATHJAX)

book: $(STAMP) $(MATHJAX)
	$(VENV)/bin/jupyter-book build . --all -W -n --keep-going
	@echo
	@echo "The book is at $(CURDIR)/_build/html/index.html"

# Both steps always run; the target fails if either fails.  nbval compares
# the stored outputs of every notebook under book/ with a fresh run.
test: $(STAMP)
	@status=0; \
	notebooks=$$(find book -name '*.ipynb' -not -path '*/.ipynb_checkpoints/*' -not -path '*/_build/*' | sort); \
	if [ -z "$$notebooks" ]; then echo "== nbval: no notebooks under book/ yet, nothing to compare"; fi; \
	echo "== pytest: tests/"; \
	$(PY) -m pytest tests || status=1; \
	if [ -n "$$notebooks" ]; then \
	  echo "== nbval: "$$notebooks; \
	  $(PY) -m pytest --nbval --nbval-current-env --nbval-sanitize-with $(SANITIZE) \
	    --nbval-cell-timeout=$(NB_TIMEOUT) $$notebooks || status=1; \
	fi; \
	if [ $$status -ne 0 ]; then echo "make test: FAILED" >&2; fi; \
	exit $$status

bench: $(STAMP)
	$(PY) benchmarks/bench.py

clean:
	rm -rf _build

distclean: clean
	rm -rf $(VENV) $(MATHJAX_DIR)
