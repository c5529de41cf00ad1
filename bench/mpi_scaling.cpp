// Distributed strong scaling: one scene stepped on R MPI ranks x T OpenMP threads, with the
// step's time split into compute, communication, halo exchange, rebalancing and output gathering.
// Run once per layout and compare the wall time per step (docs/parallel.md, "Speed and scale"):
//
//   export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1   # as root only
//   OMP_NUM_THREADS=2 mpirun --oversubscribe --bind-to none -np 1
//       build/bench/ejecta_bench_mpi_scaling --scene sedov --n-side 100 --steps 5 --threads 2
//   OMP_NUM_THREADS=1 mpirun --oversubscribe --bind-to none -np 2
//       build/bench/ejecta_bench_mpi_scaling --scene sedov --n-side 100 --steps 5 --threads 1
//   and the same two with --scene impact --steps 10 (scenes/impact_3d_oblique.toml, 179,952
//   particles). Each command is one line; on 2 cores the Sedov pair takes about a minute.
//
// --bind-to none matters for the 1 x 2 layout: Open MPI binds each of up to two ranks to one core
// by default, which would put both threads of the single rank on the same core.
//
//   ejecta_bench_mpi_scaling [--scene sedov|impact] [--n-side K] [--spacing S] [--set key=value ...]
//                            [--steps 5] [--threads T] [--exact-halo]
//
// Scenes: sedov is scenes/verification/sedov_3d.toml with spacing 1/K (K^3 particles; K = 100 is
// N = 1e6); impact is scenes/impact_3d_oblique.toml at its spacing or --spacing S for its three
// bodies. The steps are timed apart from the setup (building the particles, the decomposition
// and initialise()), which is reported on its own line.
//
// The split is measured from outside the simulation, besides the two timers DistributedDomain
// keeps (DomainStats: halo exchange and rebalancing):
//   - every collective goes through a timing wrapper of the communicator, so "exchange" is the
//     time in personalised exchanges (halo build and refresh between neighbours, particle
//     migration) and
//     "collectives" the time in all-gathers and reductions (rank extents, time step, health
//     check, load balance), both including the wait for the slowest rank;
//   - "compute" is the rest of the step;
//   - after the steps, the halo build and refresh, a full rebalance, a snapshot write and a gather
//     of every particle to rank 0 (what images draw) are replayed and timed alone (these include the selection
//     and packing that the wrapper counts as compute).
// Each time is the largest over ranks (the step waits for the slowest). --exact-halo also counts,
// after the steps, how many real particles of other ranks a particle of each rank actually
// reaches, the least halo possible (it gathers every rank's positions everywhere).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <unistd.h>

#include "bench/arguments.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/parallel/communicator.hpp"
#include "sim/parallel/distributed_domain.hpp"
#include "sim/parallel/halo_exchange.hpp"
#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/sph/kernel.hpp"

using namespace ejecta;

namespace {

// The halo reach the simulation builds with: kKernelSupport x kGhostMargin of
// sim/run/simulation.cpp (its first attempt; it widens only when h grows past the margin).
constexpr double kHaloSupportFactor = kKernelSupport * 1.1;
// Particles are reordered, and ranks rebalanced, every this many steps (kSortInterval there).
constexpr int kRebalanceInterval = 16;

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Seconds and calls spent in one kind of collective.
struct CallTally {
  double seconds = 0.0;
  long calls = 0;
  double bytesSent = 0.0;
};

// Runs `call`, adding its time and the bytes it sends to `tally`.
template <typename Call>
auto timedCall(CallTally& tally, std::size_t bytes, Call&& call) {
  const auto start = Clock::now();
  auto result = call();
  tally.seconds += secondsSince(start);
  ++tally.calls;
  tally.bytesSent += static_cast<double>(bytes);
  return result;
}

// A pending exchange whose finish() is timed into `tally`.
class TimedPending final : public Communicator::PendingExchange {
 public:
  TimedPending(std::unique_ptr<Communicator::PendingExchange> inner, CallTally& tally)
      : inner_(std::move(inner)), tally_(tally) {}
  std::vector<Bytes> finish() override {
    const auto start = Clock::now();
    std::vector<Bytes> arrived = inner_->finish();
    tally_.seconds += secondsSince(start);
    return arrived;
  }
  void progress() override { inner_->progress(); }

