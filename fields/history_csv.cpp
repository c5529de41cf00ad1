#include "fields/history_csv.hpp"

#include <charconv>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "core/atomic_file.hpp"

namespace fs = std::filesystem;

namespace ejecta::fields {

std::string shortestNumber(double value) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, result.ptr);
}

std::vector<std::string> readHistoryRows(const fs::path& file, const std::string& header,
                                         const std::string& kind, double before) {
  std::vector<std::string> kept;
  std::ifstream in(file);
  if (!in) return kept;
  std::string line;
  if (!std::getline(in, line)) return kept;  // empty file: nothing to keep
  if (line != header)
    throw std::runtime_error(file.string() + ":1: not a " + kind + " (header '" + line +
                             "', expected '" + header + "')");
  for (long lineNumber = 2; std::getline(in, line); ++lineNumber) {
    if (line.empty()) continue;
    double time = 0.0;
    const char* end = line.data() + line.size();
    const auto [ptr, ec] = std::from_chars(line.data(), end, time);
    if (ec != std::errc() || ptr == end || *ptr != ',')
      throw std::runtime_error(file.string() + ":" + std::to_string(lineNumber) +
                               ": time_s is not a number in '" + line + "'");
    if (time < before) kept.push_back(line);
  }
  return kept;
}

HistoryCsv::HistoryCsv(fs::path file, std::string header, std::string kind)
    : file_(std::move(file)), header_(std::move(header)), kind_(std::move(kind)) {}

void HistoryCsv::record(double time, const std::string& row) {
  if (!started_) {
    started_ = true;
    // A fresh run's first output is at t = 0: an old file in the directory is simply replaced.
    if (time > 0.0) rows_ = readHistoryRows(file_, header_, kind_, time);
  }
  rows_.push_back(row);
  std::string text = header_ + '\n';
  for (const std::string& r : rows_) text += r + '\n';
  writeFileAtomically(file_, text);
}

}  // namespace ejecta::fields
