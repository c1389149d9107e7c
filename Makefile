# Geomatics Toolbox — every set-up step is here, so a fresh Debian 12 machine needs only
#   make demo    (runs the main job through qgis_process on generated demo data → out/)
#   make test    (all three test tiers)
# Both install the Debian packages (QGIS 3.22, GDAL, SciPy, Qt tools) and the venv if missing.

SHELL := /bin/bash
PLUGIN := geomatics_toolbox
SYSPY := /usr/bin/python3
VENV := .venv
PY := $(VENV)/bin/python
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
DEB_PACKAGES := qgis python3-qgis qgis-providers python3-gdal gdal-bin python3-scipy \
	python3-venv python3-pip qttools5-dev-tools pyqt5-dev-tools chromium xvfb xauth
PYTEST_ARGS ?=
QGIS_PROFILE ?= $(HOME)/.local/share/QGIS/QGIS3/profiles/default

export QT_QPA_PLATFORM := offscreen
export PROJ_DATA := /usr/share/proj
export PYTHONDONTWRITEBYTECODE := 1

PY_SOURCES = $(shell git ls-files '*.py' 2>/dev/null | grep -vE '^(tests|benchmarks|scripts)/')
TS_FILES := i18n/$(PLUGIN)_ar.ts i18n/$(PLUGIN)_fa.ts
QM_FILES := $(TS_FILES:.ts=.qm)

.PHONY: help system-deps venv demo test test-core test-qgis test-cli test-340 root-340 bench \
	lint ts qm package deploy clean model help-pages screenshots

help:
	@echo "make demo | test | test-340 | bench | lint | ts | qm | model | help-pages | screenshots | package | deploy | clean"

# --------------------------------------------------------------------------- set-up
system-deps:
	@if ! command -v qgis_process.bin >/dev/null 2>&1 || ! command -v lrelease >/dev/null 2>&1 \
	   || ! command -v pylupdate5 >/dev/null 2>&1 || ! command -v gdal_grid >/dev/null 2>&1 \
	   || ! command -v chromium >/dev/null 2>&1 || ! command -v xvfb-run >/dev/null 2>&1 \
	   || ! $(SYSPY) -c 'import qgis.core, osgeo.gdal, scipy, venv, pip' >/dev/null 2>&1; then \
	  echo "Installing Debian packages: $(DEB_PACKAGES)"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends \
	    $(DEB_PACKAGES) >/dev/null; \
	fi

$(VENV)/.stamp: requirements.txt requirements-dev.txt | system-deps
	$(SYSPY) -m venv --system-site-packages $(VENV)
	$(SYSPY) -c 'import numpy; print("numpy==" + numpy.__version__)' > $(VENV)/constraints.txt
	$(PY) -m pip install -q --disable-pip-version-check -c $(VENV)/constraints.txt \
		-r requirements-dev.txt
	touch $@

# `import geomatics_toolbox` from the venv (scripts, benchmarks): a link under the
# installed name and a .pth file pointing at it.
$(VENV)/.plugin-link: $(VENV)/.stamp
	mkdir -p $(VENV)/plugin-path
	ln -sfn "$(CURDIR)" $(VENV)/plugin-path/$(PLUGIN)
	echo "$(abspath $(VENV))/plugin-path" > \
		"$$($(PY) -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')/$(PLUGIN).pth"
	touch $@

venv: $(VENV)/.stamp $(VENV)/.plugin-link

# --------------------------------------------------------------------------- i18n
# Translations live in i18n/strings/*.json; the .ts files are generated from them.
ts: venv
	$(PY) scripts/i18n_sync.py

i18n/%.qm: i18n/%.ts
	lrelease -silent $< -qm $@

qm: system-deps $(QM_FILES)

# --------------------------------------------------------------------------- run
demo: venv qm
	bash scripts/demo.sh out

test: venv qm
	$(PY) -m pytest $(PYTEST_ARGS)

test-core: venv
	$(PY) -m pytest tests/core $(PYTEST_ARGS)

test-qgis: venv qm
	$(PY) -m pytest tests/qgis $(PYTEST_ARGS)

test-cli: venv qm
	$(PY) -m pytest tests/cli $(PYTEST_ARGS)

# The same `make test` on QGIS 3.40 LTR (Python 3.13, numpy 2.2, GDAL 3.10) in a Debian 13
# root made with debootstrap (scripts/qgis340_root.sh: ~7 min the first time, then reused;
# its own venv; this checkout and ../shared mounted inside). .ci/run runs it after `make test`.
test-340:
	bash scripts/qgis340_root.sh test $(PYTEST_ARGS)

root-340:
	bash scripts/qgis340_root.sh build

$(VENV)/.bench-stamp: requirements-bench.txt $(VENV)/.stamp
	$(PY) -m pip install -q --disable-pip-version-check -c $(VENV)/constraints.txt \
		-r requirements-bench.txt
	touch $@

bench: venv $(VENV)/.bench-stamp
	$(PY) benchmarks/run_all.py $(BENCH_ARGS)

lint: venv
	$(VENV)/bin/ruff check .
	$(PY) scripts/i18n_sync.py --check

# The shipped model is generated (every child parameter set): rerun after changing a child.
model: venv
	QT_HASH_SEED=0 $(PY) scripts/build_model.py   # stable XML attribute order

# Help pages shipped with the plugin (helpUrl), generated from the help strings.
help-pages: venv qm
	$(PY) scripts/build_help.py

# Every dialog and report in en/ar/fa as PNGs for review (Xvfb + QGIS, headless Chromium);
# SCREENSHOTS_ARGS="--only idwdtm,lsqgroundfilter --langs ar,fa" limits the run.
screenshots: venv qm
	xvfb-run -a -s "-screen 0 1280x1024x24" env QT_QPA_PLATFORM=xcb \
		$(PY) scripts/screenshots.py --out out/screenshots $(SCREENSHOTS_ARGS)

# --------------------------------------------------------------------------- ship
package: venv qm
	$(PY) scripts/package.py --out dist

deploy: qm
	mkdir -p "$(QGIS_PROFILE)/python/plugins"
	ln -sfn "$(CURDIR)" "$(QGIS_PROFILE)/python/plugins/$(PLUGIN)"
	@echo "Linked $(CURDIR) as $(QGIS_PROFILE)/python/plugins/$(PLUGIN);"
	@echo "enable 'Geomatics Toolbox' in Plugins > Manage and Install Plugins."

clean:
	rm -rf out dist build .pytest_cache $(QM_FILES)
