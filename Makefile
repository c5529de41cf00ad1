# ejecta: the two commands of the README quick start, and a few conveniences.
#   make demo   install missing packages, build (Release), run the default scene
#   make test   install missing packages, build (Release), run the test suite
BUILD ?= build
JOBS  ?= $(shell nproc)
CTEST_ARGS ?= -LE slow

.PHONY: all deps configure build demo test verification bench sanitize fuzz clean

all: build

deps:
	@bash cmake/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > $(BUILD).configure.log 2>&1 || (cat $(BUILD).configure.log; exit 1)

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/apps/ejecta run --overwrite --out runs/demo

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

verification: build
	cd $(BUILD) && ctest --output-on-failure -L verification

# Each under a minute on 2 cores: SPH hydro (3D Sedov; 2D Sedov with global against individual
# time steps), particles to grids and VDB files (3D and
# RZ revolved), the impact scene's solid-mechanics overhead, ray-cast view factors, the thermal
# chain with and without the asteroid as occluder, the wall solvers, and off-screen rendering;
# throughput per core at 1 and 2 threads where it scales.
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

# Checked builds (docs/robustness.md), each in a folder of its own:
#   make sanitize  the unit tests built with AddressSanitizer + UndefinedBehaviorSanitizer (gcc);
#                  any report fails its test. MPI tests are left out (Open MPI's own allocations
#                  are reported as leaks), as are the hostile corpus' process-spawning cases.
#   make fuzz      the scene and snapshot readers' libFuzzer targets (clang, with the same
#                  sanitizers), FUZZ_SECONDS each from the committed corpus; new inputs go to a
#                  scratch folder, failures to $(FUZZ_BUILD)/findings/.
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

fuzz:
	@bash cmake/install-deps.sh fuzz
	@CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=Release -DEJECTA_FUZZ=ON \
	  > $(FUZZ_BUILD).configure.log 2>&1 || (cat $(FUZZ_BUILD).configure.log; exit 1)
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_scene_reader fuzz_snapshot_reader
	@for reader in scene_reader snapshot_reader; do \
	  mkdir -p $(FUZZ_BUILD)/scratch/$$reader $(FUZZ_BUILD)/findings && \
	  echo "fuzzing the $$reader for $(FUZZ_SECONDS) s" && \
	  $(SANITIZE_ENV) $(FUZZ_BUILD)/tests/fuzz/fuzz_$$reader -max_total_time=$(FUZZ_SECONDS) \
	    -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 -print_final_stats=1 \
	    -artifact_prefix=$(FUZZ_BUILD)/findings/$$reader- \
	    $(FUZZ_BUILD)/scratch/$$reader tests/fuzz/corpus/$$reader || exit 1; \
	done

clean:
	rm -rf $(BUILD) $(BUILD).configure.log $(SANITIZE_BUILD) $(SANITIZE_BUILD).configure.log \
	  $(FUZZ_BUILD) $(FUZZ_BUILD).configure.log
