# spinimpact: the two commands a newcomer needs are `make demo` and `make test`.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
BASE   := $(VENV)/.installed-base

.PHONY: demo test bench lint images validation clean

$(PY):
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip

# Reinstall whenever the project metadata changes. The demo needs the package alone;
# the tests install every optional extra they cover.
$(BASE): pyproject.toml | $(PY)
	$(PY) -m pip install --quiet -e .
	touch $(BASE)

$(STAMP): pyproject.toml | $(PY)
	$(PY) -m pip install --quiet -e '.[test,parquet,fast,dask,engines,jax]'
	touch $(STAMP)

demo: $(BASE)  ## solve the documented default impact and print the report
	$(VENV)/bin/spinimpact solve

test: $(STAMP)  ## run the whole test suite
	$(PY) -m pytest

bench: $(STAMP)  ## print benchmark ratios (not part of the tests)
	$(PY) -m benchmarks.bench

images: $(STAMP)  ## regenerate the README's figures in docs/images
	$(VENV)/bin/spinimpact map --output docs/images/map.png --resolution 800 --dpi 80
	$(VENV)/bin/spinimpact figures --output-dir docs/images --dpi 80
	$(PY) docs/scripts/convergence.py docs/images/convergence.png
	$(PY) docs/scripts/engines.py docs/images/engines.png
	$(VENV)/bin/spinimpact planar --body rod --orientation-deg 45 --mu 0.3 --kappa 0.8 --plot docs/images/routh_planar.png --dpi 80 > /dev/null
	$(VENV)/bin/spinimpact planar --body rod --mu 0.8 --kappa 0.9 --law newton --map-plot docs/images/planar_map.png --resolution 300 --dpi 80 > /dev/null
	$(PY) docs/scripts/fit_kharaz.py docs/images/fit_kharaz.png
	$(PY) docs/scripts/flight.py docs/images

validation: $(STAMP)  ## every model against Kharaz et al. (2001); the Chung & Ooi (2011) tests
	$(PY) -m benchmarks.validation kharaz --output docs/images
	for t in 1 2 3 4 5 6; do $(PY) -m benchmarks.validation chung-ooi --test $$t || exit 1; done

lint: $(STAMP)
	$(VENV)/bin/ruff check src tests
	$(VENV)/bin/ruff format --check src tests

clean:
	rm -rf $(VENV) build dist src/*.egg-info .pytest_cache .hypothesis
