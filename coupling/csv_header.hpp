#pragma once
// The first line of a CSV file as column names (empty when the file is missing or empty), and
// how many data rows follow it: what a chart needs to know before it asks for columns.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace ejecta::coupling {

inline std::vector<std::string> csvHeader(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::vector<std::string> columns;
  std::stringstream s(line);
  for (std::string c; std::getline(s, c, ',');) columns.push_back(c);
  return columns;
}

inline std::size_t csvRowCount(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) ++lines;
  return lines > 0 ? lines - 1 : 0;
}

inline bool hasColumn(const std::vector<std::string>& columns, const std::string& name) {
  return std::find(columns.begin(), columns.end(), name) != columns.end();
}

}  // namespace ejecta::coupling
