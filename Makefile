# ejecta: the two commands of the README quick start, and a few conveniences.
#   make demo   install missing packages, build (Release), run the default scene
#   make test   install missing packages, build (Release), run the test suite
BUILD ?= build
JOBS  ?= $(shell nproc)
CTEST_ARGS ?= -LE slow

.PHONY: all deps configure build demo test verification bench sanitize fuzz fuzz-ci fuzz-build paraview-deps clean

all: build

deps:
	@bash cmake/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > $(BUILD).configure.log 2>&1 || (cat $(BUILD).configure.log; exit 1)

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/apps/ejecta run --overwrite --out runs/demo

# The suite, then the readers under AddressSanitizer + UndefinedBehaviorSanitizer: a clang build
# of the libraries they are part of, those libraries' unit tests and the readers' fuzzers
# (~8 minutes on 2 cores from a clean folder; docs/robustness.md).
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)
	@$(MAKE) --no-print-directory fuzz-ci

# ParaView (pvbatch, its Python modules) and a virtual X server: with them installed, the next
# configure registers the test that opens a run's series in ParaView itself (label paraview),
# and `make test` runs it. Large (~440 MB), so not part of `deps`.
paraview-deps:
	@bash cmake/install-deps.sh paraview
	@cmake -S . -B $(BUILD) > $(BUILD).configure.log 2>&1 || (cat $(BUILD).configure.log; exit 1)

verification: build
	cd $(BUILD) && ctest --output-on-failure -L verification

# Each under a minute on 2 cores: SPH hydro (3D Sedov; 2D Sedov with global against individual
# time steps), particles to grids and VDB files (3D and
# RZ revolved), the impact scene's solid-mechanics overhead, ray-cast view factors, the thermal
# chain with and without the asteroid as occluder, the wall solvers, and off-screen rendering;
# throughput per core at 1 and 2 threads where it scales; what the snapshots' checksums cost;
# the memory a run takes per particle (against the memory check's constant); what the exact
# reference solutions cost.
bench: build
	$(BUILD)/bench/ejecta_bench_sedov --n 40
	$(BUILD)/bench/ejecta_bench_time_steps --problem sedov_2d --set "bodies[0].spacing=0.01" --set "energy_deposits[0].width=0.02"
	$(BUILD)/bench/ejecta_bench_fields --threads-sweep
	$(BUILD)/bench/ejecta_bench_fields --geometry rz --threads-sweep
	$(BUILD)/bench/ejecta_bench_impact --threads-sweep
	$(BUILD)/bench/ejecta_bench_viewfactor --max-build 100000
	$(BUILD)/bench/ejecta_bench_thermal
	$(BUILD)/bench/ejecta_bench_wall_heat --threads-sweep
	$(BUILD)/bench/ejecta_bench_render --threads-sweep
	$(BUILD)/bench/ejecta_bench_snapshot_io --particles 1000000 --repeats 3
	$(BUILD)/bench/ejecta_bench_memory
	$(BUILD)/bench/ejecta_bench_exact_solutions

# Checked builds (docs/robustness.md), each in a folder of its own:
#   make sanitize  the unit tests built with AddressSanitizer + UndefinedBehaviorSanitizer (gcc);
#                  any report fails its test. MPI tests are left out (Open MPI's own allocations
#                  are reported as leaks), as are the hostile corpus' process-spawning cases.
#   make fuzz      the scene and snapshot readers' libFuzzer targets (clang, with the same
#                  sanitizers), FUZZ_SECONDS each from the committed corpus; new inputs go to a
#                  scratch folder, failures to $(FUZZ_BUILD)/findings/ (cmake/run-fuzzers.sh).
SANITIZE_BUILD ?= build-sanitize
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
SANITIZE_ENV = ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=0 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/fuzz/lsan.supp

sanitize: deps
	@cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Release -DEJECTA_SANITIZE=ON \
	  > $(SANITIZE_BUILD).configure.log 2>&1 || (cat $(SANITIZE_BUILD).configure.log; exit 1)
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	cd $(SANITIZE_BUILD) && $(SANITIZE_ENV) ctest --output-on-failure -j $(JOBS) -L unit -LE "mpi|hostile"

fuzz: fuzz-build
	@bash cmake/run-fuzzers.sh $(FUZZ_BUILD) $(FUZZ_SECONDS)

# What `make test` runs after the suite: the unit tests of core/ and sim/ under the sanitizers
# (clang; tests/fuzz/CMakeLists.txt says which), then the fuzzers with a fixed seed and input count.
fuzz-ci: fuzz-build
	cd $(FUZZ_BUILD) && $(SANITIZE_ENV) ctest --output-on-failure -j $(JOBS) -L unit
	@bash cmake/run-fuzzers.sh $(FUZZ_BUILD) ci

fuzz-build:
	@bash cmake/install-deps.sh fuzz
	@CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=Release -DEJECTA_FUZZ=ON \
	  > $(FUZZ_BUILD).configure.log 2>&1 || (cat $(FUZZ_BUILD).configure.log; exit 1)
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_scene_reader fuzz_snapshot_reader \
	  sanitized_unit_tests

clean:
	rm -rf $(BUILD) $(BUILD).configure.log $(SANITIZE_BUILD) $(SANITIZE_BUILD).configure.log \
	  $(FUZZ_BUILD) $(FUZZ_BUILD).configure.log
