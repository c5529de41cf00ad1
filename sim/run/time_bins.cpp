#include "sim/run/time_bins.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sim/parallel/thread_team.hpp"
#include "sim/solid/fracture.hpp"

namespace ejecta {

namespace {

constexpr const char* kBeginField = "step_begin";
constexpr const char* kEndField = "step_end";
constexpr const char* kGradientField = "last:velocity_gradient";

FieldSpec stateField(std::string name, std::string units, std::string description,
                     FieldOutput output, int components = 1) {
  FieldSpec f = scalarField(std::move(name), std::move(units), std::move(description), output);
  f.required = false;  // a run with global steps writes none of them
  f.components = components;
  return f;
}

int evolvedComponents(const Field& f, int dimension) {
  return f.spec.spatial ? std::min(dimension, f.spec.components) : f.spec.components;
}

// One bounded half kick, as the leapfrog's (sim/run/leapfrog.hpp).
double limitedKick(const Field& f, double y, double rate, double dt, double cap) {
  switch (f.spec.limit) {
    case KickLimit::None: return y + dt * rate;
    case KickLimit::Clamp: return std::clamp(y + dt * rate, f.spec.lo, f.spec.hi);
    case KickLimit::Cap: return advanceCrack(y, rate, dt, cap);
  }
  return y + dt * rate;
}

// The largest change of ln rho that a prediction applies: beyond it the particle's step was far
// too long for its compression, which the limiter or the next evaluation corrects.
constexpr double kMaxLogPrediction = 1.0;

}  // namespace

TimeBins::TimeBins(int limiterFactor, double dtMax) : dtMax_(dtMax) {
  if (limiterFactor == 0) {
    limiterLevels_ = -1;
  } else {
    if (limiterFactor < 2 || (limiterFactor & (limiterFactor - 1)) != 0)
      throw std::invalid_argument("time-step limiter factor must be a power of two >= 2, or 0");
    limiterLevels_ = std::countr_zero(static_cast<unsigned>(limiterFactor));
  }
}

void TimeBins::registerFields(ParticleSet& p, const Leapfrog& leapfrog, bool summationDensity,
                              bool tiedSmoothingLength) {
  summation_ = summationDensity;
  tiedH_ = tiedSmoothingLength;
  if (!p.field(kBinField)) {
    FieldSpec bin = stateField(kBinField, "1",
                               "individual time steps: the bin of the step in progress (its "
                               "length is the block's / 2^bin)",
                               FieldOutput::Particles);
    bin.halo = true;  // the limiter reads the neighbours' bins, images included
    p.declare(bin);
  }
  if (!p.field(kOwnStepField))
    p.declare(stateField(kOwnStepField, "s",
                         "individual time steps: the particle's own step limit at its last "
                         "evaluation",
                         FieldOutput::Restart));
  if (!p.field(kBeginField))
    p.declare(stateField(kBeginField, "1", "tick its step began at", FieldOutput::None));
  if (!p.field(kEndField))
    p.declare(stateField(kEndField, "1", "tick its step ends at", FieldOutput::None));
  for (const char* name : {"omega", "divv", "curlv"})
    if (!p.field(std::string("last:") + name))
      p.declare(stateField(std::string("last:") + name, p.field(name)->spec.units,
                           "its value at the particle's last evaluation", FieldOutput::Restart));
  if (!p.field(kGradientField))
    p.declare(stateField(kGradientField, "1/s",
                         "its velocity gradient at the particle's last evaluation (viscosity "
                         "reconstruction)",
                         FieldOutput::Restart, 9));
  advanced_.clear();
  // Copy the declarations first: declaring adds fields (and may move the registry).
  const std::vector<Field> fields = p.fields();
  for (const Field& f : fields) {
    if (f.spec.evolution != Evolution::Kicked) continue;
    Advanced a;
    a.name = f.spec.name;
    a.held = leapfrog.holds(f.spec.name);
    if (a.held && !((f.spec.name == "density" && summation_) ||
                    (f.spec.name == "smoothing_length" && tiedH_)))
      continue;  // held and not predicted (h from the density in continuity runs, constant h)
    a.start = f.spec.name + ":start";
    if (!p.field(a.start))
      p.declare(stateField(a.start, f.spec.units, "its value at the start of the particle's step",
                           FieldOutput::None, f.spec.components));
    if (!a.held && f.spec.limit == KickLimit::Cap) {
      a.cap = f.spec.name + ":cap";
      if (!p.field(a.cap))
        p.declare(stateField(a.cap, "1", "its kick's cap through the particle's step",
                             FieldOutput::None));
    }
    advanced_.push_back(std::move(a));
  }
}

void TimeBins::beginBlock(double start, double length) {
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::logic_error("a block of individual time steps needs a positive length");
  start_ = start;
  length_ = length;
  end_ = start + length;
  now_ = 0;
}

bool TimeBins::beginSteps(ParticleSet& p, const Leapfrog& leapfrog,
                          std::span<const std::size_t> which, std::span<const int> floorBin) {
  if (which.empty()) return true;
  std::vector<double>& bin = bins(p);
  const std::vector<double>& own = p.column(*p.field(kOwnStepField), 0);
  std::vector<double>& begin = p.column(*p.field(kBeginField), 0);
  std::vector<double>& end = p.column(*p.field(kEndField), 0);
  bool ok = true;
#pragma omp parallel for schedule(static) reduction(&& : ok) if (which.size() >= kThreadTeamFrom)
  for (std::size_t k = 0; k < which.size(); ++k) {
    const std::size_t i = which[k];
    double dt = own[i];
    if (dtMax_ > 0.0) dt = std::min(dt, dtMax_);
    int b = 0;
    while (b < kDeepest && std::ldexp(length_, -b) > dt) ++b;
    if (!(std::ldexp(length_, -b) <= dt)) ok = false;  // finer than the finest bin (or NaN)
    if (!floorBin.empty()) b = std::max(b, std::min(floorBin[k], kDeepest));
    while (now_ % ticksOf(b) != 0) ++b;  // a step starts on a multiple of its length
    bin[i] = b;
    begin[i] = static_cast<double>(now_);
    end[i] = static_cast<double>(now_ + ticksOf(b));
  }
  for (const Advanced& a : advanced_) {
    const Field& f = *p.field(a.name);
    const Field& s = *p.field(a.start);
    for (int c = 0; c < f.spec.components; ++c) {
      const std::vector<double>& y = p.column(f, c);
      std::vector<double>& y0 = p.column(s, c);
      for (std::size_t i : which) y0[i] = y[i];
    }
    if (a.cap.empty()) continue;
    const Leapfrog::CapSource* source = leapfrog.caps(a.name);
    if (!source) throw std::logic_error("field '" + a.name + "' is Cap-limited but has no cap source");
    const std::vector<double> caps = (*source)(p);
    std::vector<double>& stored = p.column(*p.field(a.cap), 0);
    for (std::size_t i : which) stored[i] = caps[i];
  }
  return ok;
}

TimeBins::Tick TimeBins::nextEnd(const ParticleSet& p) const {
  const std::vector<double>& end = p.column(*p.field(kEndField), 0);
  double next = static_cast<double>(kBlockTicks);
  for (std::size_t i = 0; i < p.numReal; ++i) next = std::min(next, end[i]);
  return static_cast<Tick>(next);
}

std::vector<std::size_t> TimeBins::advanceTo(ParticleSet& p, const Leapfrog& leapfrog, Tick next,
                                             int dimension) {
  (void)leapfrog;
  const std::size_t n = p.numReal;
  const std::vector<double>& begin = p.column(*p.field(kBeginField), 0);
  const std::vector<double>& end = p.column(*p.field(kEndField), 0);
  const double tNow = timeAt(now_), tNext = timeAt(next);
  const double delta = tNext - tNow;
  // Per particle: time since its step began, half its step, whether its step ends now (scratch
  // kept between sub-steps: every entry is written below).
  std::vector<double>& elapsed = elapsed_;
  std::vector<double>& half = half_;
  std::vector<unsigned char>& ends = ends_;
  elapsed.resize(n);
  half.resize(n);
  ends.resize(n);
  // Every column this sub-step moves, looked up before the loops (a lookup compares names).
  struct Column {
    const Field* field;
    double* y;
    double* y0;  // finishing particles: becomes y_half
    const double* rate;
    const double* caps;  // Cap-limited fields: each particle's cap, else nullptr
    double heldSign;     // held fields: -1 (density) or 1/D (h); 0 for the others
    double* x;           // the velocity's columns: the positions they drift
    const double* a0;
  };
  std::vector<Column> columns;
  const Field* velocity = p.field("velocity");
  for (const Advanced& a : advanced_) {
    const Field& f = *p.field(a.name);
    const Field& s = *p.field(a.start);
    if (a.held) {
      columns.push_back({&f, p.column(f, 0).data(), p.column(s, 0).data(), nullptr, nullptr,
                         a.name == "density" ? -1.0 : 1.0 / dimension, nullptr, nullptr});
      continue;
    }
    const Field& rate = *p.field(f.spec.rate);
    const double* caps = a.cap.empty() ? nullptr : p.column(*p.field(a.cap), 0).data();
    for (int c = 0; c < evolvedComponents(f, dimension); ++c) {
      const bool drifts = &f == velocity;
      columns.push_back({&f, p.column(f, c).data(), p.column(s, c).data(), p.column(rate, c).data(), caps,
                         0.0, drifts ? p.x[static_cast<std::size_t>(c)].data() : nullptr,
                         drifts ? p.a[static_cast<std::size_t>(c)].data() : nullptr});
    }
  }
  std::vector<std::size_t> finishing;
  finishing.reserve(n);  // filled inside the team, where an allocation's failure could not be thrown
  const double* divv = p.divv.data();
  // One thread team for the whole prediction (a team per column cost more than the loops on a
  // blast's sub-steps). Each phase's loops write disjoint columns, so they run without waiting
  // for each other; the phases wait once.
#pragma omp parallel if (n >= kThreadTeamFrom)
  {
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double t0 = timeAt(static_cast<Tick>(begin[i]));
      elapsed[i] = tNext - t0;
      half[i] = 0.5 * (timeAt(static_cast<Tick>(end[i])) - t0);
      ends[i] = static_cast<Tick>(end[i]) == next;
    }
#pragma omp single
    for (std::size_t i = 0; i < n; ++i)
      if (ends[i]) finishing.push_back(i);
    // Every particle predicted to the sub-step's time, one loop per kind of limit so the plain
    // ones vectorise (this runs for every particle at every sub-step).
    for (const Column& col : columns) {
      double* y = col.y;
      const double* y0 = col.y0;
      const double* r = col.rate;
      if (col.heldSign != 0.0) {
        // rho(t0) exp(-div v dt), h(t0) exp(div v dt / d): the continuity rate's prediction.
        const double sign = col.heldSign;
#pragma omp for schedule(static) nowait
        for (std::size_t i = 0; i < n; ++i)
          y[i] = y0[i] * std::exp(std::clamp(sign * divv[i] * elapsed[i], -kMaxLogPrediction,
                                             kMaxLogPrediction));
        continue;
      }
      switch (col.field->spec.limit) {
        case KickLimit::None:
#pragma omp for schedule(static) nowait
          for (std::size_t i = 0; i < n; ++i) y[i] = y0[i] + elapsed[i] * r[i];
          break;
        case KickLimit::Clamp: {
          const double lo = col.field->spec.lo, hi = col.field->spec.hi;
#pragma omp for schedule(static) nowait
          for (std::size_t i = 0; i < n; ++i) y[i] = std::clamp(y0[i] + elapsed[i] * r[i], lo, hi);
          break;
        }
        case KickLimit::Cap: {
          const double* caps = col.caps;
#pragma omp for schedule(static) nowait
          for (std::size_t i = 0; i < n; ++i) y[i] = advanceCrack(y0[i], r[i], elapsed[i], caps ? caps[i] : 1.0);
          break;
        }
      }
    }
#pragma omp barrier
    // The particles whose step ends here take the first half kick instead, and the second from
    // it (at a block's end every particle finishes, so these are shared too).
    for (const Column& col : columns) {
      if (col.heldSign != 0.0) continue;
#pragma omp for schedule(static) nowait
      for (std::size_t k = 0; k < finishing.size(); ++k) {
        const std::size_t i = finishing[k];
        const double cap = col.caps ? col.caps[i] : 1.0;
        const double yHalf = limitedKick(*col.field, col.y0[i], col.rate[i], half[i], cap);
        col.y0[i] = yHalf;
        col.y[i] = limitedKick(*col.field, yHalf, col.rate[i], half[i], cap);
      }
    }
#pragma omp barrier
    // Positions drift by the half-step velocity of each particle's own step.
    for (const Column& col : columns) {
      if (!col.x) continue;
      double* x = col.x;
      const double* v0 = col.y0;
      const double* a0 = col.a0;
#pragma omp for schedule(static) nowait
      for (std::size_t i = 0; i < n; ++i) x[i] += delta * (ends[i] ? v0[i] : v0[i] + half[i] * a0[i]);
    }
  }
  if (!velocity || !p.field("velocity:start"))
    throw std::logic_error("individual time steps need the velocity among the advanced fields");
  now_ = next;
  return finishing;
}

