# Build, test and benchmark the railtrack book and package.
#
#   make venv    only the environment: .venv (the pins of environment.txt, railtrack
#                editable) and MathJax in book/_static; every other target makes it first
#   make book    build the HTML book (every notebook re-executed) into _build/html
#   make test    ruff on the notebooks, pytest over tests/ and nbval over every notebook
#                under book/ (on every core), then the
#                book built from the notebooks' stored outputs with Sphinx warnings as
#                errors, every page of it opened in headless Chromium (screenshots in
#                _build/screenshots), and the student edition checked for leaked solutions
#   make book-student  the book without solutions, into _build/student/_build/html
#   make pdf     the book as PDF, solutions in an appendix, and the student edition's
#                PDF, into _build/pdf (headless Chromium prints a single-page build);
#                fails if a chapter prints on more than 25 pages
#   make lab     JupyterLab on the book's notebooks with the project's kernel
#   make test-roundoff  nbval over every notebook with every Track's masses,
#                stiffnesses and dampings changed by 1e-12 and two BLAS threads:
#                a printed digit that changes is decided by round-off
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
# Seconds per cell, as execute.timeout in _config.yml.
NB_TIMEOUT  := 300

# The kernel must be the venv's Python, whatever kernelspecs the user has.
export PATH := $(CURDIR)/$(VENV)/bin:$(PATH)
export JUPYTER_PREFER_ENV_PATH := 1
export PYDEVD_DISABLE_FILE_VALIDATION := 1
# Matplotlib's font cache in the venv, not in ~/.cache: a cache written by
# another clone's venv names that venv's fonts, and once that clone is gone
# every figure warns on stderr ("findfont: ... not found"), which nbval reads
# as a changed output.
export MPLCONFIGDIR := $(CURDIR)/$(VENV)/matplotlib
unexport VIRTUAL_ENV PYTHONPATH PYTHONHOME

.PHONY: help venv book book-student pdf lab test test-roundoff bench clean distclean

help:
	@echo "make venv   - only the environment: .venv with the pins of environment.txt, railtrack editable"
	@echo "make book   - build the HTML book into _build/html (re-executes every notebook)"
	@echo "make test   - pytest over tests/, nbval over book/**/*.ipynb, the rendered book's checks"
	@echo "make book-student - the book without solutions, into _build/student"
	@echo "make pdf    - the book and its student edition as PDF, into _build/pdf"
	@echo "make lab    - JupyterLab on the notebooks (http://127.0.0.1:$(LAB_PORT)/lab)"
	@echo "make test-roundoff - the notebooks re-run with every Track perturbed by 1e-12"
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

# The editions built from the notebooks' stored outputs (tools/editions.py):
# seconds instead of minutes, since nothing is executed.
STORED      := _build/stored
STUDENT     := _build/student
LAB_PORT    ?= 8888

# $(call edition,KIND,OUT[,BUILDER]): write the KIND edition's sources
# (stored, student or appendix) to OUT-src and build them into OUT with
# Sphinx warnings as errors; the log is OUT-build.log, and on failure its
# warnings and errors are shown (or its tail, if it has none).
edition = $(PY) tools/editions.py $(1) $(2)-src && \
  { $(VENV)/bin/jupyter-book build $(2)-src --all -W -n --keep-going \
      --builder $(or $(3),html) --path-output $(2) > $(2)-build.log 2>&1 || \
    { grep -E 'WARNING|ERROR' $(2)-build.log || tail -n 40 $(2)-build.log; false; }; }

book-student: $(STAMP) $(MATHJAX)
	$(call edition,student,$(STUDENT))
	$(PY) tools/editions.py check-student $(STUDENT)/_build/html
	@echo "The student edition is at $(CURDIR)/$(STUDENT)/_build/html/index.html"

# The PDFs: each edition built from the stored outputs on one page (Sphinx's
# singlehtml builder) and printed by headless Chromium (tools/print_pdf.py
# says why this route and not LaTeX).  About a minute for both.  The book's
# pages per chapter are then counted (tools/chapter_pages.py, which also
# lists the near-empty pages): a chapter over CHAPTER_PAGES fails the target,
# the page budget of a chapter a lecturer can teach (issue 30).
PDF         := _build/pdf
CHAPTER_PAGES ?= 25

