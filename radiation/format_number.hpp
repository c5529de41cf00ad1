#pragma once
// printf-style formatting of one number, for messages and the text reports.
#include <cstdio>
#include <string>

namespace ejecta::radiation {

inline std::string formatNumber(const char* spec, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, spec, v);
  return buf;
}

}  // namespace ejecta::radiation
