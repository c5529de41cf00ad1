#pragma once
// Opening a grid file for reading, the one way every reader in fields/ does it: OpenVDB
// initialised once, the file's seal checked (grid_file_seal.hpp), OpenVDB's errors turned into
// messages naming the file. Internal to fields/ (it includes OpenVDB).
#include <openvdb/openvdb.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>

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

}  // namespace ejecta::fields
