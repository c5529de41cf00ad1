# Third-party packages, all from Debian 12 (see cmake/install-deps.sh and docs/dependencies.md).
# Each library target links only what it uses; this file just finds them.
# TBB before OpenVDB: OpenVDB's own FindTBB.cmake defines only TBB::tbb, and TBB's config
# fails later if that one wins (docs/dependencies.md).
find_package(TBB 2021 CONFIG REQUIRED)
list(APPEND CMAKE_MODULE_PATH /usr/lib/x86_64-linux-gnu/cmake/OpenVDB)
find_package(OpenVDB 10 REQUIRED)
find_package(OpenMP REQUIRED)
find_package(embree 3 CONFIG REQUIRED)          # target: embree (radiation/ ray casting)
find_package(Eigen3 3.4 CONFIG REQUIRED)        # Eigen3::Eigen (radiation/ implicit wall solver)
find_package(PkgConfig REQUIRED)
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)  # PkgConfig::OSMESA (render/, GL included)
find_package(PNG REQUIRED)                      # PNG::PNG (render/)
# Text in images (render/outline_font.cpp): FreeType and DejaVu Sans, both in Debian
# (libfreetype-dev, fonts-dejavu-core); without them images use the built-in bitmap font.
find_package(Freetype QUIET)
find_file(EJECTA_FONT_FILE DejaVuSans.ttf PATHS /usr/share/fonts/truetype/dejavu NO_DEFAULT_PATH)
find_package(HDF5 REQUIRED COMPONENTS C)
find_package(tomlplusplus 3 CONFIG REQUIRED)
find_package(CLI11 2 CONFIG REQUIRED)
find_package(GTest REQUIRED)
find_package(benchmark CONFIG QUIET)
find_package(nlohmann_json 3 CONFIG REQUIRED)
# Distributed runs (sim/parallel/): Open MPI from Debian (libopenmpi-dev). A build without MPI
# runs one rank; EJECTA_MPI=OFF forces that even where MPI is installed.
option(EJECTA_MPI "Build distributed runs on MPI when MPI is found" ON)
set(EJECTA_HAVE_MPI OFF)
if(EJECTA_MPI)
  find_package(MPI COMPONENTS CXX)
  if(MPI_CXX_FOUND)
    set(EJECTA_HAVE_MPI ON)
    find_program(EJECTA_MPIEXEC NAMES mpirun mpiexec HINTS ${MPIEXEC_EXECUTABLE})
  endif()
endif()
message(STATUS "ejecta: distributed runs on MPI: ${EJECTA_HAVE_MPI}")
