# linkrepro: `make reproduce` and `make test` each set up a fresh Debian machine first
# (gfortran and chromium from apt if missing, a .venv, the package installed into it), then run.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
SOURCES := pyproject.toml meson.build $(shell find legacy port harness package -type f -not -name '*.pyc' 2>/dev/null)

.PHONY: reproduce test packaging bench fuzz toolchains setup clean

reproduce: $(VENV)/.installed
	$(BIN)/linkrepro arithmetic --out out/arithmetic > /dev/null
	$(BIN)/linkrepro bench --repeat 3 --out out/bench > /dev/null
	$(BIN)/linkrepro reproduce --out out

# the tests, then every scene but the dynamic study (4.1-4.3 s of CPU measured 2026-11-28, Exudyn; its convergence is asserted by
# tests/ali1977/test_elastodynamics.py at coarse settings) run again and verified against reference/
test: $(VENV)/.installed
	$(BIN)/python -m pytest -q -n auto tests
	$(BIN)/linkrepro reproduce --out out/verify --without ali1977-elastodynamics > /dev/null
	$(BIN)/linkrepro verify --out out/verify

# An sdist and a wheel of what git has committed (python -m build), the wheel repaired with auditwheel
# (gfortran's runtime copied in; the tools are pyproject's `packaging` extra, installed by the test into a
# venv of its own), each installed into a fresh venv and run from outside the checkout, the wheel where
# the system's libgfortran and gfortran are hidden (one build, serially: a few minutes; CI runs it after `make test`).
packaging: $(VENV)/.installed
	LINKREPRO_CHECK_PACKAGING=1 $(BIN)/python -m pytest -q tests/harness/test_packaging.py

bench: $(VENV)/.installed
	$(BIN)/linkrepro bench --out out/bench

# the fuzz's seeds (each 20,000 calls, about two minutes on 2 cores): `make fuzz SEEDS=7` for another;
# then the property tests at ten times the examples, the register's slow checks, the numba cache race whole,
# and the tests that `make test` runs small at their whole size (LINKREPRO_FULL_TESTS=1, tests/sizes.py: the
# fuzz runner's known calls with the fuzz's own context, its slice in two workers, every docs block recomputed,
# the docs' examples and the register's checks each in a fresh interpreter)
SEEDS ?= 0 1 2
fuzz: $(VENV)/.installed
	for seed in $(SEEDS); do \
	  $(BIN)/python -m linkrepro.harness.fuzz --calls 20000 --seed $$seed --timeout 60 --out out/fuzz-$$seed.json || exit 1; \
	done
	HYPOTHESIS_PROFILE=thorough $(BIN)/python -m pytest -q -n auto tests/ali1977/test_differential.py \
	  tests/ali1977/test_cognate_geometry.py tests/ali1977/test_conditioning.py \
	  tests/rahman1996/test_differential.py tests/rahman1996/test_differential_qprog.py \
	  tests/rahman1996/test_qprog_scaling.py tests/rahman1996/test_qprog_feasibility.py \
	  tests/rahman1996/test_arguments.py
	LINKREPRO_SLOW_CHECKS=1 LINKREPRO_FULL_TESTS=1 $(BIN)/python -m pytest -q tests/harness/test_register_citations.py
	LINKREPRO_FULL_TESTS=1 $(BIN)/python -m pytest -q -n auto tests/harness/test_fuzz.py tests/harness/test_docs.py \
	  tests/test_python_c.py
	LINKREPRO_FULL_NUMBA_RACE=1 $(BIN)/python -m pytest -q tests/harness/test_numba_cache.py

# the run of record under each Fortran compiler (harness/toolchains.py: gfortran-11, gfortran-12, flang-22,
# from Debian's packages if missing): the package built by each into out/toolchains/<name>/ (its own venv),
# every scene run and verified against reference/, and the matrix of every cell written to reference/toolchains/
# (commit it). Its own target, not part of `make test` (a few minutes).
TOOLCHAINS ?= gfortran-11 gfortran-12 flang-22
toolchains: $(VENV)/.installed
	@for fc in $(TOOLCHAINS); do command -v $$fc >/dev/null 2>&1 || { \
	  echo "$$fc not found: installing it from Debian's packages"; \
	  SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	  $$SUDO apt-get update -qq && $$SUDO apt-get install -y -qq $$fc || echo "$$fc could not be installed"; }; done
	$(BIN)/python -m pip install -q "meson-python>=0.18" "meson>=1.1" ninja
	$(BIN)/python -m linkrepro.harness.toolchains --out out/toolchains --only $(TOOLCHAINS) --commit

setup: $(VENV)/.installed

$(VENV)/.installed: $(SOURCES)
	@command -v gfortran >/dev/null 2>&1 || { \
	  echo "gfortran not found: installing it from Debian's packages"; \
	  SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	  $$SUDO apt-get update -qq && $$SUDO apt-get install -y -qq gfortran; }
	@command -v chromedriver >/dev/null 2>&1 || { \
	  echo "chromium not found: installing it from Debian's packages (for the report's browser test)"; \
	  SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	  { $$SUDO apt-get update -qq && $$SUDO apt-get install -y -qq chromium chromium-driver >/dev/null; } || \
	  echo "chromium could not be installed: the browser test will be skipped"; }
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q ".[test,multibody]"
	@touch $@

clean:
	rm -rf $(VENV) build out
