#pragma once
// Individual time steps: every particle advances on its own time bin (GADGET-2, Springel 2005,
// MNRAS 364 1105; SWIFT, Schaller et al. 2024, MNRAS 530 2378), so the few particles that need a
// short step (a deposit's hot core, a shock front, a cracking solid) no longer set the step of
// all the others (docs/time_steps.md).
//
// Time runs in blocks that end at the run's synchronisation points (outputs, t_end, delayed
// deposits), where every particle is at the same time. A block of length T holds 2^kDeepest
// ticks; a particle on bin b steps T / 2^b, and may start a step only on a tick that is a
// multiple of its step, so bins nest and each sub-step ends where the shortest steps in progress
// end. Each particle's step [t0, t1] is kick-drift-kick as the global leapfrog's
// (sim/run/leapfrog.hpp), with the rates at its own t0 and t1:
//   y_half = y(t0) + (t1 - t0)/2 y'(t0),   x += (t - t_prev) v_half at every sub-step,
//   y(t1)  = y_half + (t1 - t0)/2 y'(t1).
// Between t0 and t1 its other fields are predicted to the sub-step's time, y(t0) + (t - t0)
// y'(t0), so the particles that are evaluated see their neighbours where they are; a density
// set by summation (and h tied to it) is predicted by the continuity rate,
// rho(t) = rho(t0) exp(-div v (t - t0)), h = h(t0) exp(div v (t - t0) / d).
//
// The limiter (Saitoh & Makino 2009, ApJ 697 L99; Durier & Dalla Vecchia 2012, MNRAS 419 465):
// a particle starting a step takes no bin more than log2(factor) coarser than any neighbour's,
// and a neighbour already on a longer step is woken: its step is cut to end at the next tick of
// the bin it may have, and its first half kick shortened to match (y_half as if the step had been
// the shorter one from t0).
//
// The state of each particle lives in fields declared on the particles (so it is reordered with
// them and travels with them): its bin, the ticks its step begins and ends at, its own step
// limit at its last evaluation (stored in snapshots: a restart at a synchronisation point chooses
// the same bins), and the value at its step's start of each field the leapfrog advances.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "sim/run/leapfrog.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

class TimeBins {
 public:
  using Tick = std::int64_t;
  static constexpr int kDeepest = 50;  // a block's finest step is 2^-50 of it
  static constexpr Tick kBlockTicks = Tick{1} << kDeepest;

  // `limiterFactor`: a power of two >= 2, or 0 for no limiter. `dtMax`: the longest step [s]
  // (0: none).
  TimeBins(int limiterFactor, double dtMax);

  // Declares the per-particle state and a start value for every field `leapfrog` advances (and
  // those it holds that are predicted: a summation density, h tied to it). Idempotent; call once
  // every package has declared its fields.
  void registerFields(ParticleSet& p, const Leapfrog& leapfrog, bool summationDensity,
                      bool tiedSmoothingLength);

  // Whether every particle is at the end of the block (or no block has begun).
  bool synchronised() const { return now_ == kBlockTicks; }
  // Starts a block [start, start + length] with every particle at its start.
  void beginBlock(double start, double length);
  double blockStart() const { return start_; }
  double blockLength() const { return length_; }
  Tick now() const { return now_; }
  double timeAt(Tick t) const {
    if (t >= kBlockTicks) return end_;  // the block ends exactly where the run asked
    // t / 2^kDeepest: a power-of-two scaling, exact (as ldexp, which costs a call per particle).
    constexpr double kTickScale = 1.0 / static_cast<double>(kBlockTicks);
    return start_ + length_ * (static_cast<double>(t) * kTickScale);
  }

  // Starts a step at the present tick for each particle of `which`: its bin is the coarsest
  // whose step is within its own limit (`dtOwn`), no coarser than `floorBin` (the limiter; may
  // be empty), and aligned with the present tick. Stores the start values (and the caps of
  // Cap-limited fields, from `leapfrog`). Returns false if a particle's limit needs a bin finer
  // than kDeepest (the caller stops the run).
  bool beginSteps(ParticleSet& p, const Leapfrog& leapfrog, std::span<const std::size_t> which,
                  std::span<const int> floorBin);

  // The earliest end of a step in progress: the next sub-step's tick.
  Tick nextEnd(const ParticleSet& p) const;
  // Drifts every particle to tick `next` and predicts its fields there; the particles whose step
  // ends at `next` (returned, ascending) get their first half kick, as the leapfrog's predict.
  std::vector<std::size_t> advanceTo(ParticleSet& p, const Leapfrog& leapfrog, Tick next,
                                     int dimension);
  // The second half kick of the particles whose step ended (with their new rates).
  void finishSteps(ParticleSet& p, const Leapfrog& leapfrog, std::span<const std::size_t> which,
                   int dimension);

  // The limiter's bin floor for a particle with neighbours on bins `neighbourBins`.
  int floorFrom(int neighbourBin) const { return limiterLevels_ < 0 ? 0 : neighbourBin - limiterLevels_; }
  bool limiting() const { return limiterLevels_ >= 0; }
  // Wakes particle i (inactive) so that its step ends no later than the next tick of `bin`.
  // Returns true when its step was shortened.
  bool wake(ParticleSet& p, std::size_t i, int bin) const;

  // The results of the density pass that a particle keeps while others are evaluated (its
  // omega, div v, |curl v| and, with reconstruction, velocity gradient `gradient`, 9 per
  // particle): kept in stored fields at a synchronisation point, so a restart there resumes
  // with the values the uninterrupted run has (they are not otherwise in a snapshot).
  void keepEvaluation(ParticleSet& p, const std::vector<double>& gradient) const;
  void restoreEvaluation(ParticleSet& p, std::vector<double>& gradient) const;

  // The per-particle state's fields.
  static constexpr const char* kBinField = "time_bin";
  static constexpr const char* kOwnStepField = "dt_own";
  std::vector<double>& bins(ParticleSet& p) const { return p.column(*p.field(kBinField), 0); }
  const std::vector<double>& bins(const ParticleSet& p) const { return p.column(*p.field(kBinField), 0); }
  std::vector<double>& ownSteps(ParticleSet& p) const { return p.column(*p.field(kOwnStepField), 0); }

  // Particle-steps completed so far (the cost counter of docs/time_steps.md).
  std::uint64_t updates() const { return updates_; }

 private:
  struct Advanced {
    std::string name;        // the field
    std::string start;       // its start-value field
    std::string cap;         // Cap-limited: its caps field, else empty
    bool held = false;       // held by the leapfrog: predicted from the continuity rate
  };
  Tick ticksOf(int bin) const { return Tick{1} << (kDeepest - bin); }

  int limiterLevels_ = 2;  // log2 of the limiter factor, -1: no limiter
  double dtMax_ = 0.0;
  double start_ = 0.0, length_ = 0.0, end_ = 0.0;
  Tick now_ = kBlockTicks;
  std::vector<Advanced> advanced_;
  bool summation_ = false, tiedH_ = false;
  std::uint64_t updates_ = 0;
  std::vector<double> elapsed_, half_;  // advanceTo's scratch
  std::vector<unsigned char> ends_;
};

}  // namespace ejecta
