# VolGrid's four entry points. Each installs missing Debian packages first (scripts/install-deps.sh).
#   make build   the CLI (build/bin/volgrid) and the plugin (build/lib/paraview-5.11/plugins/VolGrid/VolGrid.so)
#   make test    builds both flavours (ParaView plugin, VTK-only module) and runs every test
#   make demo    meshes a bundled example and checks it
#   make bench   VolGrid against TetGen, CGAL and vtkDelaunay3D, in one run
BUILD_DIR ?= build
VTK_ONLY_DIR ?= $(BUILD_DIR)/vtk-only
JOBS ?= $(shell nproc)
PARAVIEW_VTK_DIR := /usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/vtk

.PHONY: build build-vtk-only test demo bench deps clean

deps:
	@scripts/install-deps.sh test

$(BUILD_DIR)/CMakeCache.txt:
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DVOLGRID_FLAVOUR=ParaView

build: deps $(BUILD_DIR)/CMakeCache.txt
	cmake --build $(BUILD_DIR) -j $(JOBS)

$(VTK_ONLY_DIR)/CMakeCache.txt:
	cmake -S . -B $(VTK_ONLY_DIR) -DCMAKE_BUILD_TYPE=Release -DVOLGRID_FLAVOUR=VTK -DVTK_DIR=$(PARAVIEW_VTK_DIR) -DVOLGRID_CORE_TESTS=OFF

build-vtk-only: deps $(VTK_ONLY_DIR)/CMakeCache.txt
	cmake --build $(VTK_ONLY_DIR) -j $(JOBS)

# Both flavours always run (a failure in the first does not hide the second); the target fails if either did.
test: build build-vtk-only
	@status=0; \
	echo "== ParaView flavour ($(BUILD_DIR)) =="; \
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS) --timeout 900 || status=1; \
	echo "== VTK-only flavour ($(VTK_ONLY_DIR)) =="; \
	ctest --test-dir $(VTK_ONLY_DIR) --output-on-failure -j $(JOBS) --timeout 900 || status=1; \
	exit $$status

demo: build
	scripts/demo.sh $(BUILD_DIR)

bench: build
	@scripts/install-deps.sh bench
	cmake --build $(BUILD_DIR) -j $(JOBS) --target volgrid_benchmarks
	scripts/bench.sh $(BUILD_DIR)

clean:
	rm -rf $(BUILD_DIR)
