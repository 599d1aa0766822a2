# pathlab — `make` builds ./pathlab, `make run` renders the Cornell box, `make test` runs every test.
# `make test SAN=1` builds and tests with AddressSanitizer and UndefinedBehaviorSanitizer.
CC ?= cc
WARN = -std=c99 -Wall -Wextra -pedantic
DEFS = -D_POSIX_C_SOURCE=200809L
ifeq ($(SAN),1)
  BUILD = build-san
  OPT = -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
  PROG = $(BUILD)/pathlab
else
  BUILD = build
  OPT = -O3 -march=native -g
  PROG = pathlab
endif
CFLAGS = $(WARN) $(DEFS) $(OPT)
LDLIBS = -lm -lpthread

SRC = $(wildcard src/*.c)
OBJ = $(SRC:src/%.c=$(BUILD)/%.o)
LIB_OBJ = $(filter-out $(BUILD)/main.o,$(OBJ))
TEST_SRC = $(wildcard tests/test_*.c)
TEST_BIN = $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)

all: $(PROG)

$(PROG): $(OBJ)
	$(CC) $(CFLAGS) -o $@ $(OBJ) $(LDLIBS)

$(BUILD)/%.o: src/%.c $(wildcard src/*.h) | $(BUILD)
	$(CC) $(CFLAGS) -c -o $@ $<

$(BUILD)/tests/%: tests/%.c $(LIB_OBJ) tests/check.h | $(BUILD)
	$(CC) $(CFLAGS) -Isrc -o $@ $< $(LIB_OBJ) $(LDLIBS)

$(BUILD):
	mkdir -p $(BUILD)/tests

run: $(PROG)
	./$(PROG) render scenes/cornell.obj --spp 64 -o cornell.ppm
	@echo "The Cornell box is in cornell.ppm (open it with any image viewer)."

# Tools the tests use but pathlab never links: OpenImageIO's idiff.
test-deps:
	@command -v idiff >/dev/null 2>&1 || { echo "installing openimageio-tools (idiff) for the tests"; \
	  SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq openimageio-tools >/dev/null; }

TOOLS = $(BUILD)/tests/zcheck $(BUILD)/tests/pfmtool $(BUILD)/bench-plot

test: $(PROG) $(TEST_BIN) $(TOOLS) test-deps
	BUILD=$(BUILD) PATHLAB=./$(PROG) PATHLAB_FAST=$(SAN) tests/run.sh

# The numerical stress suite (tests/stress/run.sh): scaled and moved scenes, slivers, z-fighting,
# sharp lobes, tiny and grazing lights, rays along edges, acne; about 2 minutes on 2 cores.
stress: $(PROG) $(TOOLS)
	BUILD=$(BUILD) PATHLAB=./$(PROG) tests/stress/run.sh

# Reference images and their manifest (slow; the result is committed).
refs: $(PROG)
	ref/make_refs.sh

# The benchmarks (about 7.5 minutes on 2 cores; see docs/performance.md): ray speed against Embree 3 on
# the Stanford meshes (needs ../shared and Debian's libembree-dev), the time to reach the same L1
# error per --direct mode (bench/direct_modes.sh), and RMSE against render time for every estimator
# on every scene (bench/sweep.sh: bench/results.csv, docs/bench.svg).
BENCH_MESHES ?= ../shared/data/meshes/bunny.obj ../shared/data/meshes/dragon.obj
bench: $(PROG) $(BUILD)/tests/pfmtool $(BUILD)/bench-plot
	@for m in $(BENCH_MESHES); do for t in 1 2; do \
	  echo "== $$m, $$t thread(s)"; ../shared/tools/embree-rays/compare.sh $$m $$t 3; done; done
	BUILD=$(BUILD) PATHLAB=./$(PROG) bench/direct_modes.sh
	BUILD=$(BUILD) PATHLAB=./$(PROG) bench/sweep.sh

# The benchmark's error, slopes, ranking and SVG (bench/plot.c), linked like the tests.
$(BUILD)/bench-plot: bench/plot.c $(LIB_OBJ) | $(BUILD)
	$(CC) $(CFLAGS) -Isrc -o $@ bench/plot.c $(LIB_OBJ) $(LDLIBS)

# Mutation testing (tests/mutants/run.sh): classic bugs put into a copy of src/, each must make
# one fast test fail; about 2 minutes on 2 cores.
mutants:
	tests/mutants/run.sh

clean:
	rm -rf build build-san pathlab

.PHONY: all run test test-deps stress refs bench clean mutants
