# ellvor — build, test, run, benchmark. See README.md.
#   make run       install missing Debian packages, build, check the bundled example (300
#                  ellipses, 30 nested) and build its Delaunay graph (build/example-graph.json, .svg)
#   make test      install missing packages, build and run the whole test suite
#   make sanitize  the test suite built with AddressSanitizer + UndefinedBehaviorSanitizer
#   make bench     build and run the benchmark programs under experiments/
#   make fuzz      the libFuzzer targets under fuzz/ (clang, ASan + UBSan), FUZZ_SECONDS each;
#                  findings in build-fuzz/findings/ (fails on new ones; old ones listed apart)
#   make python    the Python module in-tree: build/python/ellvor (PYTHONPATH=build/python)

BUILD    ?= build
CXX      ?= g++
OPT      ?= -O2 -g
SANITIZE ?=
CXXFLAGS := -std=c++17 $(OPT) $(SANITIZE) -fPIC -Wall -Wextra -Wno-unused-parameter -I. -I/usr/include/eigen3 -MMD -MP
LDLIBS   := -lflint-arb -lflint -lmpfr -lgmp
JOBS     ?= 2
# Debian's interpreter: a python3 earlier on PATH (pyenv) may not see Debian's numpy and pytest.
PYTHON   ?= /usr/bin/python3
# PYTHON_TESTS=no leaves the Python suite out of `make test` (`make sanitize` does).
PYTHON_TESTS ?= yes

