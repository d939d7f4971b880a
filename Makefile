# Rockly: `make run` starts the app, `make test` runs the whole suite.
# Both set up what is missing first (Debian packages, venv, Python deps, Blockly);
# `make test` also makes .venv-ros2 (ROS 2 from pinned wheels, `make ros2`).

VENV      := .venv
PY        := $(VENV)/bin/python
STAMP_SYS := $(VENV)/.system-packages
STAMP_PY  := $(VENV)/.python-deps
STAMP_ROS2 := .venv-ros2/.requirements
BLOCKLY   := resources/blockly/vendor/.version
# Tests and benchmarks run as root in CI, where Chromium's sandbox cannot start
# (the app itself turns the sandbox off only when it runs as root).
TEST_ENV  := QTWEBENGINE_DISABLE_SANDBOX=1 QT_QPA_PLATFORM=offscreen
# `make test` runs the suite shuffled, in the order of this seed (pytest-randomly prints it in the header):
# the same order for the same commit, so CI gives the same answer twice; `make test TEST_SEED=N` repeats
# another run's order. Moved only after a whole run with the new seed was green (docs/decisions/038).
TEST_SEED ?= 2911

.PHONY: setup ros2 run test test-shuffled bench clean runtime

setup: $(STAMP_SYS) $(STAMP_PY) $(BLOCKLY)

$(STAMP_SYS): scripts/setup-system.sh
	bash scripts/setup-system.sh
	@mkdir -p $(VENV) && touch $@

$(PY): | $(STAMP_SYS)
	/usr/bin/python3 -m venv --system-site-packages $(VENV)

$(STAMP_PY): pyproject.toml setup.py | $(PY) $(BLOCKLY)
	$(PY) -m pip install --quiet --disable-pip-version-check -e '.[dev]'
	@touch $@

$(BLOCKLY): scripts/fetch-blockly.sh | $(STAMP_SYS)
	bash scripts/fetch-blockly.sh

# ROS 2 lives in its own venv and process (Debian's ROS 1 owns the same module names).
ros2: $(STAMP_ROS2)

$(STAMP_ROS2): requirements-ros2.txt scripts/setup-ros2.sh | $(STAMP_SYS)
	bash scripts/setup-ros2.sh

# The runtime alone (no Qt; runtime/README.md), as a wheel to copy to a robot: dist/rockly_runtime-*.whl
runtime: $(STAMP_PY)
	$(PY) -m pip wheel --quiet --no-deps --no-build-isolation ./runtime -w dist

run: setup
	$(PY) -m rockly_desktop

test: setup ros2
	$(VENV)/bin/ruff check .
	$(TEST_ENV) $(VENV)/bin/lint-imports
	$(TEST_ENV) $(PY) -m pytest -p randomly --randomly-seed=$(TEST_SEED)

# A new order each time (its seed printed in the header): what the pinned seed does not show.
test-shuffled: setup ros2
	$(TEST_ENV) $(PY) -m pytest -p randomly

# Byte-compiled first, as an installed Rockly is (the bare-Blockly baseline's PySide6 is too).
bench: setup ros2
	$(PY) -m compileall -q rockly_desktop profiles
	$(TEST_ENV) $(PY) benchmarks/run_all.py

clean:
	rm -rf $(VENV) .venv-ros2 resources/blockly/vendor
