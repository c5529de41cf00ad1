# ejecta: the two commands of the README quick start, and a few conveniences.
#   make demo   install missing packages, build (Release), run the default scene
#   make test   install missing packages, build (Release), run the test suite
BUILD ?= build
JOBS  ?= $(shell nproc)
CTEST_ARGS ?= -LE slow

.PHONY: all deps configure build demo test verification bench clean

all: build

deps:
	@bash cmake/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > $(BUILD).configure.log 2>&1 || (cat $(BUILD).configure.log; exit 1)

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/apps/ejecta run --out runs/demo

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

clean:
	rm -rf $(BUILD) $(BUILD).configure.log
