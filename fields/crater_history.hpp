#pragma once
// The crater's growth during an impact run: RUN_DIR/crater_history.csv, one row per snapshot
// output, rewritten whole (atomically) at every output so that a reader or a crash never sees a
// half-written file. Columns (docs/crater.md, docs/impact.md):
//   time_s, found, depth_m, apparent_diameter_m, rim_diameter_m, rim_height_m,
//   volume_m3, excavated_mass_kg, elongation             (RZ and 3D)
//   ... area_m2, excavated_mass_kg_per_m                 (2D planar: per metre, no elongation)
// Values are written in the shortest form that reads back to the same double, so the last row
// of a run equals its summary.json crater figures exactly.
#include <filesystem>
#include <string>
#include <vector>

#include "fields/crater.hpp"
#include "fields/history_csv.hpp"

namespace ejecta::fields {

// The CSV header line (no newline) for a planar or a volumetric crater.
std::string craterHistoryHeader(bool planar);
// One row (no newline) for the crater measured at `time` [s].
std::string craterHistoryRow(double time, const CraterMetrics& m, bool planar);

class CraterHistory {
 public:
  CraterHistory(std::filesystem::path file, bool planar);

  // Adds the crater at `time` and rewrites the file. At the first call of a run that does not
  // start at t = 0 (a restart), the rows of the file already there that are earlier than
  // `time` are kept first, so the history runs on across restarts without repeated rows.
  // Throws std::runtime_error naming the file and line when that earlier file cannot be read
  // as a crater history of the same kind (planar or not).
  void record(double time, const CraterMetrics& m);

  const std::vector<std::string>& rows() const { return history_.rows(); }

 private:
  HistoryCsv history_;
  bool planar_;
};

// Rows of an existing history file whose time is below `before` [s] (none if there is no
// file). Throws std::runtime_error naming the file and line for a wrong header or a row whose
// time is not a number.
std::vector<std::string> readCraterHistoryRows(const std::filesystem::path& file, bool planar,
                                               double before);

}  // namespace ejecta::fields
