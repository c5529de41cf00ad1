#pragma once
// summary.json: a small machine-readable record of how a run went (for scripts, CI and the
// verification studies). Layout in docs/output_format.md.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace ejecta {

// A value in RunSummary::extras. Note that a string literal selects std::string (C++20 rules).
using SummaryValue = std::variant<bool, std::int64_t, double, std::string>;

struct RunSummary {
  std::string scene;
  std::size_t particles = 0;
  long steps = 0;
  double tEnd = 0.0;         // simulation time reached [s]
  double wallSeconds = 0.0;  // wall-clock time of the time loop, the snapshots and the in-situ
                             // outputs at each snapshot; over every invocation of a restarted run [s]
  double totalWallSeconds = 0.0;  // this invocation, from the command's start (scene, particles)
                                  // to summary.json, the end hooks (crater, charts) included [s]
  int threads = 0;           // OpenMP threads used (per rank)
  int ranks = 1;             // MPI ranks (written only for a distributed run)

  struct Energy {
    double initial = 0.0;         // [J]
    double final = 0.0;           // [J]
    double relativeError = 0.0;   // |final - initial| / |initial| (caller's definition)
  } energy;

  struct Momentum {
    std::array<double, 3> initial{};  // [kg m/s]
    std::array<double, 3> final{};
  } momentum;

  // Interrupted: stopped by SIGINT/SIGTERM after a step, its state in a last snapshot (resume
  // with `ejecta run --restart`).
  enum class Status { Completed, Failed, Interrupted };
  Status status = Status::Completed;  // written as "completed" / "failed" / "interrupted"
  std::string message;                // why it failed, or any remark

  // Free-form additions, written in order under "extras" (a later duplicate key wins).
  std::vector<std::pair<std::string, SummaryValue>> extras;

  // The extras read back as summary.json holds them (a later duplicate wins). The typed readers
  // throw std::out_of_range naming the key when it is missing or holds another type, so a
  // mistyped key fails loudly instead of reading as 0.
  bool has(const std::string& key) const;
  double number(const std::string& key) const;
  std::int64_t integer(const std::string& key) const;
  bool flag(const std::string& key) const;
  const std::string& text(const std::string& key) const;
};

// Writes `summary` as pretty-printed JSON to `path`, atomically. Non-finite numbers (e.g. a
// relative error with zero initial energy) are written as null. Throws std::runtime_error
// naming the file on failure.
void writeSummaryJson(const std::string& path, const RunSummary& summary);

}  // namespace ejecta