 private:
  std::unique_ptr<Communicator::PendingExchange> inner_;
  CallTally& tally_;
};

// A communicator that forwards every collective to `inner` and tallies the time spent in it.
// The Simulation holds it as its only view of the ranks, so every message of a step is counted.
class TimedCommunicator final : public Communicator {
 public:
  explicit TimedCommunicator(std::shared_ptr<const Communicator> inner) : inner_(std::move(inner)) {}
  int rank() const override { return inner_->rank(); }
  int size() const override { return inner_->size(); }

  std::vector<Bytes> allGather(std::span<const std::byte> mine) const override {
    return timedCall(collectives_, mine.size(), [&] { return inner_->allGather(mine); });
  }
  std::vector<Bytes> exchange(const std::vector<Bytes>& toRank) const override {
    std::size_t bytes = 0;
    for (std::size_t r = 0; r < toRank.size(); ++r)
      if (static_cast<int>(r) != rank()) bytes += toRank[r].size();
    return timedCall(exchanges_, bytes, [&] { return inner_->exchange(toRank); });
  }
  std::vector<Bytes> exchangeWith(std::span<const int> to, const std::vector<Bytes>& payloads,
                                  std::span<const int> from) const override {
    std::size_t bytes = 0;
    for (const Bytes& b : payloads) bytes += b.size();
    return timedCall(exchanges_, bytes, [&] { return inner_->exchangeWith(to, payloads, from); });
  }
  // A pending exchange counts as an exchange: the time to start it and the time its finish()
  // waits (what the overlap did not hide).
  std::unique_ptr<PendingExchange> startExchangeWith(std::span<const int> to, std::vector<Bytes> payloads,
                                                     std::span<const int> from,
                                                     std::span<const std::size_t> sizes) const override {
    std::size_t bytes = 0;
    for (const Bytes& b : payloads) bytes += b.size();
    auto pending = timedCall(exchanges_, bytes, [&] {
      return inner_->startExchangeWith(to, std::move(payloads), from, sizes);
    });
    return std::make_unique<TimedPending>(std::move(pending), exchanges_);
  }
  std::vector<Bytes> gatherToRoot(std::span<const std::byte> mine) const override {
    return timedCall(collectives_, mine.size(), [&] { return inner_->gatherToRoot(mine); });
  }
  void sumInPlace(std::span<std::uint64_t> values) const override {
    timedCall(collectives_, values.size_bytes(), [&] { inner_->sumInPlace(values); return 0; });
  }
  void minInPlace(std::span<double> values) const override {
    timedCall(collectives_, values.size_bytes(), [&] { inner_->minInPlace(values); return 0; });
  }
  void maxInPlace(std::span<double> values) const override {
    timedCall(collectives_, values.size_bytes(), [&] { inner_->maxInPlace(values); return 0; });
  }
  std::shared_ptr<const Communicator> split(int color) const override {
    return std::make_shared<TimedCommunicator>(inner_->split(color));
  }

  const CallTally& exchanges() const { return exchanges_; }
  const CallTally& collectives() const { return collectives_; }
  void reset() { exchanges_ = collectives_ = CallTally{}; }

