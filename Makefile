# spinimpact: the two commands a newcomer needs are `make demo` and `make test`
# (`make check`: the quick subset of the tests; `make help`: every command).
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
BASE   := $(VENV)/.installed-base
# Where `make images` and `make validation` draw their figures: git-ignored folders, so a
# plain run never touches a tracked file. `make images IMAGES=docs/images` and
# `make validation VALIDATION=docs/images` refresh the figures the docs show.
IMAGES     ?= build/images
VALIDATION ?= build/validation

.PHONY: help demo test check bench lint images validation docs clean

help:  ## list these commands
	@awk -F':.*## ' '/^[a-z]+:.*## / {printf "  make %-11s %s\n", $$1, $$2}' $(firstword $(MAKEFILE_LIST))

$(PY):
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip

# Reinstall whenever the project metadata changes. The demo needs the package alone;
# the tests install every optional extra they cover.
$(BASE): pyproject.toml | $(PY)
	$(PY) -m pip install --quiet -e .
	touch $(BASE)

$(STAMP): pyproject.toml | $(PY)
	$(PY) -m pip install --quiet -e '.[test,parquet,fast,dask,engines,jax,docs,explore]'
	touch $(STAMP)

DOCS_STAMP := $(VENV)/.installed-docs
$(DOCS_STAMP): pyproject.toml | $(STAMP)
	$(PY) -m pip install --quiet -e '.[docs]'
	touch $(DOCS_STAMP)

docs: $(DOCS_STAMP)  ## build the documentation site into build/docs/html (warnings are errors)
	$(VENV)/bin/sphinx-build -W --keep-going -q -b html docs build/docs/html

demo: $(BASE)  ## solve the documented default impact and print the report
	$(VENV)/bin/spinimpact solve

# make test runs the tests on two pytest-xdist workers, a test file each at a time (WORKERS=0:
# all in this one process); a test marked alone still runs with no other test beside it.
WORKERS ?= 2

test: $(STAMP) docs  ## build the documentation site, then run the whole test suite (what CI runs)
	$(PY) -m pytest -n $(WORKERS) --dist loadfile

check: $(STAMP)  ## the everyday quick subset: every test but the slow and browser ones, 25 examples a property
	SPINIMPACT_HYPOTHESIS=quick $(PY) -m pytest -m "not slow and not browser"

bench: $(STAMP)  ## print benchmark ratios (not part of the tests)
	$(PY) -m benchmarks.bench

images: $(STAMP)  ## draw the docs' figures into build/images (git-ignored); IMAGES=docs/images refreshes the published ones
	mkdir -p $(IMAGES)
	$(VENV)/bin/spinimpact map --output $(IMAGES)/map.png --resolution 800 --dpi 80
	$(VENV)/bin/spinimpact figures --output-dir $(IMAGES) --dpi 80
	$(PY) docs/scripts/convergence.py $(IMAGES)/convergence.png
	$(PY) docs/scripts/engines.py $(IMAGES)/engines.png
	$(PY) docs/scripts/engine_restitution.py $(IMAGES)/engine_restitution.png > /dev/null
	$(VENV)/bin/spinimpact planar --body rod --orientation-deg 45 --mu 0.3 --kappa 0.8 --plot $(IMAGES)/routh_planar.png --dpi 80 > /dev/null
	$(VENV)/bin/spinimpact planar --body rod --mu 0.8 --kappa 0.9 --law newton --map-plot $(IMAGES)/planar_map.png --resolution 300 --dpi 80 > /dev/null
	$(PY) docs/scripts/fit_kharaz.py $(IMAGES)/fit_kharaz.png
	$(PY) docs/scripts/flight.py $(IMAGES)
	$(PY) docs/scripts/explorer.py $(IMAGES)

validation: $(STAMP)  ## every model against Kharaz et al. (2001) and the Chung & Ooi (2011) tests; figures in build/validation (VALIDATION=docs/images refreshes the published ones)
	$(PY) -m benchmarks.validation kharaz --output $(VALIDATION)
	for t in 1 2 3 4 5 6; do $(PY) -m benchmarks.validation chung-ooi --test $$t || exit 1; done

lint: $(STAMP)
	$(VENV)/bin/ruff check src tests
	$(VENV)/bin/ruff format --check src tests

clean:
	rm -rf $(VENV) build dist src/*.egg-info .pytest_cache .hypothesis
