# rotordyn: `make run` and `make test` install whatever is missing (Debian packages, a
# virtualenv, the package) and then run the main job or every test. Idempotent: each step
# leaves a stamp and is skipped while its inputs are unchanged.
SHELL := /bin/bash
.DEFAULT_GOAL := run

PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
PIP    := $(PY) -m pip --disable-pip-version-check -q
STAMPS := $(VENV)/.stamps
APT_PKGS := libeigen3-dev libsuitesparse-dev libsundials-dev liblapack-dev libblas-dev g++ make
# `make test` only: a headless browser for the HTML report's test (tests/test_report_browser.py)
APT_TEST_PKGS := chromium
PY_BUILD := scikit-build-core pybind11 cmake ninja
PY_DEPS  := numpy scipy pandas pyarrow "dask[distributed]" matplotlib threadpoolctl pytest pytest-xdist hypothesis control
# Optional (the `hinf` extra): H∞ synthesis (python-control's hinfsyn/mixsyn need slycot);
# wheels only (no Fortran build from source): a machine without a wheel still builds and
# tests, the H∞ tests skip with the reason.
PY_OPT_DEPS := "slycot>=0.6"
SOURCES := $(shell find cpp python cmake sweeps -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.py' -o -name '*.txt' -o -name '*.toml' -o -name '*.cmake' -o -name '*.pyi' -o -name 'py.typed' \) 2>/dev/null) CMakeLists.txt pyproject.toml
OUT ?= out

.PHONY: run test test-cpp test-py install sysdeps testdeps bench clean distclean sanitize fuzz

sysdeps: $(STAMPS)/sysdeps
$(STAMPS)/sysdeps:
	@mkdir -p $(STAMPS)
	@if ! dpkg -s $(APT_PKGS) >/dev/null 2>&1; then \
	  SUDO=""; if [ "$$(id -u)" -ne 0 ]; then SUDO="sudo"; fi; \
	  echo "make: installing Debian packages: $(APT_PKGS)"; \
	  $$SUDO apt-get update -qq && \
	  $$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $(APT_PKGS) >/dev/null; \
	fi
	@touch $@

$(STAMPS)/venv: pyproject.toml Makefile | $(STAMPS)/sysdeps
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	@echo "make: installing Python build tools and dependencies into $(VENV)"
	@$(PIP) install $(PY_BUILD) $(PY_DEPS)
	@$(PIP) install --only-binary=slycot $(PY_OPT_DEPS) || echo "make: optional $(PY_OPT_DEPS) not installed (no wheel): the H∞ tests will skip"
	@mkdir -p $(STAMPS) && touch $@

install: $(STAMPS)/install
$(STAMPS)/install: $(STAMPS)/venv $(SOURCES)
	@echo "make: building and installing rotordyn (incremental build in build/py)"
	@$(PIP) install --no-build-isolation --no-deps .
	@touch $@

run: $(STAMPS)/install
	@mkdir -p $(OUT)
	$(VENV)/bin/rotordyn report paper-rig --out $(OUT) --html $(OUT)/report.html

test-cpp: $(STAMPS)/install
	$(VENV)/bin/ctest --test-dir build/py --output-on-failure

testdeps: $(STAMPS)/testdeps
$(STAMPS)/testdeps: | $(STAMPS)/sysdeps
	@if ! dpkg -s $(APT_TEST_PKGS) >/dev/null 2>&1; then \
	  SUDO=""; if [ "$$(id -u)" -ne 0 ]; then SUDO="sudo"; fi; \
	  echo "make: installing Debian packages for the tests: $(APT_TEST_PKGS)"; \
	  $$SUDO apt-get update -qq && \
	  $$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $(APT_TEST_PKGS) >/dev/null; \
	fi
	@touch $@

# The suite runs in PYTEST_WORKERS processes (pytest-xdist), whole files per process
# (`--dist loadfile`: a module's fixtures are built once); PYTEST_WORKERS=0 runs it serially.
PYTEST_WORKERS ?= 2
test-py: $(STAMPS)/install $(STAMPS)/testdeps
	$(PY) -m pytest -q --durations=25 $(if $(filter 0,$(PYTEST_WORKERS)),,-n $(PYTEST_WORKERS) --dist loadfile)

test: test-cpp test-py

# Sanitizer build (ASan + UBSan + LeakSanitizer) in build/asan, untouched by the normal build:
# the C++ tests under ctest, then a Python smoke run of every C++ entry point with the
# sanitizer runtime preloaded and the sanitized _core staged in build/asan/site (PYTHONPATH).
# Leaks of the interpreter itself (not instrumented) are suppressed by .ci/lsan-python.supp;
# the Python run records 12 frames per allocation so that a suppression matches only
# allocations made by the interpreter, not rotordyn code called from it.
# Measured (issue 13, loaded 2-core machine): build 5.5-7.5 min CPU, ctest 10 s, smoke 20 s.
ASAN_DIR   := build/asan
ASAN_FLAGS := -O1 -g1
ASAN_ENV   := ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_init_order=1:detect_stack_use_after_return=0 \
              UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
              LSAN_OPTIONS=suppressions=$(CURDIR)/.ci/lsan-python.supp:print_suppressions=0
sanitize: $(STAMPS)/venv
	$(VENV)/bin/cmake -S . -B $(ASAN_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(ASAN_FLAGS)" -DROTORDYN_SANITIZE=address,undefined \
	  -DROTORDYN_BUILD_PYTHON=ON -DPython_EXECUTABLE=$(CURDIR)/$(PY) \
	  -Dpybind11_DIR=$$($(PY) -m pybind11 --cmakedir) >/dev/null
	$(VENV)/bin/cmake --build $(ASAN_DIR)
	$(ASAN_ENV) $(VENV)/bin/ctest --test-dir $(ASAN_DIR) --output-on-failure
	rm -rf $(ASAN_DIR)/site && mkdir -p $(ASAN_DIR)/site
	cp -r python/rotordyn $(ASAN_DIR)/site/ && cp $(ASAN_DIR)/cpp/_core*.so $(ASAN_DIR)/site/rotordyn/
	$(ASAN_ENV) ASAN_OPTIONS=detect_leaks=1:strict_init_order=1:malloc_context_size=12 \
	  PYTHONMALLOC=malloc \
	  PYTHONPATH=$(CURDIR)/$(ASAN_DIR)/site \
	  LD_PRELOAD="$$(g++ -print-file-name=libasan.so) $$(g++ -print-file-name=libubsan.so)" \
	  $(PY) .ci/sanitize_smoke.py

# Longer fuzzing than `make test`'s fixed budget: FUZZ_SCALE times the examples, a random
# seed (a failure prints the @reproduce_failure blob to paste into the test).
FUZZ_SCALE ?= 20
fuzz: $(STAMPS)/install
	ROTORDYN_FUZZ_SCALE=$(FUZZ_SCALE) ROTORDYN_FUZZ_EXPLORE=1 \
	  $(PY) -m pytest -q tests/test_fuzz.py tests/test_fuzz_more.py --hypothesis-show-statistics

bench: $(STAMPS)/install
	for b in benchmarks/bench_*.py; do $(PY) $$b || exit 1; done

clean:
	rm -rf build $(OUT)

distclean: clean
	rm -rf $(VENV)
