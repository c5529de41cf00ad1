#pragma once
// Opening a grid file for reading, the one way every reader in fields/ does it: OpenVDB
// initialised once, the file's seal checked (grid_file_seal.hpp), OpenVDB's errors turned into
// messages naming the file. Internal to fields/ (it includes OpenVDB).
#include <openvdb/openvdb.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/join.hpp"
#include "fields/grid_file_seal.hpp"

namespace ejecta::fields {

inline void initialiseOpenVdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

inline void openGridFile(openvdb::io::File& file, const std::string& path) {
  initialiseOpenVdb();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw std::runtime_error(path + ": no such grid file");
  verifyGridFile(path);
  try {
    file.open();
  } catch (const openvdb::Exception& e) {
    throw std::runtime_error(path + ": not a readable OpenVDB file (" + e.what() + ")");
  }
}

// The names of an open file's grids, in the file's order.
inline std::vector<std::string> gridNamesIn(openvdb::io::File& file) {
  std::vector<std::string> names;
  for (auto it = file.beginName(); it != file.endName(); ++it) names.push_back(*it);
  return names;
}

// A missing grid named with the grids the file has, so a misspelt name is seen at once.
inline void requireGrid(openvdb::io::File& file, const std::string& path, const std::string& name) {
  if (file.hasGrid(name)) return;
  throw std::runtime_error(path + ": no grid named '" + name + "' (the file has: " + joinList(gridNamesIn(file)) + ")");
}

}  // namespace ejecta::fields
