#pragma once
// A layered wall (e.g. 0.2 mm tungsten sprayed on 3 mm aluminium), its finite-volume
// discretisation through the thickness and along the face, the temperature histories a run
// reports, and the interface the two solvers (wall_explicit.hpp, wall_implicit.hpp) share.
//
// Discretisation (docs/thermal_wall.md): nodes sit on both faces and on every interface between
// layers, with `cells` equal cells inside each layer. Node i owns the half cells on either side
// of it, so a node on an interface holds half a cell of each material. The conductance between
// two neighbouring nodes is the series (harmonic) combination of the material between them,
// which is one layer's k/dx because no cell straddles an interface: the heat flux is continuous
// across the interface and a steady profile is exactly piecewise linear. Along the face (2D),
// nodes are spaced evenly, with half control widths at the two ends; a node's along-face
// conductance is the parallel sum of the material in its control thickness.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "radiation/wall_materials.hpp"

namespace ejecta::radiation {

struct WallLayer {
  WallMaterial material;
  double thickness = 0.0;   // [m]
  int cells = 0;            // equal cells across the layer, >= 1
};

// A layer of a built-in material, looked up by name (wallMaterial(); unknown names throw).
WallLayer wallLayer(std::string_view materialName, double thickness, int cells);

// Layers from the hot face to the cold face. Throws std::invalid_argument naming the layer (its
// number and material) and the reason: no layers, a thickness that is not positive and finite,
// fewer than one cell, or a bad material property.
class LayeredWall {
 public:
  explicit LayeredWall(std::vector<WallLayer> layers);

  const std::vector<WallLayer>& layers() const { return layers_; }
  std::size_t layerCount() const { return layers_.size(); }
  int nodeCount() const { return static_cast<int>(position_.size()); }
  double thickness() const { return position_.back(); }
  double arealMass() const;                       // Sum rho * thickness [kg/m^2]

  // Per node, from the hot face (node 0) to the cold face:
  const std::vector<double>& position() const { return position_; }      // [m]
  const std::vector<double>& capacity() const { return capacity_; }      // rho c_p h [J/(m^2 K)]
  // k h along the face over the node's control thickness h [W/K]
  const std::vector<double>& inPlaneConductance() const { return inPlane_; }
  // Per pair of neighbours (nodeCount - 1): k / dx between node i and i + 1 [W/(m^2 K)].
  const std::vector<double>& conductance() const { return conductance_; }

  int firstNode(std::size_t layer) const { return first_.at(layer); }
  int lastNode(std::size_t layer) const { return first_.at(layer) + layers_.at(layer).cells; }
  // Which layer a node belongs to; an interface node belongs to the layer on its cold side.
  std::size_t layerOfNode(int node) const;

 private:
  std::vector<WallLayer> layers_;
  std::vector<int> first_;
  std::vector<double> position_, capacity_, inPlane_, conductance_;
};

// The wall across its thickness (index i, nx nodes) and along its face (index j, ny nodes).
// ny = 1 is the 1D model: quantities are per unit face area. ny > 1 is the 2D model of a strip
// of face of length `faceLength`, nodes on its ends: quantities are per unit depth.
class WallGrid {
 public:
  explicit WallGrid(LayeredWall wall, double faceLength = 0.0, int faceNodes = 1);

  const LayeredWall& wall() const { return wall_; }
  int nx() const { return wall_.nodeCount(); }
  int ny() const { return ny_; }
  std::size_t size() const { return static_cast<std::size_t>(nx()) * ny_; }
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * nx() + i; }
  bool is2D() const { return ny_ > 1; }
  double faceLength() const { return length_; }
  double faceSpacing() const { return dy_; }               // 0 in 1D
  double facePosition(int j) const { return j * dy_; }     // [m]
  double faceWidth(int j) const;                           // control width [m]; 1 in 1D

  // Net heat conducted into every node [W/m^2 in 1D, W/m in 2D]: Sum G (T_neighbour - T).
  void conduction(std::span<const double> temperature, std::span<double> rate) const;

 private:
  LayeredWall wall_;
  double length_;
  int ny_;
  double dy_;
};

// Temperature histories of a run: per record the time, the hot and cold face temperatures, every
// interface and the maximum of every layer (in 2D, maxima along the face); per layer the peak
// temperature and the first time it reached its melting point (linear interpolation between
// records; NaN when never). Record every step to get melting times to the step's accuracy.
class WallHistory {
 public:
  explicit WallHistory(const WallGrid& grid);
  void record(double time, std::span<const double> temperature);

  std::size_t size() const { return time_.size(); }
  const std::vector<double>& time() const { return time_; }
  const std::vector<double>& hotFace() const { return hot_; }
  const std::vector<double>& coldFace() const { return cold_; }
  const std::vector<double>& interfaceTemperature(std::size_t interface) const {
    return interfaces_.at(interface);
  }
  const std::vector<double>& layerMaximum(std::size_t layer) const { return layerMax_.at(layer); }
  double peakTemperature(std::size_t layer) const { return peak_.at(layer); }
  double meltTime(std::size_t layer) const { return melt_.at(layer); }
  const LayeredWall& wall() const { return wall_; }

 private:
  LayeredWall wall_;
  int ny_;
  std::vector<double> time_, hot_, cold_;
  std::vector<std::vector<double>> interfaces_, layerMax_;
  std::vector<double> peak_, melt_;
};

// Writes a history as CSV: time_s, hot_face_K, interface_<k>_K ..., cold_face_K,
// max_<layer>_K ... with one row per record, and a comment line per layer giving its peak and
// melting time. The file is replaced atomically (temporary file, sync, rename); throws
// std::runtime_error naming the file on failure.
void writeWallHistoryCsv(const std::filesystem::path& path, const WallHistory& history);

// What both solvers offer. advance(dt) moves the state by dt (the explicit solver may split it
// into stable sub-steps); run() advances to an end time in steps of at most dt, recording every
// step in `history` when given.
class WallSolver {
 public:
  virtual ~WallSolver() = default;
  virtual void advance(double dt) = 0;
  virtual double time() const = 0;
  virtual std::span<const double> temperature() const = 0;
  virtual const WallGrid& grid() const = 0;
  // Net energy that entered through the flux faces since the start, as the scheme applied it
  // [J/m^2 in 1D, J/m in 2D] (absorbed minus re-radiated; fixed-temperature faces not included).
  virtual double faceEnergy() const = 0;

  void run(double endTime, double dt, WallHistory* history = nullptr);
};

// Stored heat relative to a reference state: Sum C (T - T_ref) [J/m^2 in 1D, J/m in 2D].
double storedHeat(const WallGrid& grid, std::span<const double> temperature,
                  std::span<const double> reference);

}  // namespace ejecta::radiation