 private:
  std::shared_ptr<const Communicator> inner_;
  // The interface's collectives are const; the tallies are the wrapper's own bookkeeping.
  mutable CallTally exchanges_, collectives_;
};

struct Options {
  std::string scene = "sedov";
  int nSide = 100;                     // sedov: particles per axis
  double spacing = 0.0;                // impact: 0 keeps the scene's
  std::vector<std::string> overrides;  // --set
  int steps = 5;
  int threads = 0;
  bool exactHalo = false;  // also count the halo exact neighbour lists would need
};

Options parseOptions(int argc, char** argv) {
  Options o;
  bench::Arguments args(argc, argv);
  for (std::string arg; args.next(arg);) {
    auto next = [&args] { return args.value(); };
    if (arg == "--scene") o.scene = next();
    else if (arg == "--n-side") o.nSide = std::atoi(next());
    else if (arg == "--spacing") o.spacing = std::atof(next());
    else if (arg == "--set") o.overrides.push_back(next());
    else if (arg == "--steps") o.steps = std::atoi(next());
    else if (arg == "--threads") o.threads = std::atoi(next());
    else if (arg == "--exact-halo") o.exactHalo = true;
    else { std::fprintf(stderr, "unknown option %s\n", arg.c_str()); std::exit(2); }
  }
  if ((o.scene != "sedov" && o.scene != "impact") || o.nSide < 2 || o.steps < 1) {
    std::fprintf(stderr, "--scene sedov|impact, --n-side >= 2, --steps >= 1\n");
    std::exit(2);
  }
  return o;
}

// The scene with an end time no step reaches (steps are never cut to land on it) and no outputs.
Scene benchScene(const Options& o) {
  std::vector<std::string> overrides;
  std::string path = EJECTA_SOURCE_DIR "/scenes/";
  if (o.scene == "sedov") {
    path += "verification/sedov_3d.toml";
    overrides.push_back("bodies[0].spacing=" + std::to_string(1.0 / o.nSide));
  } else {
    path += "impact_3d_oblique.toml";
    if (o.spacing > 0.0)
      for (int b = 0; b < 3; ++b)
        overrides.push_back("bodies[" + std::to_string(b) + "].spacing=" + std::to_string(o.spacing));
  }
  overrides.insert(overrides.end(), o.overrides.begin(), o.overrides.end());
  Scene scene = loadScene(path, overrides);
  if (scene.time.dtMin <= 0.0) scene.time.dtMin = 1e-12 * scene.time.tEnd;
  scene.time.tEnd = 1e6 * scene.time.tEnd;
  scene.output.snapshots = false;
  return scene;
}

// What one rank measured, as plain doubles so that rank 0 can gather them.
struct RankReport {
  double particles = 0.0;          // of the whole run
  double setupSeconds = 0.0;       // particles, decomposition, initialise()
  double stepSeconds = 0.0;        // all timed steps
  double rebalanceStepSeconds = 0.0;  // the steps that rebalanced (step index % 16 == 0)
  double rebalanceSteps = 0.0;
  double exchangeSeconds = 0.0;    // in exchange() during the steps
  double collectiveSeconds = 0.0;  // in all-gathers and reductions during the steps
  double exchangeBytes = 0.0;      // sent to other ranks during the steps
  double exchangeCalls = 0.0;
  double collectiveCalls = 0.0;
  double haloSeconds = 0.0;        // in the halo build and refreshes during the steps (DomainStats)
  double rebalancingSeconds = 0.0; // in rebalancing during the steps (DomainStats)
  double haloBuildSeconds = 0.0;   // replayed
  double haloRefreshSeconds = 0.0; // replayed
  double rebalanceSeconds = 0.0;   // replayed: a full rebalance (new splitters, migration)
  double gatherSeconds = 0.0;      // replayed: a gather of every particle to rank 0 (images)
  double writeSeconds = 0.0;       // replayed: a snapshot written by the ranks in turn
  double owned = 0.0;
  double haloReceived = 0.0;
  double haloSent = 0.0;
  double boxHalo = 0.0;    // other ranks' real particles near this rank's one box
  double exactHalo = 0.0;  // those of them within reach of a particle of this rank
};

// This rank's particles as the step left them, without the halos (real particles and this rank's
// boundary ghosts: what the halo build starts from).
ParticleSet withoutHalos(const ParticleSet& p) {
  ParticleSet copy = p;
  const auto firstHalo = std::find(copy.ghostSource.begin(), copy.ghostSource.end(), kRemoteSource);
  const std::size_t ghosts = static_cast<std::size_t>(firstHalo - copy.ghostSource.begin());
  copy.resize(copy.numReal + ghosts);
  copy.ghostSource.resize(ghosts);
  return copy;
}

// The halo build and refresh, a full rebalance, a snapshot write and a gather to rank 0, each
// timed alone (the first three on a copy).
void replayDistributedPhases(Simulation& sim, const std::shared_ptr<const Communicator>& comm,
                             RankReport& report) {
  if (comm->size() == 1) return;  // one rank: none of these phases exists
  ParticleSet copy = withoutHalos(sim.particles());
  HaloExchange halos;
  auto start = Clock::now();
  halos.build(copy, 3, kHaloSupportFactor, *comm);
  report.haloBuildSeconds = secondsSince(start);
  start = Clock::now();
  halos.refresh(copy, *comm);
  report.haloRefreshSeconds = secondsSince(start);

  // A fresh domain has no splitters: its first rebalance lays the curve anew and migrates.
  DistributedDomain domain(comm, 3);
  const std::vector<std::uint64_t> equalCost(copy.numReal, 1);
  start = Clock::now();
  domain.rebalance(copy, equalCost);
  report.rebalanceSeconds = secondsSince(start);

  start = Clock::now();
  sim.gatheredParticles();
  report.gatherSeconds = secondsSince(start);

  // A snapshot as the run writes one, into a directory of its own that is removed after.
  const std::string dir = comm->firstMessage(
      comm->isRoot()
          ? (std::filesystem::temp_directory_path() / ("ejecta_bench_snapshot_" + std::to_string(::getpid()))).string()
          : std::string());
  if (comm->isRoot()) std::filesystem::create_directories(dir);
  comm->sum(0);  // the directory exists before any rank writes into it
  SnapshotInfo info;
  info.geometry = sim.scene().geometry;
  start = Clock::now();
  writeSnapshot(dir + "/snap_0000.h5", sim.particles(), info, *comm);
  report.writeSeconds = secondsSince(start);
  if (comm->isRoot()) std::filesystem::remove_all(dir);
}

// How many of the other ranks' real particles lie within reach of the one box around this rank's
// particles (the halo criterion of the first version, 8132fe1), and how many of them a particle
// here actually reaches (within the halo reach of max(h_i, h_j)): what a halo from exact
// neighbour lists would hold, to set beside the halo received. Every rank's positions are
// gathered everywhere, so this is a measurement only.
void countRealHalos(const ParticleSet& p, const Communicator& comm, RankReport& report) {
  struct Point {
    double x, y, z, h;
  };
  std::vector<Point> mine(p.numReal);
  for (std::size_t i = 0; i < p.numReal; ++i) mine[i] = {p.x[0][i], p.x[1][i], p.x[2][i], p.h[i]};
  Bytes bytes;
  appendBytes(bytes, mine.data(), mine.size());
  const std::vector<Bytes> all = comm.allGather(bytes);

  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  double hMine = 0.0, hAll = 0.0;
  for (const Point& q : mine) {
    lo = {std::min(lo[0], q.x), std::min(lo[1], q.y), std::min(lo[2], q.z)};
    hi = {std::max(hi[0], q.x), std::max(hi[1], q.y), std::max(hi[2], q.z)};
    hMine = std::max(hMine, q.h);
  }
  for (const Bytes& b : all)
    for (const Point& q : fromBytes<Point>(b)) hAll = std::max(hAll, q.h);
  // This rank's particles binned in cubes of the largest reach: a reaching pair is in
  // neighbouring cubes.
  const double cell = kHaloSupportFactor * hAll;
  auto cellOf = [&](double x, std::size_t a) { return static_cast<std::int64_t>(std::floor((x - lo[a]) / cell)); };
  auto cellKey = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return (static_cast<std::uint64_t>(i + (1 << 20)) << 42) | (static_cast<std::uint64_t>(j + (1 << 20)) << 21) |
           static_cast<std::uint64_t>(k + (1 << 20));
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
  for (std::size_t i = 0; i < mine.size(); ++i)
    cells[cellKey(cellOf(mine[i].x, 0), cellOf(mine[i].y, 1), cellOf(mine[i].z, 2))].push_back(i);

  for (std::size_t r = 0; r < all.size(); ++r) {
    if (static_cast<int>(r) == comm.rank()) continue;
    for (const Point& q : fromBytes<Point>(all[r])) {
      const std::array<double, 3> x{q.x, q.y, q.z};
      double d2 = 0.0;
      for (std::size_t a = 0; a < 3; ++a) {
        const double out = x[a] < lo[a] ? lo[a] - x[a] : x[a] > hi[a] ? x[a] - hi[a] : 0.0;
        d2 += out * out;
      }
      if (std::sqrt(d2) >= kHaloSupportFactor * std::max(hMine, q.h)) continue;
      ++report.boxHalo;
      const std::int64_t ci = cellOf(q.x, 0), cj = cellOf(q.y, 1), ck = cellOf(q.z, 2);
      bool reached = false;
      for (std::int64_t di = -1; di <= 1 && !reached; ++di)
        for (std::int64_t dj = -1; dj <= 1 && !reached; ++dj)
          for (std::int64_t dk = -1; dk <= 1 && !reached; ++dk) {
            const auto found = cells.find(cellKey(ci + di, cj + dj, ck + dk));
            if (found == cells.end()) continue;
            for (std::size_t i : found->second) {
              const double dx = mine[i].x - q.x, dy = mine[i].y - q.y, dz = mine[i].z - q.z;
              const double reach = kHaloSupportFactor * std::max(mine[i].h, q.h);
              if (dx * dx + dy * dy + dz * dz < reach * reach) {
                reached = true;
                break;
              }
            }
          }
      report.exactHalo += reached ? 1.0 : 0.0;
    }
  }
}

RankReport measure(const Scene& scene, int steps, int threads, bool exactHalo,
                   const std::shared_ptr<TimedCommunicator>& comm) {
  RankReport r;
  const auto setupStart = Clock::now();
  MaterialTable materials = MaterialTable::fromScene(scene);
  // As runScene builds a distributed run: each rank its slice (whole where flaws need it).
  ParticleSet particles = buildParticles(scene, materials, comm.get());
  Simulation sim(scene, std::move(particles), std::move(materials), threads, comm);
  r.particles = static_cast<double>(sim.totalParticles());
  sim.initialise();
  r.setupSeconds = secondsSince(setupStart);

  comm->reset();
  const DomainStats before = sim.domain().stats();
  for (int s = 0; s < steps; ++s) {
    const bool rebalances = sim.stepCount() % kRebalanceInterval == 0;
    const auto start = Clock::now();
    sim.step(scene.time.tEnd);
    const double seconds = secondsSince(start);
    r.stepSeconds += seconds;
    if (rebalances) {
      r.rebalanceStepSeconds += seconds;
      ++r.rebalanceSteps;
    }
  }
  r.haloSeconds = sim.domain().stats().haloSeconds - before.haloSeconds;
  r.rebalancingSeconds = sim.domain().stats().rebalanceSeconds - before.rebalanceSeconds;
  r.exchangeSeconds = comm->exchanges().seconds;
  r.exchangeBytes = comm->exchanges().bytesSent;
  r.exchangeCalls = static_cast<double>(comm->exchanges().calls);
  r.collectiveSeconds = comm->collectives().seconds;
  r.collectiveCalls = static_cast<double>(comm->collectives().calls);
  r.owned = static_cast<double>(sim.particles().numReal);
  r.haloReceived = static_cast<double>(sim.domain().halos().received());
  r.haloSent = static_cast<double>(sim.domain().halos().sent());
  replayDistributedPhases(sim, comm, r);
  if (exactHalo && comm->size() > 1) countRealHalos(sim.particles(), *comm, r);
  return r;
}

std::vector<RankReport> gatherReports(const RankReport& mine, const Communicator& comm) {
  Bytes bytes;
  appendBytes(bytes, &mine, 1);
  std::vector<RankReport> all;
  for (const Bytes& b : comm.allGather(bytes)) all.push_back(fromBytes<RankReport>(b).at(0));
  return all;
}

template <typename Member>
double largest(const std::vector<RankReport>& reports, Member member) {
  double top = 0.0;
  for (const RankReport& r : reports) top = std::max(top, r.*member);
  return top;
}

// The slowest rank's time outside the collectives.
double largestCompute(const std::vector<RankReport>& reports) {
  double top = 0.0;
  for (const RankReport& r : reports)
    top = std::max(top, r.stepSeconds - r.exchangeSeconds - r.collectiveSeconds);
  return top;
}

template <typename Member>
double total(const std::vector<RankReport>& reports, Member member) {
  double sum = 0.0;
  for (const RankReport& r : reports) sum += r.*member;
  return sum;
}

void printReport(const Scene& scene, const Options& o, int threads,
                 const std::vector<RankReport>& reports) {
  const int ranks = static_cast<int>(reports.size());
  const double steps = o.steps;
  const double particles = reports.front().particles;
  const double perStep = largest(reports, &RankReport::stepSeconds) / steps;
  const double exchange = largest(reports, &RankReport::exchangeSeconds) / steps;
  const double collectives = largest(reports, &RankReport::collectiveSeconds) / steps;
  const double compute = largestCompute(reports) / steps;
  const double cores = static_cast<double>(ranks) * threads;
  const double updatesPerCore = particles / perStep / cores;
  const double rebalanceSteps = reports.front().rebalanceSteps;
  const double ordinarySteps = steps - rebalanceSteps;
  const double ordinary =
      ordinarySteps > 0 ? (largest(reports, &RankReport::stepSeconds) -
                           largest(reports, &RankReport::rebalanceStepSeconds)) / ordinarySteps
                        : 0.0;

  std::printf("Distributed scaling: %s, %d rank(s) x %d thread(s), %.0f particles, %d steps\n",
              scene.name.c_str(), ranks, threads, particles, o.steps);
  std::printf("  setup (particles, decomposition, initialise)  %.2f s\n",
              largest(reports, &RankReport::setupSeconds));
  std::printf("  wall per step                                 %.3f s\n", perStep);
  if (rebalanceSteps > 0 && ordinarySteps > 0)
    std::printf("    steps that sort and rebalance: %.3f s, the others %.3f s\n",
                largest(reports, &RankReport::rebalanceStepSeconds) / rebalanceSteps, ordinary);
  std::printf("  particle updates per second per core          %.4g\n", updatesPerCore);
  std::printf("  split per step (slowest rank):\n");
  std::printf("    compute (outside collectives)               %.3f s (%.1f%%)\n", compute,
              100.0 * compute / perStep);
  std::printf("    personalised exchanges (halos, migration)   %.3f s (%.1f%%), %.1f calls, %.3g MB sent/rank\n",
              exchange, 100.0 * exchange / perStep,
              largest(reports, &RankReport::exchangeCalls) / steps,
              largest(reports, &RankReport::exchangeBytes) / steps / 1e6);
  std::printf("    all-gathers and reductions                  %.3f s (%.1f%%), %.1f calls\n", collectives,
              100.0 * collectives / perStep, largest(reports, &RankReport::collectiveCalls) / steps);
  if (ranks > 1) {
    const double halo = largest(reports, &RankReport::haloSeconds) / steps;
    const double rebalancing = largest(reports, &RankReport::rebalancingSeconds) / steps;
    std::printf("  the domain's own timers (DomainStats, slowest rank):\n");
    std::printf("    halo build and refreshes                    %.3f s (%.1f%%)\n", halo, 100.0 * halo / perStep);
    std::printf("    rebalancing                                 %.3f s (%.1f%%)\n", rebalancing,
                100.0 * rebalancing / perStep);
    const double build = largest(reports, &RankReport::haloBuildSeconds);
    const double refresh = largest(reports, &RankReport::haloRefreshSeconds);
    const double rebalance = largest(reports, &RankReport::rebalanceSeconds);
    std::printf("  replayed alone (slowest rank):\n");
    std::printf("    halo build (select, pack, send, unpack)     %.3f s, refresh %.3f s: %.3f s per step (%.1f%%)\n",
                build, refresh, build + refresh, 100.0 * (build + refresh) / perStep);
    std::printf("    full rebalance (new splitters, migration)   %.3f s: %.3f s per step at one per %d steps (%.1f%%)\n",
                rebalance, rebalance / kRebalanceInterval, kRebalanceInterval,
                100.0 * rebalance / kRebalanceInterval / perStep);
    std::printf("    snapshot written by the ranks in turn       %.3f s per output\n",
                largest(reports, &RankReport::writeSeconds));
    std::printf("    every particle gathered to rank 0 (images)  %.3f s per drawn output\n",
                largest(reports, &RankReport::gatherSeconds));
    std::printf("  halo particles received per rank: mean %.0f, max %.0f (%.1f%% of the owned mean %.0f)\n",
                total(reports, &RankReport::haloReceived) / ranks,
                largest(reports, &RankReport::haloReceived),
                100.0 * total(reports, &RankReport::haloReceived) / total(reports, &RankReport::owned),
                total(reports, &RankReport::owned) / ranks);
  }
  if (o.exactHalo && ranks > 1)
    std::printf("  real particles of other ranks per rank: near the one box around the rank's particles (the "
                "first version's criterion) %.0f, within reach of a particle %.0f (one box / exact %.2f)\n",
                total(reports, &RankReport::boxHalo) / ranks, total(reports, &RankReport::exactHalo) / ranks,
                total(reports, &RankReport::boxHalo) / total(reports, &RankReport::exactHalo));
  if (ranks > 1) {
    // A rank that waits long in the collectives is waiting for a slower one.
    std::printf("  per rank: owned, halo received, compute / exchanges / collectives per step [s]\n");
    for (int r = 0; r < ranks; ++r) {
      const RankReport& k = reports[static_cast<std::size_t>(r)];
      const double ex = k.exchangeSeconds / steps, co = k.collectiveSeconds / steps;
      std::printf("    rank %d: %.0f, %.0f, %.3f / %.3f / %.3f\n", r, k.owned, k.haloReceived,
                  k.stepSeconds / steps - ex - co, ex, co);
    }
  }
  std::printf("| scene | ranks x threads | N | steps | wall/step [s] | updates/s/core | compute | exchange | collectives |\n");
  std::printf("| %s | %d x %d | %.0f | %d | %.3f | %.4g | %.3f | %.3f | %.3f |\n", scene.name.c_str(), ranks,
              threads, particles, o.steps, perStep, updatesPerCore, compute, exchange, collectives);
}

}  // namespace

int main(int argc, char** argv) {
  MpiSession mpi(&argc, &argv);
  try {
    const Options o = parseOptions(argc, argv);
    const Scene scene = benchScene(o);
    const std::shared_ptr<const Communicator> world = worldCommunicator();
    const auto timed = std::make_shared<TimedCommunicator>(world);
    const int threads = resolveThreads(o.threads);
    const RankReport mine = measure(scene, o.steps, threads, o.exactHalo, timed);
    const std::vector<RankReport> reports = gatherReports(mine, *world);
    if (world->isRoot()) printReport(scene, o, threads, reports);
    return 0;
  } catch (const std::exception& e) {  // a bad scene, or a SimulationError on some rank
    std::fprintf(stderr, "ejecta_bench_mpi_scaling: %s\n", e.what());
    MpiSession::abortAll(1);
    return 1;
  }
}
