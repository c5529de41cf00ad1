#include "render/charts.hpp"

#include <stdlib.h>

#include <cstdio>
#include <stdexcept>
#include <system_error>

#include "render/atomic_write.hpp"
#include "render/chart_script.hpp"
#include "render/process.hpp"

namespace ejecta::render {

namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (u < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", u);
          out += escaped;
        } else {
          out += c;  // UTF-8 passes through: JSON text is UTF-8
        }
    }
  }
  return out + "\"";
}

std::string path(const fs::path& p) { return quoted(p.empty() ? "" : fs::absolute(p).string()); }
const char* boolean(bool b) { return b ? "true" : "false"; }

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
  json += "  \"kind\": " + quoted(spec.kind == ChartKind::Bar ? "bar" : "line") + ",\n";
  json += "  \"csv\": " + path(spec.csv) + ",\n";
  json += "  \"x\": " + quoted(spec.x) + ",\n";
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
    json += "\"y\": " + quoted(s.y);
    if (!s.label.empty()) json += ", \"label\": " + quoted(s.label);
    if (!s.x.empty()) json += ", \"x\": " + quoted(s.x);
    if (!s.csv.empty()) json += ", \"csv\": " + path(s.csv);
    json += std::string(", \"reference\": ") + boolean(s.reference);
    json += std::string(", \"markers\": ") + boolean(s.markers);
    json += std::string(", \"points\": ") + boolean(s.points) + "}";
  }
  json += "\n  ],\n";
  json += std::string("  \"xlog\": ") + boolean(spec.xlog) + ",\n";
  json += std::string("  \"ylog\": ") + boolean(spec.ylog) + ",\n";
  json += "  \"xlabel\": " + quoted(spec.xlabel) + ",\n";
  json += "  \"ylabel\": " + quoted(spec.ylabel) + ",\n";
  json += "  \"title\": " + quoted(spec.title) + ",\n";
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
