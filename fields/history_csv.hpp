#pragma once
// A history in CSV, one row per output time, rewritten whole (atomically) at every record so
// that a reader or a crash never sees half a file. At the first record of a run that does not
// start at t = 0 (a restart), the rows of the file already there that are earlier than that
// time are kept first, so the history runs on across restarts without repeated rows. Used by
// crater_history.csv and shield_history.csv.
#include <filesystem>
#include <string>
#include <vector>

namespace ejecta::fields {

// Shortest text that reads back to the same double (std::to_chars), so that a history and the
// summary's JSON agree to the last bit.
std::string shortestNumber(double value);

// Rows of an existing history file whose time (first column) is below `before` [s]; none if
// there is no file. Throws std::runtime_error naming the file and line when its header is not
// `header` ("not a <kind>") or a row's time is not a number.
std::vector<std::string> readHistoryRows(const std::filesystem::path& file, const std::string& header,
                                         const std::string& kind, double before);

class HistoryCsv {
 public:
  HistoryCsv(std::filesystem::path file, std::string header, std::string kind);
  // Adds the row (no newline) of `time` [s] and rewrites the file.
  void record(double time, const std::string& row);
  const std::vector<std::string>& rows() const { return rows_; }

 private:
  std::filesystem::path file_;
  std::string header_, kind_;
  bool started_ = false;
  std::vector<std::string> rows_;
};

}  // namespace ejecta::fields
