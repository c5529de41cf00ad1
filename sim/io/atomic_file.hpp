#pragma once
// Forwarding header: atomic file writing lives in core/ (core/atomic_file.hpp). It stays only
// for sim/io/snapshot.cpp and sim/io/xdmf.cpp, which are being rewritten elsewhere; delete it
// once they include core/atomic_file.hpp.
#include "core/atomic_file.hpp"
