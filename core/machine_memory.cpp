#include "core/machine_memory.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/input_error.hpp"

namespace ejecta {

namespace {

// cgroup v2 (memory.max) or v1 (memory.limit_in_bytes); "max" or absent: no limit.
double cgroupLimitBytes() {
  for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream in(path);
    std::string text;
    if (!(in >> text) || text == "max") continue;
    try {
      const double limit = std::stod(text);
      if (limit > 0) return limit;
    } catch (const std::exception&) {
    }
  }
  return INFINITY;
}

}  // namespace

double machineMemoryBytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
  const double physical = pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize)
                                                    : INFINITY;
  return std::fmin(physical, cgroupLimitBytes());
}

std::string formatBytes(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) bytes /= 1000.0, ++u;
  char buf[48];
  if (!std::isfinite(bytes)) return "an unbounded amount";
  std::snprintf(buf, sizeof buf, "%.3g %s", bytes, units[u]);
  return buf;
}

void requireMemory(const std::string& what, double bytes, const std::string& detail,
                   const std::string& advice, double fraction) {
  const double machine = machineMemoryBytes();
  if (bytes <= fraction * machine) return;
  throw InputError(what + " needs about " + formatBytes(bytes) + " (" + detail + "), more than the " +
                   formatBytes(machine) + " of memory this machine gives the process; " + advice);
}

}  // namespace ejecta
