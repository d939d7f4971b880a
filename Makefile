# Rockly: `make run` starts the app, `make test` runs the whole suite.
# Both set up what is missing first (Debian packages, venv, Python deps, Blockly).

VENV      := .venv
PY        := $(VENV)/bin/python
STAMP_SYS := $(VENV)/.system-packages
STAMP_PY  := $(VENV)/.python-deps
BLOCKLY   := resources/blockly/vendor/.version
QT_ENV    := QTWEBENGINE_DISABLE_SANDBOX=1

.PHONY: setup run test bench lint clean

setup: $(STAMP_SYS) $(STAMP_PY) $(BLOCKLY)

$(STAMP_SYS): scripts/setup-system.sh
	bash scripts/setup-system.sh
	@mkdir -p $(VENV) && touch $@

$(PY): | $(STAMP_SYS)
	/usr/bin/python3 -m venv --system-site-packages $(VENV)

$(STAMP_PY): pyproject.toml setup.py | $(PY)
	$(PY) -m pip install --quiet --disable-pip-version-check -e '.[dev]'
	@touch $@

$(BLOCKLY): scripts/fetch-blockly.sh | $(STAMP_SYS)
	bash scripts/fetch-blockly.sh

run: setup
	$(QT_ENV) $(PY) -m rockly_desktop

test: setup
	$(QT_ENV) QT_QPA_PLATFORM=offscreen $(VENV)/bin/lint-imports
	$(QT_ENV) QT_QPA_PLATFORM=offscreen $(PY) -m pytest

bench: setup
	$(QT_ENV) QT_QPA_PLATFORM=offscreen $(PY) benchmarks/run_all.py

clean:
	rm -rf $(VENV) resources/blockly/vendor
