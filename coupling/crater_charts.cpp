#include "coupling/crater_charts.hpp"

#include "coupling/csv_header.hpp"

namespace fs = std::filesystem;

namespace ejecta::coupling {

std::vector<std::string> writeCraterCharts(render::ChartRunner& charts, const fs::path& dir,
                                           const std::string& sceneName, Geometry geometry) {
  std::vector<std::string> written;
  const fs::path history = dir / "crater_history.csv";
  if (csvRowCount(history) > 0) {
    charts.writeChart({.csv = history, .x = "time_s",
                       .series = {{.y = "depth_m", .label = "depth", .markers = true},
                                  {.y = "apparent_diameter_m", .label = "apparent diameter",
                                   .markers = true}},
                       .xlabel = "t [s]", .ylabel = "length [m]",
                       .title = sceneName + ": crater growth", .out = dir / "crater_growth.png"});
    written.push_back("crater_growth.png");
    // Volume has its own chart: its scale is not a length's. A planar run has an area.
    const bool planar = hasColumn(csvHeader(history), "area_m2");
    charts.writeChart({.csv = history, .x = "time_s",
                       .series = {{.y = planar ? "area_m2" : "volume_m3",
                                   .label = planar ? "area (per metre)" : "volume",
                                   .markers = true}},
                       .xlabel = "t [s]",
                       .ylabel = planar ? "crater area [m^2]" : "crater volume [m^3]",
                       .title = sceneName + ": crater " + (planar ? "area" : "volume"),
                       .out = dir / "crater_volume.png"});
    written.push_back("crater_volume.png");
  }
  const fs::path profile = dir / "crater_profile.csv";
  if (csvRowCount(profile) > 0) {
    std::vector<render::ChartSeries> series;
    // Depth drawn downward, below the pre-impact surface: the crater looks like a crater.
    if (geometry == Geometry::Axisymmetric) {
      series = {{.y = "depth_mean_m", .label = "crater floor", .negate = true}};
    } else if (geometry == Geometry::Planar) {
      series = {{.y = "depth_min_m", .label = "shallower side", .negate = true},
                {.y = "depth_max_m", .label = "deeper side", .negate = true}};
    } else {
      series = {{.y = "depth_mean_m", .label = "mean over azimuths", .negate = true},
                {.y = "depth_min_m", .label = "shallowest azimuth", .negate = true},
                {.y = "depth_max_m", .label = "deepest azimuth", .negate = true}};
    }
    charts.writeChart({.csv = profile, .x = "distance_m", .series = series,
                       .xlabel = "distance from the axis along the original surface [m]",
                       .ylabel = "height relative to the original surface [m]",
                       .title = sceneName + ": crater profile at the end",
                       .hlines = {{.y = 0.0, .label = "pre-impact surface"}},
                       .out = dir / "crater_profile.png"});
    written.push_back("crater_profile.png");
  }
  return written;
}

}  // namespace ejecta::coupling
