// ejecta_bench_snapshot_io [--particles N] [--repeats R] [--dir DIR] [--json]
// What the checksums of snapshots cost (docs/robustness.md, issue 24):
// 1. the Fletcher-32 filter alone: the same 20 double arrays of N rows written and read in the
//    snapshot's chunking (~1 MiB chunks), with and without the filter, through HDF5 directly;
// 2. a whole snapshot: writeSnapshot and readSnapshot (Fletcher-32, chunk-index and value
//    checks) of N particles, per particle.
// Files go to DIR (default /tmp), usually the page cache: I/O at memory speed is where the
// checksum's share of the time is largest, so the ratio printed is an upper bound for disks.
// Each time is the median of R repeats.
#include <hdf5.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "bench/arguments.hpp"
#include "sim/io/snapshot.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

constexpr int kArrays = 20;  // about the number of double arrays a hydro snapshot stores

// Writes kArrays datasets of n doubles in ~1 MiB chunks, with or without Fletcher-32.
void writeArrays(const std::string& path, const std::vector<double>& values, bool fletcher) {
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  const hsize_t n = values.size();
  const hsize_t chunk = std::min<hsize_t>(n, (hsize_t{1} << 20) / sizeof(double));
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(dcpl, 1, &chunk);
  if (fletcher) H5Pset_fletcher32(dcpl);
  for (int k = 0; k < kArrays; ++k) {
    const std::string name = std::string("a").append(std::to_string(k));
    const hid_t d = H5Dcreate2(file, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(d);
  }
  H5Pclose(dcpl);
  H5Sclose(space);
  H5Fclose(file);
}

void readArrays(const std::string& path, std::vector<double>& values) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  for (int k = 0; k < kArrays; ++k) {
    const std::string name = std::string("a").append(std::to_string(k));
    const hid_t d = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(d);
  }
  H5Fclose(file);
}

// A valid particle set: positions in a unit cube, positive mass, density and h.
ejecta::ParticleSet particles(std::size_t n) {
  ejecta::ParticleSet p;
  p.resize(n);
  p.numReal = n;
  std::mt19937_64 random(24);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) p.x[d][i] = unit(random);
    p.v[0][i] = unit(random);
    p.mass[i] = 1e-3 * (1.0 + unit(random));
    p.rho[i] = 2700.0 * (1.0 + 0.1 * unit(random));
    p.u[i] = 1e5 * unit(random);
    p.h[i] = 0.02;
    p.id[i] = static_cast<std::int64_t>(i);
  }
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t n = 1000000;
  int repeats = 5;
  std::string dir = "/tmp";
  bool json = false;
  ejecta::bench::Arguments args(argc, argv);
  for (std::string option; args.next(option);) {
    if (option == "--particles") n = std::strtoull(args.value(), nullptr, 10);
    else if (option == "--repeats") repeats = std::atoi(args.value());
    else if (option == "--dir") dir = args.value();
    else if (option == "--json") json = true;
    else {
      std::fprintf(stderr, "usage: %s [--particles N] [--repeats R] [--dir DIR] [--json]\n", argv[0]);
      return 2;
    }
  }
  if (n == 0 || repeats < 1) {
    std::fprintf(stderr, "--particles and --repeats must be positive\n");
    return 2;
  }
  const std::string arrays = dir + "/ejecta_bench_arrays.h5";
  const std::string snapshot = dir + "/ejecta_bench_snapshot.h5";

  std::vector<double> values(n), back(n);
  for (std::size_t i = 0; i < n; ++i) values[i] = 1.0 + 1e-7 * static_cast<double>(i);
  std::vector<double> writePlain, writeSum, readPlain, readSum;
  for (int r = 0; r < repeats; ++r) {
    for (const bool fletcher : {false, true}) {
      auto t0 = Clock::now();
      writeArrays(arrays, values, fletcher);
      auto t1 = Clock::now();
      readArrays(arrays, back);
      auto t2 = Clock::now();
      (fletcher ? writeSum : writePlain).push_back(seconds(t0, t1));
      (fletcher ? readSum : readPlain).push_back(seconds(t1, t2));
    }
  }
  const ejecta::ParticleSet p = particles(n);
  ejecta::SnapshotInfo info;
  info.scene = "bench";
  std::vector<double> snapWrite, snapRead;
  for (int r = 0; r < repeats; ++r) {
    auto t0 = Clock::now();
    ejecta::writeSnapshot(snapshot, p, info);
    auto t1 = Clock::now();
    ejecta::SnapshotInfo read;
    const ejecta::ParticleSet q = ejecta::readSnapshot(snapshot, read);
    auto t2 = Clock::now();
    if (q.numReal != n) return 1;
    snapWrite.push_back(seconds(t0, t1));
    snapRead.push_back(seconds(t1, t2));
  }
  const double megabytes = kArrays * n * sizeof(double) / 1e6;
  const double wp = median(writePlain), ws = median(writeSum), rp = median(readPlain), rs = median(readSum);
  const double sw = median(snapWrite), sr = median(snapRead);
  const double fileMB = std::filesystem::file_size(snapshot) / 1e6;
  std::filesystem::remove(arrays);
  std::filesystem::remove(snapshot);
  if (json) {
    std::printf("{\"particles\": %zu, \"arrays_mb\": %.1f, \"write_plain_s\": %.4g, \"write_fletcher_s\": %.4g, "
                "\"read_plain_s\": %.4g, \"read_fletcher_s\": %.4g, \"snapshot_mb\": %.1f, "
                "\"snapshot_write_s\": %.4g, \"snapshot_read_s\": %.4g}\n",
                n, megabytes, wp, ws, rp, rs, fileMB, sw, sr);
    return 0;
  }
  std::printf("Fletcher-32 alone: %d arrays of %zu doubles (%.0f MB), median of %d, in %s\n", kArrays, n,
              megabytes, repeats, dir.c_str());
  std::printf("  write: %.0f MB/s plain, %.0f MB/s with the checksum: x%.2f the time\n", megabytes / wp,
              megabytes / ws, ws / wp);
  std::printf("  read:  %.0f MB/s plain, %.0f MB/s verifying:         x%.2f the time\n", megabytes / rp,
              megabytes / rs, rs / rp);
  std::printf("Whole snapshot of %zu particles (%.0f MB): write %.0f ns/particle, read with every check "
              "%.0f ns/particle\n",
              n, fileMB, 1e9 * sw / n, 1e9 * sr / n);
  return 0;
}
