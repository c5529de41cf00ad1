#include "coupling/verify_charts.hpp"

#include <algorithm>
#include <array>

#include "coupling/csv_header.hpp"
#include "core/atomic_file.hpp"

namespace fs = std::filesystem;

namespace ejecta::coupling {

namespace {

// The reference column of `column`, or "" when the CSV has none.
std::string referenceOf(const std::vector<std::string>& columns, const std::string& column) {
  for (const char* suffix : {"_exact", "_ref", "_reference"})
    if (hasColumn(columns, column + suffix)) return column + suffix;
  return "";
}

bool isReference(const std::string& column) {
  for (const std::string suffix : {"_exact", "_ref", "_reference"})
    if (column.size() > suffix.size() &&
        column.compare(column.size() - suffix.size(), suffix.size(), suffix) == 0)
      return true;
  return false;
}

// The problem's own CSVs in dir (NAME.csv, NAME_*.csv), its convergence table excepted, in a
// fixed order.
std::vector<fs::path> profileFiles(const verify::Report& report, const fs::path& dir) {
  std::vector<fs::path> files;
  const std::string prefix = report.problem + "_";
  const std::string table = report.problem + "_convergence.csv";
  if (!fs::is_directory(dir)) return files;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() != ".csv" || name == table) continue;
    if (name.rfind(prefix, 0) == 0 || name == report.problem + ".csv") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::string> errorCharts(render::ChartRunner& charts, const verify::Report& report,
                                     const fs::path& dir) {
  std::vector<std::string> written;
  const fs::path table = dir / (report.problem + "_convergence.csv");
  std::vector<std::string> relative;
  for (const std::string& c : csvHeader(table))
    if (c.size() > 9 && c.compare(c.size() - 9, 9, "_relative") == 0) relative.push_back(c);
  if (report.runs.size() < 2 || relative.empty()) return written;
  std::vector<render::ChartSeries> series;
  for (const std::string& c : relative)
    series.push_back({.y = c, .label = c.substr(0, c.size() - 9), .markers = true});
  render::ChartSpec spacing{.csv = table, .x = "spacing_m", .series = series, .xlog = true,
                            .ylog = true, .xlabel = "particle spacing [m]",
                            .ylabel = "L1 error / coarsest run's",
                            .title = report.problem + ": error against resolution",
                            .out = dir / (report.problem + "_error_vs_spacing.png")};
  spacing.series.push_back({.y = "first_order", .label = "first order", .reference = true});
  charts.writeChart(spacing);
  written.push_back(spacing.out.filename().string());
  render::ChartSpec cost{.csv = table, .x = "wall_s", .series = series, .xlog = true,
                         .ylog = true, .xlabel = "wall time [s]",
                         .ylabel = "L1 error / coarsest run's",
                         .title = report.problem + ": accuracy against run time",
                         .out = dir / (report.problem + "_error_vs_time.png")};
  charts.writeChart(cost);
  written.push_back(cost.out.filename().string());
  return written;
}

// An axis label with the column's SI unit, from the names the problems write (x, rho, v, P, and
// names that end in their unit: shock_radius_m, t_s).
std::string axisLabel(const std::string& column) {
  static const std::array<std::array<const char*, 2>, 14> known{{
      {"x", "x [m]"}, {"r", "r [m]"}, {"d", "distance [m]"},
      {"rho", "density [kg/m^3]"}, {"density", "density [kg/m^3]"},
      {"v", "velocity [m/s]"}, {"u", "velocity [m/s]"}, {"v_r", "radial velocity [m/s]"},
      {"P", "pressure [Pa]"}, {"pressure", "pressure [Pa]"}, {"peak_P", "peak pressure [Pa]"},
      {"t_s", "t [s]"}, {"shock_radius_m", "shock radius [m]"}, {"arrival", "arrival time [s]"},
  }};
  for (const auto& [name, label] : known)
    if (column == name) return label;
  return column;
}

// Above this many rows a profile is particles: dots, not a line through them.
constexpr std::size_t kScatterRows = 200;

std::vector<std::string> profileCharts(render::ChartRunner& charts, const verify::Report& report,
                                       const fs::path& dir) {
  std::vector<std::string> written;
  for (const fs::path& file : profileFiles(report, dir)) {
    const std::vector<std::string> columns = csvHeader(file);
    if (columns.size() < 2) continue;
    const bool scatter = csvRowCount(file) > kScatterRows;
    for (std::size_t k = 1; k < columns.size(); ++k) {
      const std::string& column = columns[k];
      if (isReference(column)) continue;
      const std::string reference = referenceOf(columns, column);
      if (reference.empty()) continue;
      render::ChartSpec spec{.csv = file, .x = columns[0],
                             .series = {{.y = column, .label = "ejecta",
                                         .markers = !scatter, .points = scatter},
                                        {.y = reference, .label = reference.substr(column.size() + 1),
                                         .reference = true}},
                             .xlabel = axisLabel(columns[0]), .ylabel = axisLabel(column),
                             .title = file.stem().string() + ": " + column,
                             .out = dir / (file.stem().string() + "_" + column + ".png")};
      charts.writeChart(spec);
      written.push_back(spec.out.filename().string());
    }
  }
  return written;
}

}  // namespace

std::string writeConvergenceTable(const verify::Report& report, const fs::path& dir) {
  fs::create_directories(dir);
  const std::string name = report.problem + "_convergence.csv";
  writeFileAtomically(dir / name, verify::convergenceCsv(report));
  return name;
}

std::vector<std::string> writeVerificationCharts(render::ChartRunner& charts,
                                                 const verify::Report& report, const fs::path& dir) {
  std::vector<std::string> written = errorCharts(charts, report, dir);
  for (const std::string& p : profileCharts(charts, report, dir)) written.push_back(p);
  return written;
}

}  // namespace ejecta::coupling
