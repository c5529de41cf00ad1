#pragma once
// The energy ledger: how the energy of a run is shared among its materials over time, and for an
// impact, how much of the impactor's kinetic energy the target now holds. energy.csv carries the
// per-material columns every step; summary.json the initial and final partition
// (docs/output_format.md).
#include <optional>
#include <string>
#include <vector>

#include "sim/state/conservation.hpp"
#include "sim/setup/scene.hpp"
#include "sim/run/simulation.hpp"
#include "sim/run/summary.hpp"

namespace ejecta {

// Materials of moving bodies (the impactor), of the energy sources (the explosive: detonated JWL
// materials and the materials of bodies that take a DED deposit), and of the other bodies at rest
// (the target). Any is empty when the scene has none.
struct LedgerGroups {
  std::vector<int> impactor;
  std::vector<int> explosive;
  std::vector<int> target;
};
LedgerGroups ledgerGroups(const Scene& scene);

// 1 kt of TNT = 4.184e12 J: the convention of nuclear yields (1 cal = 4.184 J, 1 t TNT = 1 Gcal;
// Glasstone & Dolan 1977, sec. 1.45).
inline constexpr double kJoulesPerKilotonTnt = 4.184e12;

// The device's yield [J] (per metre depth in 2D planar): the DED deposits plus the initial
// internal energy of the detonated explosives (their chemical energy, e0 per unit mass).
double sourceYield(const Scene& scene, const std::vector<double>& initialInternal);

// What the target's energy gain is measured against: the yield of a source, else the impactor's
// kinetic energy. reference = 0: nothing to measure (no source, no impact).
struct CouplingReference {
  std::vector<int> target;
  double targetInitial = 0.0;  // the target's total energy at t = 0 [J]
  double reference = 0.0;      // [J]
  bool isYield = false;
};
// When every source is a delayed deposit, the target's reference is its energy just before the
// first of them fired (`firings`, Simulation::depositFirings), so that an impactor's energy is not
// counted as the device's; before that, reference = 0.
CouplingReference couplingReference(const Scene& scene, const std::vector<double>& initialKinetic,
                                    const std::vector<double>& initialInternal,
                                    const std::vector<DepositFiring>& firings = {});
// Whether the scene's only sources are delayed deposits (time > 0), and then the first firing
// (nullptr before it, or when some source acts at t = 0).
bool onlyDelayedSources(const Scene& scene);
const DepositFiring* sourceFiring(const Scene& scene, const std::vector<DepositFiring>& firings);
// The target's energy gain over the reference, from per-material totals now.
double couplingShare(const CouplingReference& ref, const std::vector<ConservedTotals>& now);

// Depth of the source below the target's surface [m] (negative: a height above it), from the
// first detonation's point or the first deposit's centre (or its body's centre of mass; for a
// delayed deposit that has fired, the centroid of its energy then), and the target bodies'
// shapes (sphere, shell, box, half-space). Empty without a source or target.
std::optional<double> depthOfBurst(const Scene& scene, const std::vector<DepositFiring>& firings = {});

// The material's name as a CSV/JSON key part: letters, digits, '-' and '_' kept, others '_'.
std::string ledgerKey(const std::string& materialName);

// The partition at the end of a run, typed: what summary.json's energy entries hold
// (docs/output_format.md) and what `ejecta run` prints.
struct LedgerSummary {
  struct Material {
    std::string key;  // ledgerKey of its name
    std::optional<double> initialKinetic, initialInternal;  // [J]; empty without the t = 0 totals
    double kinetic = 0.0, internal = 0.0;                    // now [J]
  };
  // When a deposit fired: at t = 0 with the particles, or a delayed one at its step (or never).
  struct Deposit {
    std::string key;       // "deposit_" + ledgerKey of its name
    bool delayed = false;  // time > 0
    std::optional<DepositFiring> firing;  // a delayed deposit's, once it fired
  };
  // A source's share of the run (the seed's Tables 3.4-3.6 and eq. 3.1).
  struct Source {
    double yield = 0.0;             // [J] (per metre in 2D planar)
    bool planar = false;            // the yield is per metre: no kt, no scaled depth
    std::optional<double> yieldKt;  // [kt of TNT]; not for 2D planar
    int dimension = 3;              // coordinates of a firing point
    std::vector<Deposit> deposits;
    std::optional<double> targetEnergyBeforeSource;  // [J], a delayed source's reference
    std::optional<double> targetShareOfYield, targetKineticFraction, targetInternalFraction,
        explosiveShareOfYield;
    std::optional<double> depthOfBurst;        // [m]
    std::optional<double> scaledDepthOfBurst;  // [m / kt^(1/3)]
  };
  // An impact: the impactor's initial kinetic energy and what the target gained.
  struct Impact {
    double impactorKinetic = 0.0, targetKineticGain = 0.0, targetInternalGain = 0.0;  // [J]
    std::optional<double> targetShareOfImpactorEnergy;
  };
  std::vector<Material> materials;
  std::optional<Source> source;  // with deposits or detonations and the t = 0 totals
  std::optional<Impact> impact;  // with an impactor, a target and the t = 0 totals
};

// The partition: per material the initial and final kinetic and internal energy; for an impact
// the impactor's initial kinetic energy, the target's gain, its kinetic/internal split and the
// share of the impactor's kinetic energy it represents; for a source the yield (J and kt), when
// each deposit fired, the share of it in the target and its split (from the target's energy just
// before a delayed source), the share still in the explosive, and the depth of burst, scaled by
// the cube root of the yield (the seed's eq. 3.1; not for 2D planar runs, whose yield is per
// metre).
LedgerSummary ledgerSummary(const Scene& scene, const std::vector<double>& initialKinetic,
                            const std::vector<double>& initialInternal,
                            const std::vector<ConservedTotals>& now,
                            const std::vector<DepositFiring>& firings = {});

// Writes the partition into the summary's extras: the one place its summary.json keys are named.
void addToSummary(const LedgerSummary& ledger, RunSummary& summary);

// ledgerSummary added to the summary's extras.
void addEnergyPartition(const Scene& scene, const std::vector<double>& initialKinetic,
                        const std::vector<double>& initialInternal,
                        const std::vector<ConservedTotals>& now, RunSummary& summary,
                        const std::vector<DepositFiring>& firings = {});

}  // namespace ejecta