pdf: $(STAMP) $(MATHJAX)
	$(call edition,appendix,$(PDF)/book,singlehtml)
	$(PY) tools/print_pdf.py $(PDF)/book/_build/singlehtml $(PDF)/railtrack-book.pdf
	$(call edition,student,$(PDF)/student,singlehtml)
	$(PY) tools/editions.py check-student $(PDF)/student/_build/singlehtml
	$(PY) tools/print_pdf.py $(PDF)/student/_build/singlehtml $(PDF)/railtrack-book-student.pdf
	@echo "The PDFs are $(CURDIR)/$(PDF)/railtrack-book.pdf and railtrack-book-student.pdf"
	$(PY) tools/chapter_pages.py --limit $(CHAPTER_PAGES) $(PDF)/railtrack-book.pdf

# JupyterLab on this machine only (127.0.0.1), the venv's kernel; Ctrl-C stops it.
# Offline: no extension manager asking PyPI, no news, no update check.
# (--allow-root only where make runs as root, as in a container.)
lab: $(STAMP)
	$(VENV)/bin/jupyter lab --ServerApp.ip=127.0.0.1 --ServerApp.port=$(LAB_PORT) \
	  --ServerApp.root_dir=$(CURDIR)/book --no-browser \
	  --LabApp.extension_manager=readonly --LabApp.news_url=None \
	  --LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate \
	  $(if $(filter 0,$(shell id -u)),--allow-root)

# Every step always runs; the target fails if any fails.  nbval compares
# the stored outputs of every notebook under book/ with a fresh run.  The
# tests and the notebooks share one pytest run spread over every core
# (pytest-xdist; --dist loadscope keeps each notebook, and each test module,
# on one worker, in order); one BLAS thread per worker, so that the workers
# do not compete for the cores.
TEST_WORKERS ?= auto
test: $(STAMP) $(MATHJAX)
	@status=0; \
	notebooks=$$(find book -name '*.ipynb' -not -path '*/.ipynb_checkpoints/*' -not -path '*/_build/*' | sort); \
	if [ -z "$$notebooks" ]; then echo "== nbval: no notebooks under book/ yet, nothing to compare"; fi; \
	echo "== ruff: the notebooks' code is formatted and fits the page (76 columns)"; \
	{ $(VENV)/bin/ruff format --check --quiet . && $(VENV)/bin/ruff check --quiet .; } || status=1; \
	echo "== pytest over tests/ and nbval over "$$notebooks", on $(TEST_WORKERS) workers"; \
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1 \
	  $(PY) -m pytest -n $(TEST_WORKERS) --dist loadscope tests $$notebooks \
	    --nbval --nbval-current-env --nbval-sanitize-with $(SANITIZE) \
	    --nbval-cell-timeout=$(NB_TIMEOUT) --durations=25 || status=1; \
	echo "== the book from its stored outputs, Sphinx warnings and broken references as errors"; \
	{ $(call edition,stored,$(STORED)); } || status=1; \
	echo "== headless Chromium on every page of that build (tests/rendered)"; \
	$(PY) -m pytest -q tests/rendered/test_pages.py --book-html $(STORED)/_build/html || status=1; \
	echo "== the student edition: no solution may reach it"; \
	{ $(call edition,student,$(STUDENT)) && \
	  $(PY) tools/editions.py check-student $(STUDENT)/_build/html; } || status=1; \
	if [ $$status -ne 0 ]; then echo "make test: FAILED" >&2; fi; \
	exit $$status

# The round-off probe (tests/roundoff/sitecustomize.py): every notebook re-run
# with the masses, stiffnesses and dampings of every Track changed by 1e-12
# (relative) and BLAS on two threads, compared by nbval with the stored
# outputs.  A printed digit that changes here is decided by round-off and
# would differ on another machine.  About 3 minutes on 2 cores; on a fresh
# clone make test takes 12 minutes (venv included) and make book 7.5 more
# (measured for issue 28), so it is a target of its own.
ROUNDOFF_PROBE ?= 1e-12
test-roundoff: $(STAMP) $(MATHJAX)
	notebooks=$$(find book -name '*.ipynb' -not -path '*/.ipynb_checkpoints/*' -not -path '*/_build/*' | sort); \
	PYTHONPATH=$(CURDIR)/tests/roundoff RAILTRACK_ROUNDOFF_PROBE=$(ROUNDOFF_PROBE) \
	OMP_NUM_THREADS=2 OPENBLAS_NUM_THREADS=2 MKL_NUM_THREADS=2 \
	  $(PY) -m pytest -p no:cacheprovider -n $(TEST_WORKERS) --dist loadscope $$notebooks \
	    --nbval --nbval-current-env --nbval-sanitize-with $(SANITIZE) \
	    --nbval-cell-timeout=$(NB_TIMEOUT)

bench: $(STAMP)
	$(PY) benchmarks/bench.py

clean:
	rm -rf _build

distclean: clean
	rm -rf $(VENV) $(MATHJAX_DIR)
