#pragma once
// Shield sizing: the thinnest coating of each candidate material that keeps a structural layer
// (e.g. 3 mm aluminium) below its limit through a given heating history. Each trial thickness is
// a transient 1D run of the coated wall (wall_implicit.hpp or wall_explicit.hpp); the thickness
// is found by bisection, assuming the structure's peak temperature falls as the coating thickens.
// The seed's example (sec. 4.5): 0.2 mm of tungsten, +50 kg on its vehicle. docs/thermal_wall.md.
#include <string>
#include <vector>

#include "radiation/layered_wall.hpp"
#include "radiation/wall_boundary.hpp"
#include "radiation/wall_materials.hpp"

namespace ejecta::radiation {

enum class WallScheme { Explicit, CrankNicolson };

// The temperature the structural layer must stay below.
struct ShieldLimit {
  enum class Kind { MeltingPoint, MarginBelowMelting, Temperature };
  Kind kind = Kind::MeltingPoint;
  double value = 0.0;   // MarginBelowMelting: the margin [K]; Temperature: the limit [K]
  double temperatureFor(const WallMaterial& structure) const;
};

struct ShieldSizingProblem {
  WallLayer structure;                       // material, thickness, cells
  // The hot face: an incident flux history (FaceCondition::irradiated), or the seed's method, a
  // fixed surface temperature. With useCoatingOptics the face's absorptivity and emissivity are
  // replaced by the outer material's (the coating's, or the structure's when bare).
  FaceCondition hotFace;
  bool useCoatingOptics = true;
  FaceCondition coldFace = FaceCondition::insulated();
  double initialTemperature = 293.15;        // [K]
  double duration = 0.0;                     // the heating history's length [s], > 0
  double timeStep = 0.0;                     // [s]; 0: duration / 2000
  WallScheme scheme = WallScheme::CrankNicolson;
  ShieldLimit limit;
  double patchArea = 1.0;                    // the coated area, for the added mass [m^2]
  double maxThickness = 5e-3;                // thickest coating considered [m]
  double minThickness = 1e-7;                // below this a coating counts as none [m]
  double tolerance = 1e-3;                   // bisection ends at this relative bracket width
  int coatingCells = 10;                     // cells across the coating at every thickness
};

// One transient run of a coating thickness (0: the bare structure).
struct CoatingTrial {
  double thickness = 0.0;          // [m]
  double structurePeak = 0.0;      // peak of the structural layer, interface included [K]
  double coatingPeak = 0.0;        // peak of the coating [K] (0 when bare)
  double structureMeltTime = 0.0;  // when the structure reached its melting point [s], or NaN
  bool withinLimit = false;        // structurePeak < the limit
};

struct ShieldSizing {
  std::string material;
  bool feasible = false;           // some thickness up to maxThickness works
  double thickness = 0.0;          // minimum coating thickness found [m]: the bracket's safe end
  double addedMass = 0.0;          // density * thickness * patchArea [kg]
  double structurePeak = 0.0;      // at `thickness` [K] (at maxThickness when infeasible)
  double coatingPeak = 0.0;        // [K]
  bool coatingMelts = false;       // the coating itself reached its melting point
  double limit = 0.0;              // the structure's limit [K]
  int runs = 0;                    // transient runs made
  std::string note;
};

// Throws std::invalid_argument naming the bad field of the problem.
void validateSizingProblem(const ShieldSizingProblem& problem);

// One run: the coating (thickness > 0) on the structure, or the bare structure (thickness 0).
CoatingTrial evaluateCoating(const ShieldSizingProblem& problem, const WallMaterial& coating,
                             double thickness);

// The thinnest coating of one material: thickness 0 when the bare structure already stays below
// the limit; not feasible when maxThickness does not suffice.
ShieldSizing sizeCoating(const ShieldSizingProblem& problem, const WallMaterial& coating);

// Every candidate (OpenMP over candidates; each result is independent of the thread count).
// The hot face's flux function must be thread safe.
std::vector<ShieldSizing> sizeShield(const ShieldSizingProblem& problem,
                                     const std::vector<WallMaterial>& candidates);

}  // namespace ejecta::radiation
