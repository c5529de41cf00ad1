// ejecta_bench_compare_snapshots A.h5 B.h5 [--tolerance T]
// Two snapshots of the same scene, particle by particle (matched by id), field by field: the
// largest difference of each over the field's largest magnitude. How a distributed run is
// checked against a one-rank run (docs/parallel.md):
//   mpirun -np 2 ejecta run SCENE --out runs/np2 && ejecta run SCENE --out runs/np1
//   ejecta_bench_compare_snapshots runs/np1/snapshots/snap_0004.h5 runs/np2/snapshots/snap_0004.h5
// Exits 1 when a field differs by more than the tolerance (default 1e-9, the distributed tests'
// bound; tests/parallel/test_mpi_runs.cpp says why), 2 on bad input.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "sim/io/particle_difference.hpp"
#include "sim/io/snapshot.hpp"

int main(int argc, char** argv) {
  std::string a, b;
  double tolerance = 1e-9;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--tolerance" && k + 1 < argc) tolerance = std::atof(argv[++k]);
    else if (a.empty()) a = arg;
    else if (b.empty()) b = arg;
    else {
      std::fprintf(stderr, "usage: %s A.h5 B.h5 [--tolerance T]\n", argv[0]);
      return 2;
    }
  }
  if (b.empty()) {
    std::fprintf(stderr, "usage: %s A.h5 B.h5 [--tolerance T]\n", argv[0]);
    return 2;
  }
  try {
    ejecta::SnapshotInfo infoA, infoB;
    const ejecta::ParticleSet pa = ejecta::readSnapshot(a, infoA);
    const ejecta::ParticleSet pb = ejecta::readSnapshot(b, infoB);
    std::printf("%zu particles at t = %.6g s (%s) and t = %.6g s (%s)\n", pa.numReal, infoA.time,
                a.c_str(), infoB.time, b.c_str());
    std::printf("%-24s %14s %14s\n", "field", "relative", "absolute");
    bool within = true;
    for (const ejecta::FieldDifference& d : ejecta::particleDifferences(pa, pb)) {
      std::printf("%-24s %14.3e %14.3e%s\n", d.field.c_str(), d.relative, d.absolute,
                  d.relative > tolerance ? "  > tolerance" : "");
      within = within && d.relative <= tolerance;
    }
    const ejecta::FieldDifference worst =
        ejecta::largestDifference(ejecta::particleDifferences(pa, pb));
    std::printf("largest: %s %.3e of its largest value (tolerance %.1e): %s\n", worst.field.c_str(),
                worst.relative, tolerance, within ? "same" : "DIFFERENT");
    return within ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ejecta_bench_compare_snapshots: %s\n", e.what());
    return 2;
  }
}
