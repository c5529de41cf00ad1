#pragma once
// How much memory this process may use, and the refusal when a request would not fit: a run,
// a grid or a study that cannot fit is refused before it starts, with the number it would
// need, instead of allocating until the machine or the kernel's OOM killer stops it.
#include <cstdint>
#include <string>

namespace ejecta {

// Physical memory, or the cgroup's limit (containers, batch jobs) when that is lower [bytes].
double machineMemoryBytes();

// "2.6 TB", "310 MB": bytes in decimal units for messages.
std::string formatBytes(double bytes);

// Throws InputError "<what> needs about <bytes> (<detail>), more than the <machine> this
// process may use; <advice>" when `bytes` exceeds the share `fraction` of machineMemoryBytes().
void requireMemory(const std::string& what, double bytes, const std::string& detail,
                   const std::string& advice, double fraction = 0.9);

}  // namespace ejecta
