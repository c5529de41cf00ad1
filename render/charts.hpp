#pragma once
// Charts from CSV files: line charts (linear or log axes, several series, a dashed reference
// curve for an exact solution) and grouped bar charts, drawn by matplotlib. The script,
// render/charts.py, is compiled into the library and run with /usr/bin/python3; a machine
// without python3 or matplotlib simply has no charts (chartsAvailable() says so), and the CSV
// the caller wrote is still there.
//
//   ChartRunner charts;
//   if (charts.chartsAvailable()) charts.writeChart({.csv = "energy.csv", .x = "time_s",
//       .series = {{.y = "kinetic_J", .label = "kinetic"}}, .out = "energy.png"});
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ejecta::render {

enum class ChartKind { Line, Bar };

struct ChartSeries {
  std::string y{};              // column
  std::string label{};          // legend entry (default: the column's name)
  std::string x{};              // this series' x column (default: the chart's)
  std::filesystem::path csv{};  // this series' file (default: the chart's)
  bool reference = false;       // an exact or reference curve: dashed black
  bool markers = false;         // points joined by lines, in order of x
  bool points = false;          // small dots, no line: every particle of a profile
  bool scatter = false;         // large markers, no line: a few measured points
  bool negate = false;          // plot -y: a depth drawn downward below a surface at 0
};

// How a horizontal line is drawn (grey in every case): dashed by default; where a chart has two
// kinds (an estimate and its band) one of them solid or dotted tells them apart in the legend.
enum class LineStyle { Dashed, Dotted, Solid };

// A horizontal line across a line chart (the pre-impact surface, a limit), or a vertical one
// (a resolution limit, always dotted): `y` is its place on the axis it crosses.
struct ChartLine {
  double y = 0.0;
  std::string label{};
  LineStyle style = LineStyle::Dashed;
};

struct ChartSpec {
  ChartKind kind = ChartKind::Line;
  std::filesystem::path csv{};
  std::string x{};  // x column; Bar: the column of category names
  std::vector<ChartSeries> series{};
  bool xlog = false, ylog = false;
  std::string xlabel{}, ylabel{}, title{};  // labels with units, e.g. "t [s]"; an x label in
                                            // [s] is shown in ms or us when the times are short
  std::vector<ChartLine> hlines{};          // grey lines, each in its style (dashed by default)
  std::vector<ChartLine> vlines{};          // dotted grey vertical lines, at x = ChartLine::y
  std::string note{};                       // a line of text in the middle of the axes: "no
                                            // coating needed" where the bars are all zero
  std::filesystem::path out{};              // the PNG
  int width = 900, height = 600;            // pixels
};

// The spec as the JSON charts.py reads (paths made absolute). Throws std::invalid_argument
// naming the key for a spec that cannot work: no series, no out, no csv or x for a series, a
// size below 50 pixels.
std::string chartSpecJson(const ChartSpec& spec);

class ChartRunner {
 public:
  explicit ChartRunner(std::filesystem::path python = "/usr/bin/python3");

  // Whether `python` runs and imports matplotlib; asked once, then remembered.
  bool chartsAvailable();
  // Why not, when chartsAvailable() is false.
  const std::string& unavailableReason();

  // Draws the chart into spec.out (atomically: a temporary name, then rename). Throws
  // std::runtime_error when charts are not available or the script fails (with its message:
  // a missing file or column, a value that is not a number), std::invalid_argument for a
  // spec chartSpecJson rejects.
  void writeChart(const ChartSpec& spec);
  // The same for a spec already in charts.py's JSON (its other kinds, e.g. "ble" for
  // `ejecta whipple`); `out` names the PNG in messages.
  void writeChartJson(const std::string& json, const std::string& out);

 private:
  std::filesystem::path python_;
  std::optional<bool> available_;
  std::string reason_;
};

}  // namespace ejecta::render
