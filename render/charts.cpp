#include "render/charts.hpp"

#include <stdlib.h>

#include <stdexcept>
#include <system_error>

#include "core/atomic_file.hpp"
#include "core/json.hpp"
#include "render/chart_script.hpp"
#include "render/process.hpp"

namespace ejecta::render {

namespace fs = std::filesystem;

namespace {

std::string path(const fs::path& p) { return jsonString(p.empty() ? "" : fs::absolute(p).string()); }
const char* boolean(bool b) { return b ? "true" : "false"; }

const char* lineStyleName(LineStyle style) {
  switch (style) {
    case LineStyle::Dotted: return "dotted";
    case LineStyle::Solid: return "solid";
    case LineStyle::Dashed: break;
  }
  return "dashed";
}

// A private temporary directory, removed with everything in it when done.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    std::string pattern = (fs::temp_directory_path() / "ejecta-chart-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
      throw std::runtime_error("cannot create a temporary directory for a chart in '" +
                               fs::temp_directory_path().string() + "'");
    path_ = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

std::string chartSpecJson(const ChartSpec& spec) {
  if (spec.series.empty()) throw std::invalid_argument("chart spec: 'series' is empty");
  if (spec.out.empty()) throw std::invalid_argument("chart spec: 'out' is not given");
  if (spec.width < 50 || spec.height < 50)
    throw std::invalid_argument("chart spec: 'width' and 'height' must be at least 50 pixels");
  if (spec.kind == ChartKind::Bar && spec.x.empty())
    throw std::invalid_argument("chart spec: a bar chart needs 'x', the category column");
  std::string json = "{\n";
  json += "  \"kind\": " + jsonString(spec.kind == ChartKind::Bar ? "bar" : "line") + ",\n";
  json += "  \"csv\": " + path(spec.csv) + ",\n";
  json += "  \"x\": " + jsonString(spec.x) + ",\n";
  json += "  \"series\": [";
  for (std::size_t i = 0; i < spec.series.size(); ++i) {
    const ChartSeries& s = spec.series[i];
    if (s.y.empty())
      throw std::invalid_argument("chart spec: series " + std::to_string(i) + " has no 'y'");
    if (s.csv.empty() && spec.csv.empty())
      throw std::invalid_argument("chart spec: series '" + s.y + "' has no 'csv'");
    if (s.x.empty() && spec.x.empty())
      throw std::invalid_argument("chart spec: series '" + s.y + "' has no 'x'");
    json += i ? ",\n    {" : "\n    {";
    json += "\"y\": " + jsonString(s.y);
    if (!s.label.empty()) json += ", \"label\": " + jsonString(s.label);
    if (!s.x.empty()) json += ", \"x\": " + jsonString(s.x);
    if (!s.csv.empty()) json += ", \"csv\": " + path(s.csv);
    json += std::string(", \"reference\": ") + boolean(s.reference);
    json += std::string(", \"markers\": ") + boolean(s.markers);
    json += std::string(", \"points\": ") + boolean(s.points);
    json += std::string(", \"scatter\": ") + boolean(s.scatter);
    json += std::string(", \"negate\": ") + boolean(s.negate) + "}";
  }
  json += "\n  ],\n";
  json += std::string("  \"xlog\": ") + boolean(spec.xlog) + ",\n";
  json += std::string("  \"ylog\": ") + boolean(spec.ylog) + ",\n";
  json += "  \"xlabel\": " + jsonString(spec.xlabel) + ",\n";
  json += "  \"ylabel\": " + jsonString(spec.ylabel) + ",\n";
  json += "  \"title\": " + jsonString(spec.title) + ",\n";
  json += "  \"hlines\": [";
  for (std::size_t i = 0; i < spec.hlines.size(); ++i)
    json += (i ? ", " : "") + std::string("{\"y\": ") + jsonNumber(spec.hlines[i].y, 17) +
            ", \"label\": " + jsonString(spec.hlines[i].label) +
            ", \"style\": " + jsonString(lineStyleName(spec.hlines[i].style)) + "}";
  json += "],\n  \"vlines\": [";
  for (std::size_t i = 0; i < spec.vlines.size(); ++i)
    json += (i ? ", " : "") + std::string("{\"x\": ") + jsonNumber(spec.vlines[i].y, 17) +
            ", \"label\": " + jsonString(spec.vlines[i].label) + "}";
  json += "],\n";
  json += "  \"note\": " + jsonString(spec.note) + ",\n";
  json += "  \"out\": " + path(spec.out) + ",\n";
  json += "  \"width\": " + std::to_string(spec.width) + ",\n";
  json += "  \"height\": " + std::to_string(spec.height) + "\n}\n";
  return json;
}

ChartRunner::ChartRunner(fs::path python) : python_(std::move(python)) {}

bool ChartRunner::chartsAvailable() {
  if (available_) return *available_;
  // Built stepwise: GCC 12 gives a false -Wrestrict on "'" + string.
  const std::string name = python_.string();
  reason_.clear();
  reason_.push_back('\'');
  reason_ += name;
  std::error_code ec;
  if (!fs::exists(python_, ec)) {
    reason_ += "' does not exist";
    available_ = false;
    return false;
  }
  const ProcessResult r =
      runProcess({python_.string(), "-c",
                  "import matplotlib; matplotlib.use('Agg'); import matplotlib.pyplot"});
  available_ = r.exitCode == 0;
  if (*available_)
    reason_.clear();
  else
    reason_ += "' cannot import matplotlib (Debian: python3-matplotlib): " + r.output;
  return *available_;
}

const std::string& ChartRunner::unavailableReason() {
  chartsAvailable();
  return reason_;
}

void ChartRunner::writeChart(const ChartSpec& spec) {
  writeChartJson(chartSpecJson(spec), spec.out.string());
}

void ChartRunner::writeChartJson(const std::string& json, const std::string& out) {
  if (!chartsAvailable())
    throw std::runtime_error("cannot draw '" + out + "': charts are not available: " + reason_);
  TemporaryDirectory directory;
  const fs::path script = directory.path() / "charts.py";
  const fs::path specFile = directory.path() / "chart.json";
  writeFileAtomically(script, kChartScript);
  writeFileAtomically(specFile, json);
  const ProcessResult r =
      runProcess({python_.string(), script.string(), "--spec", specFile.string()});
  if (r.exitCode != 0)
    throw std::runtime_error("cannot draw '" + out +
                             "': " + (r.output.empty() ? "the chart script failed" : r.output));
}

}  // namespace ejecta::render