void TimeBins::finishSteps(ParticleSet& p, const Leapfrog& leapfrog,
                           std::span<const std::size_t> which, int dimension) {
  const std::vector<double>& begin = p.column(*p.field(kBeginField), 0);
  const std::vector<double>& end = p.column(*p.field(kEndField), 0);
  std::vector<double> half(which.size());
  for (std::size_t k = 0; k < which.size(); ++k)
    half[k] = 0.5 * (timeAt(static_cast<Tick>(end[which[k]])) - timeAt(static_cast<Tick>(begin[which[k]])));
  // Field by field: a cap comes from the state at the step's end, including the fields kicked
  // before it. The components of a field share one thread team when enough particles finish.
  const std::size_t count = which.size();
  for (const Advanced& a : advanced_) {
    if (a.held) continue;
    const Field& f = *p.field(a.name);
    const Field& s = *p.field(a.start);
    const Field& rate = *p.field(f.spec.rate);
    std::vector<double> caps;
    if (!a.cap.empty()) caps = (*leapfrog.caps(a.name))(p);  // runs its own parallel loop
    const double* cap = caps.empty() ? nullptr : caps.data();
    // The columns looked up outside the team (a lookup may throw, which a team cannot pass on).
    const int components = evolvedComponents(f, dimension);
    std::vector<double*> y;
    std::vector<const double*> yHalf, r;
    for (int c = 0; c < components; ++c) {
      y.push_back(p.column(f, c).data());
      yHalf.push_back(p.column(s, c).data());
      r.push_back(p.column(rate, c).data());
    }
#pragma omp parallel if (count >= kThreadTeamFrom)
    for (int c = 0; c < components; ++c) {
#pragma omp for schedule(static) nowait
      for (std::size_t k = 0; k < count; ++k) {
        const std::size_t i = which[k];
        y[c][i] = limitedKick(f, yHalf[c][i], r[c][i], half[k], cap ? cap[i] : 1.0);
      }
    }
  }
  updates_ += which.size();
}