LIB_SRC   := $(wildcard util/*.cpp decision/*.cpp sites/*.cpp exact/*.cpp subdivision/*.cpp circles/*.cpp predicates/*.cpp traits/*.cpp graph/*.cpp cells/*.cpp output/*.cpp)
CLI_SRC   := $(wildcard cli/*.cpp)
TEST_SRC  := $(wildcard tests/*.cpp tests/*/*.cpp)
BENCH_SRC := $(wildcard experiments/*.cpp)
FUZZ_SRC  := $(wildcard fuzz/*.cpp)
PY_SRC    := $(wildcard python/src/*.cpp)

LIB_OBJ   := $(LIB_SRC:%.cpp=$(BUILD)/obj/%.o)
CLI_OBJ   := $(CLI_SRC:%.cpp=$(BUILD)/obj/%.o)
TEST_OBJ  := $(TEST_SRC:%.cpp=$(BUILD)/obj/%.o)
LIBRARY   := $(BUILD)/libellvor.a
ELLVOR    := $(BUILD)/ellvor
TESTS     := $(BUILD)/ellvor_tests
BENCHES   := $(BENCH_SRC:experiments/%.cpp=$(BUILD)/experiments/%)
FUZZERS   := $(FUZZ_SRC:fuzz/%.cpp=$(BUILD)/%)
PY_OBJ    := $(PY_SRC:%.cpp=$(BUILD)/obj/%.o)
# PY_EXT and PY_INCLUDES come from the Python that `deps` installs, and make
# reads them when it parses this file (a target's name must be known then, so
# the suffix cannot wait for a recipe). On a bare machine the first make parses
# before the install and gets nothing (PY_EXT falls back to .so). So they are
# right only in a make started after the install: every target that needs them
# depends on $(DEPS_STAMP), then runs a sub-make, which parses again, with
# goals that name no parse-time value (python-module, never $(PY_MODULE)).
# scripts/bare-machine-check.sh checks this on a fresh Debian 12.
PY_EXT    := $(or $(shell $(PYTHON) -c "import sysconfig; print(sysconfig.get_config_var('EXT_SUFFIX'))" 2>/dev/null),.so)
PY_INCLUDES := $(shell $(PYTHON) -c "import sysconfig; print('-I' + sysconfig.get_paths()['include'])" 2>/dev/null)
PY_MODULE := $(BUILD)/python/ellvor/_ellvor$(PY_EXT)
# The package: the pure-Python half copied next to the extension module.
PY_FILES  := $(patsubst python/%,$(BUILD)/python/%,$(wildcard python/ellvor/*.py))
DEPS_STAMP := $(BUILD)/.deps-installed

.PHONY: all deps run test sanitize bench fuzz fuzzers python python-module clean
.DEFAULT_GOAL := all

all: $(ELLVOR) $(TESTS)

# Installs the Debian 12 packages ellvor needs (only the missing ones).
deps: $(DEPS_STAMP)
$(DEPS_STAMP): scripts/install-deps.sh
	@bash scripts/install-deps.sh
	@mkdir -p $(BUILD) && touch $@

$(BUILD)/obj/%.o: %.cpp | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -c $< -o $@

# The objects that compute under the upward rounding mode (util/upward_interval.hpp,
# which requires ELLVOR_ROUNDING_MATH): -frounding-math keeps the compiler from folding
# -((-x) - y) into x + y or constants in round-to-nearest, -ffp-contract=off from fusing a
# product and a sum (one rounding less; only with FMA, e.g. -march=native). Only these
# objects: the flags are measured in experiments/results/ellipse_speed.md.
ROUNDING_MATH     := -frounding-math -ffp-contract=off -DELLVOR_ROUNDING_MATH
ROUNDING_MATH_OBJ := $(BUILD)/obj/subdivision/voronoi_circle_in_doubles.o $(BUILD)/obj/cells/normal_ray_in_doubles.o \
                     $(BUILD)/obj/subdivision/voronoi_circle_by_bounding_disks.o \
                     $(BUILD)/obj/tests/util/test_upward_interval.o $(BUILD)/obj/tests/util/test_upward_ball.o
$(ROUNDING_MATH_OBJ): CXXFLAGS += $(ROUNDING_MATH)

# The test and CLI objects need the path of the ellvor binary of this build.
$(TEST_OBJ): CXXFLAGS += -DELLVOR_BINARY='"$(abspath $(ELLVOR))"' -DELLVOR_SOURCE_DIR='"$(abspath .)"'

$(LIBRARY): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@ && ar rcs $@ $^

$(ELLVOR): $(CLI_OBJ) $(LIBRARY)
	$(CXX) $(CXXFLAGS) $^ -o $@ $(LDLIBS)

$(TESTS): $(TEST_OBJ) $(LIBRARY)
	$(CXX) $(CXXFLAGS) $^ -o $@ $(LDLIBS)

# The extension module: pybind11 (header-only) over the library. Every
# object is compiled with -fPIC, so the library links into it as it is.
$(PY_OBJ): CXXFLAGS += -fvisibility=hidden $(PY_INCLUDES)

$(PY_MODULE): $(PY_OBJ) $(LIBRARY)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -shared $^ -o $@ $(LDLIBS)

$(BUILD)/python/ellvor/%.py: python/ellvor/%.py
	@mkdir -p $(dir $@)
	cp $< $@

# Internal: a sub-make's goal (see PY_EXT); `make python` is the command.
python-module: $(PY_MODULE) $(PY_FILES)

python: $(DEPS_STAMP)
	@$(MAKE) --no-print-directory -j$(JOBS) python-module

$(BUILD)/experiments/%: experiments/%.cpp $(LIBRARY)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -DNDEBUG -frounding-math $< $(LIBRARY) -o $@ $(LDLIBS)

# A libFuzzer target: the library built with -fsanitize=fuzzer-no-link (see
# fuzz), linked with libFuzzer's main.
$(FUZZERS): $(BUILD)/%: $(BUILD)/obj/fuzz/%.o $(LIBRARY)
	$(CXX) $(CXXFLAGS) -fsanitize=fuzzer $^ -o $@ $(LDLIBS)

fuzzers: $(FUZZERS)

run: $(DEPS_STAMP)
	@$(MAKE) --no-print-directory -j$(JOBS) $(ELLVOR)
	$(ELLVOR) check data/example-300.ell --describe
	$(ELLVOR) build data/example-300.ell --validate --stats --json $(BUILD)/example-graph.json --svg $(BUILD)/example-graph.svg
	@echo "Delaunay graph written to $(BUILD)/example-graph.json, drawing to $(BUILD)/example-graph.svg"

# The Catch2 suite, then the Python suite (tests/python, against the CLI of
# this build); one closing line "N passed, M failed" for both.
test: $(DEPS_STAMP)
ifeq ($(PYTHON_TESTS),no)
	@$(MAKE) --no-print-directory -j$(JOBS) $(ELLVOR) $(TESTS)
	@bash tests/run_suite.sh $(TESTS)
else
	@$(MAKE) --no-print-directory -j$(JOBS) $(ELLVOR) $(TESTS) python-module
	@PYTHON=$(PYTHON) PYTHONPATH=$(abspath $(BUILD)/python) ELLVOR_BINARY=$(abspath $(ELLVOR)) \
	    bash tests/run_suite.sh $(TESTS) --pytest tests/python
endif

# shift-base is left out: CGAL's MP_Float (used by the tests that compare with
# CGAL) left-shifts negative numbers, which C++20 defines and every compiler
# does as expected; all other undefined behaviour aborts the run.
sanitize: $(DEPS_STAMP)
	@$(MAKE) --no-print-directory BUILD=build-sanitize OPT="-O1 -g" PYTHON_TESTS=no \
	    SANITIZE="-fsanitize=address,undefined -fno-sanitize=shift-base -fno-sanitize-recover=undefined -fno-omit-frame-pointer" test

bench: $(DEPS_STAMP)
	@$(MAKE) --no-print-directory -j$(JOBS) $(BENCHES) $(ELLVOR) python-module
	@for b in $(BENCHES); do echo "== $$b"; $$b || exit 1; done
	@echo "== experiments/python_build.py"
	@PYTHONPATH=$(BUILD)/python ELLVOR_BINARY=$(abspath $(ELLVOR)) $(PYTHON) experiments/python_build.py --count 3000 --reps 3
	@echo "== experiments/cells_vs_sampling.py"
	@PYTHONPATH=$(BUILD)/python ELLVOR_BINARY=$(abspath $(ELLVOR)) $(PYTHON) experiments/cells_vs_sampling.py

# libFuzzer needs clang; its packages are installed here only, so that `make
# test` and CI never depend on clang. The build gets its own directory.
FUZZ_BUILD    := build-fuzz
FUZZ_SECONDS  ?= 60
FUZZ_PACKAGES := clang-14 libclang-rt-14-dev llvm-14
FUZZ_STAMP    := $(FUZZ_BUILD)/.fuzz-deps-installed

$(FUZZ_STAMP): scripts/install-deps.sh
	@bash scripts/install-deps.sh $(FUZZ_PACKAGES)
	@mkdir -p $(FUZZ_BUILD) && touch $@

fuzz: $(FUZZ_STAMP)
	@$(MAKE) --no-print-directory -j$(JOBS) BUILD=$(FUZZ_BUILD) CXX=clang++-14 OPT="-O1 -g" \
	    SANITIZE="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined \
	        -fno-omit-frame-pointer" fuzzers
	@FUZZ_SECONDS=$(FUZZ_SECONDS) bash scripts/run-fuzz.sh $(FUZZ_BUILD)

clean:
	rm -rf build build-sanitize build-fuzz

-include $(LIB_OBJ:.o=.d) $(CLI_OBJ:.o=.d) $(TEST_OBJ:.o=.d) $(PY_OBJ:.o=.d) $(BENCHES:=.d) $(FUZZ_SRC:%.cpp=$(BUILD)/obj/%.d)
