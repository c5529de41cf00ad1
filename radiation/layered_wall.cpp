#include "radiation/layered_wall.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"

namespace ejecta::radiation {

namespace {

constexpr double kNever = std::numeric_limits<double>::quiet_NaN();

std::string layerName(std::size_t index, std::size_t count, const WallLayer& layer) {
  return "layer " + std::to_string(index + 1) + " of " + std::to_string(count) + " ('" +
         layer.material.name + "')";
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

WallLayer wallLayer(std::string_view materialName, double thickness, int cells) {
  return {wallMaterial(materialName), thickness, cells};
}

LayeredWall::LayeredWall(std::vector<WallLayer> layers) : layers_(std::move(layers)) {
  if (layers_.empty()) throw std::invalid_argument("layered wall: no layers");
  const std::size_t count = layers_.size();
  int nodes = 1;
  for (std::size_t l = 0; l < count; ++l) {
    const WallLayer& layer = layers_[l];
    const std::string which = "layered wall, " + layerName(l, count, layer);
    if (!(std::isfinite(layer.thickness) && layer.thickness > 0.0))
      throw std::invalid_argument(which + ": thickness must be positive and finite [m], got " +
                                  number(layer.thickness));
    if (layer.cells < 1 || layer.cells > 10'000'000)
      throw std::invalid_argument(which + ": cells must lie in [1, 1e7], got " +
                                  std::to_string(layer.cells));
    try {
      validateWallMaterial(layer.material);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(which + ": " + e.what());
    }
    first_.push_back(nodes - 1);
    nodes += layer.cells;
  }
  const auto n = static_cast<std::size_t>(nodes);
  position_.assign(n, 0.0);
  capacity_.assign(n, 0.0);
  inPlane_.assign(n, 0.0);
  conductance_.assign(n - 1, 0.0);
  double x = 0.0;
  for (std::size_t l = 0; l < count; ++l) {
    const WallLayer& layer = layers_[l];
    const WallMaterial& m = layer.material;
    const double dx = layer.thickness / layer.cells;
    const auto first = static_cast<std::size_t>(first_[l]);
    for (int c = 0; c < layer.cells; ++c) {
      const std::size_t a = first + static_cast<std::size_t>(c);
      position_[a] = x + c * dx;
      // Each cell gives half its heat capacity and along-face conductance to each end node.
      capacity_[a] += 0.5 * m.density * m.specificHeat * dx;
      capacity_[a + 1] += 0.5 * m.density * m.specificHeat * dx;
      inPlane_[a] += 0.5 * m.alongFaceConductivity() * dx;
      inPlane_[a + 1] += 0.5 * m.alongFaceConductivity() * dx;
      conductance_[a] = m.conductivity / dx;
    }
    x += layer.thickness;
    position_[first + static_cast<std::size_t>(layer.cells)] = x;
  }
}

double LayeredWall::arealMass() const {
  double m = 0.0;
  for (const auto& l : layers_) m += l.material.density * l.thickness;
  return m;
}

std::size_t LayeredWall::layerOfNode(int node) const {
  if (node < 0 || node >= nodeCount())
    throw std::out_of_range("layered wall: node " + std::to_string(node) + " out of range");
  const auto it = std::upper_bound(first_.begin(), first_.end(), node);
  return static_cast<std::size_t>(it - first_.begin()) - 1;
}

WallGrid::WallGrid(LayeredWall wall, double faceLength, int faceNodes)
    : wall_(std::move(wall)), length_(faceLength), ny_(faceNodes), dy_(0.0) {
  if (faceNodes < 1)
    throw std::invalid_argument("wall grid: faceNodes must be >= 1, got " +
                                std::to_string(faceNodes));
  if (faceNodes == 1) {
    length_ = 0.0;
    return;
  }
  if (!(std::isfinite(faceLength) && faceLength > 0.0))
    throw std::invalid_argument("wall grid: a 2D wall (faceNodes > 1) needs a positive, finite "
                                "faceLength [m], got " + number(faceLength));
  dy_ = faceLength / (faceNodes - 1);
}

double WallGrid::faceWidth(int j) const {
  if (ny_ == 1) return 1.0;
  return (j == 0 || j == ny_ - 1) ? 0.5 * dy_ : dy_;
}

void WallGrid::conduction(std::span<const double> temperature, std::span<double> rate) const {
  const int n = nx(), m = ny_;
  const double* g = wall_.conductance().data();
  const double* kh = wall_.inPlaneConductance().data();
  const double invDy = m > 1 ? 1.0 / dy_ : 0.0;
  // Columns are independent: each thread writes its own; the result does not depend on the
  // thread count.
#pragma omp parallel for schedule(static) if (size() > 40000)
  for (int j = 0; j < m; ++j) {
    const double w = faceWidth(j);
    const double* t = temperature.data() + index(0, j);
    double* r = rate.data() + index(0, j);
    r[0] = w * g[0] * (t[1] - t[0]);
    for (int i = 1; i < n - 1; ++i)
      r[i] = w * (g[i - 1] * (t[i - 1] - t[i]) + g[i] * (t[i + 1] - t[i]));
    r[n - 1] = w * g[n - 2] * (t[n - 2] - t[n - 1]);
    if (m == 1) continue;
    if (j > 0) {
      const double* left = t - n;
      for (int i = 0; i < n; ++i) r[i] += kh[i] * invDy * (left[i] - t[i]);
    }
    if (j < m - 1) {
      const double* right = t + n;
      for (int i = 0; i < n; ++i) r[i] += kh[i] * invDy * (right[i] - t[i]);
    }
  }
}

WallHistory::WallHistory(const WallGrid& grid)
    : wall_(grid.wall()),
      ny_(grid.ny()),
      interfaces_(grid.wall().layerCount() - 1),
      layerMax_(grid.wall().layerCount()),
      peak_(grid.wall().layerCount(), -std::numeric_limits<double>::infinity()),
      melt_(grid.wall().layerCount(), kNever) {}

void WallHistory::record(double time, std::span<const double> temperature) {
  const int nx = wall_.nodeCount();
  if (temperature.size() != static_cast<std::size_t>(nx) * ny_)
    throw std::invalid_argument("wall history: temperature field of the wrong size");
  auto nodeMax = [&](int i) {
    double v = temperature[static_cast<std::size_t>(i)];
    for (int j = 1; j < ny_; ++j)
      v = std::max(v, temperature[static_cast<std::size_t>(j) * nx + i]);
    return v;
  };
  const double previousTime = time_.empty() ? time : time_.back();
  time_.push_back(time);
  hot_.push_back(nodeMax(0));
  cold_.push_back(nodeMax(nx - 1));
  for (std::size_t k = 0; k < interfaces_.size(); ++k)
    interfaces_[k].push_back(nodeMax(wall_.firstNode(k + 1)));
  for (std::size_t l = 0; l < layerMax_.size(); ++l) {
    double v = -std::numeric_limits<double>::infinity();
    for (int i = wall_.firstNode(l); i <= wall_.lastNode(l); ++i) v = std::max(v, nodeMax(i));
    const double melting = wall_.layers()[l].material.meltingPoint;
    if (std::isnan(melt_[l]) && v >= melting) {
      const bool crossed = !layerMax_[l].empty() && layerMax_[l].back() < melting;
      melt_[l] = crossed ? previousTime + (melting - layerMax_[l].back()) /
                                              (v - layerMax_[l].back()) * (time - previousTime)
                         : time;
    }
    layerMax_[l].push_back(v);
    peak_[l] = std::max(peak_[l], v);
  }
}

void writeWallHistoryCsv(const std::filesystem::path& path, const WallHistory& history) {
  const LayeredWall& wall = history.wall();
  std::string out;
  for (std::size_t l = 0; l < wall.layerCount(); ++l) {
    const WallLayer& layer = wall.layers()[l];
    const double melt = history.meltTime(l);
    out += "# layer " + std::to_string(l + 1) + " " + layer.material.name + " " +
           number(layer.thickness) + " m: peak " + number(history.peakTemperature(l)) +
           " K, melting point " + number(layer.material.meltingPoint) + " K, reached at " +
           (std::isnan(melt) ? std::string("never") : number(melt) + " s") + "\n";
  }
  std::vector<std::string> header{"time_s", "hot_face_K"};
  for (std::size_t k = 0; k + 1 < wall.layerCount(); ++k)
    header.push_back("interface_" + std::to_string(k + 1) + "_K");
  header.push_back("cold_face_K");
  for (std::size_t l = 0; l < wall.layerCount(); ++l)
    header.push_back("max_" + std::to_string(l + 1) + "_" + wall.layers()[l].material.name + "_K");
  CsvWriter csv(header);
  for (std::size_t r = 0; r < history.size(); ++r) {
    csv.number(history.time()[r]).number(history.hotFace()[r]);
    for (std::size_t k = 0; k + 1 < wall.layerCount(); ++k) csv.number(history.interfaceTemperature(k)[r]);
    csv.number(history.coldFace()[r]);
    for (std::size_t l = 0; l < wall.layerCount(); ++l) csv.number(history.layerMaximum(l)[r]);
    csv.endRow();
  }
  out += csv.str();
  writeFileAtomically(path, out);
}

void WallSolver::run(double endTime, double dt, WallHistory* history) {
  const double span = endTime - time();
  if (!(dt > 0.0 && std::isfinite(dt)))
    throw std::invalid_argument("wall run: time step must be positive and finite, got " +
                                number(dt));
  if (!(span >= 0.0 && std::isfinite(span)))
    throw std::invalid_argument("wall run: end time " + number(endTime) +
                                " s is before the current time " + number(time()) + " s");
  if (history && history->size() == 0) history->record(time(), temperature());
  // Equal steps that land on the end time; no step exceeds dt. Every step but the last is the
  // same number, so an implicit solver keeps its factorisation; the last absorbs the rounding.
  const auto steps = static_cast<long>(std::ceil(span / dt * (1.0 - 1e-12)));
  const double h = span / static_cast<double>(steps);
  for (long k = 1; k <= steps; ++k) {
    advance(k < steps ? h : endTime - time());
    if (history) history->record(time(), temperature());
  }
}

double storedHeat(const WallGrid& grid, std::span<const double> temperature,
                  std::span<const double> reference) {
  const auto& c = grid.wall().capacity();
  double sum = 0.0;
  for (int j = 0; j < grid.ny(); ++j) {
    const double w = grid.faceWidth(j);
    for (int i = 0; i < grid.nx(); ++i) {
      const std::size_t n = grid.index(i, j);
      sum += c[static_cast<std::size_t>(i)] * w * (temperature[n] - reference[n]);
    }
  }
  return sum;
}

}  // namespace ejecta::radiation