void TimeBins::keepEvaluation(ParticleSet& p, const std::vector<double>& gradient) const {
  const std::size_t n = p.numReal;
  for (const char* name : {"omega", "divv", "curlv"}) {
    const std::vector<double>& from = p.column(*p.field(name), 0);
    std::copy(from.begin(), from.begin() + static_cast<std::ptrdiff_t>(n),
              p.column(*p.field(std::string("last:") + name), 0).begin());
  }
  const Field& g = *p.field(kGradientField);
  const bool have = gradient.size() >= 9 * n;
  for (int c = 0; c < 9; ++c) {
    std::vector<double>& to = p.column(g, c);
    for (std::size_t i = 0; i < n; ++i) to[i] = have ? gradient[9 * i + static_cast<std::size_t>(c)] : 0.0;
  }
}

void TimeBins::restoreEvaluation(ParticleSet& p, std::vector<double>& gradient) const {
  const std::size_t n = p.numReal;
  for (const char* name : {"omega", "divv", "curlv"}) {
    const std::vector<double>& from = p.column(*p.field(std::string("last:") + name), 0);
    std::copy(from.begin(), from.begin() + static_cast<std::ptrdiff_t>(n),
              p.column(*p.field(name), 0).begin());
  }
  if (gradient.empty()) return;  // the run does not reconstruct velocities
  gradient.assign(9 * n, 0.0);
  const Field& g = *p.field(kGradientField);
  for (int c = 0; c < 9; ++c) {
    const std::vector<double>& from = p.column(g, c);
    for (std::size_t i = 0; i < n; ++i) gradient[9 * i + static_cast<std::size_t>(c)] = from[i];
  }
}

bool TimeBins::wake(ParticleSet& p, std::size_t i, int bin) const {
  std::vector<double>& end = p.column(*p.field(kEndField), 0);
  const Tick step = ticksOf(std::clamp(bin, 0, kDeepest));
  const Tick cut = (now_ / step + 1) * step;  // the next tick of `bin` after now
  if (cut >= static_cast<Tick>(end[i])) return false;
  end[i] = static_cast<double>(cut);
  bins(p)[i] = bin;
  return true;
}

}  // namespace ejecta
