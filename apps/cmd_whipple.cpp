// `ejecta whipple SHIELD.toml [--out DIR] [--json]`: ballistic-limit curves of a Whipple shield
// (Christiansen's equations, radiation/whipple.hpp) for each rear wall listed, and the wall that
// stops the file's threat (radiation/whipple_study.hpp, docs/whipple.md). Writes ble.csv,
// whipple.json and, where matplotlib is installed, ble.png.
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "apps/commands.hpp"
#include "core/atomic_file.hpp"
#include "coupling/json_text.hpp"
#include "radiation/whipple_study.hpp"
#include "render/charts.hpp"
#include "sim/setup/scene_catalog.hpp"

namespace ejecta::app {

using namespace ejecta::coupling;  // the in-situ chain (coupling/)

namespace fs = std::filesystem;

namespace {

// ble.png through the chart script's "ble" kind (curves per rear wall, regime corners, the
// threat). Returns an empty string, or why there is no chart.
std::string drawBleChart(const fs::path& csv, const fs::path& png, const radiation::WhippleResult& r) {
  render::ChartRunner charts;
  if (!charts.chartsAvailable()) return charts.unavailableReason();
  const radiation::WhippleThreat& t = r.study.threat;
  std::string spec = "{\"kind\": \"ble\", \"csv\": " + jsonString(fs::absolute(csv).string()) +
                     ", \"out\": " + jsonString(fs::absolute(png).string()) +
                     ", \"title\": " + jsonString(r.study.name + ": Whipple shield ballistic limit") + ", \"threat\": ";
  if (t.diameter > 0.0 && t.speed > 0.0)
    spec += "{\"speed_m_s\": " + std::to_string(t.speed) + ", \"diameter_m\": " + std::to_string(t.diameter) + "}";
  else
    spec += "null";
  spec += "}\n";
  try {
    charts.writeChartJson(spec, png.string());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

int whippleCommand(const WhippleArgs& args) {
  // A file, or a shipped study's name ("whipple/haiv", `ejecta scenes`).
  const SceneText text = readSceneArgument(args.shield, "Whipple study");
  const radiation::WhippleStudy study = radiation::parseWhippleStudy(text.text, text.label);
  const radiation::WhippleResult result = radiation::runWhippleStudy(study);
  const fs::path out = args.outDir.empty() ? fs::path("runs") / study.name : fs::path(args.outDir);
  fs::create_directories(out);
  writeFileAtomically(out / "ble.csv", radiation::formatWhippleCsv(result));
  const std::string json = radiation::formatWhippleJson(result);
  writeFileAtomically(out / "whipple.json", json);
  const std::string noChart = drawBleChart(out / "ble.csv", out / "ble.png", result);
  if (!noChart.empty()) std::fprintf(stderr, "ejecta whipple: no ble.png: %s\n", noChart.c_str());

  if (args.json) {
    std::fputs(json.c_str(), stdout);
  } else {
    std::fputs(radiation::formatWhippleText(result).c_str(), stdout);
    std::printf("wrote %s/{ble.csv, whipple.json%s}\n", out.string().c_str(), noChart.empty() ? ", ble.png" : "");
  }
  return 0;
}

}  // namespace ejecta::app
