#pragma once
// HDF5 plumbing for ejecta's snapshot files (sim/io/snapshot.cpp): identifiers that close
// themselves, errors as exceptions with HDF5's own reason, typed datasets and attributes with
// their units and descriptions, and checked reading (shape, element class, presence). Internal
// to sim/io/.
#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ejecta::hdf5 {

// ---------------------------------------------------------------------------------------------
// HDF5 plumbing: handle ownership and error reporting.
// ---------------------------------------------------------------------------------------------

// Owns one HDF5 identifier and closes it with the matching H5?close.
class Hid {
 public:
  using Closer = herr_t (*)(hid_t);
  Hid(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Hid(Hid&& other) noexcept
      : id_(std::exchange(other.id_, H5I_INVALID_HID)), closer_(other.closer_) {}
  Hid& operator=(Hid&&) = delete;
  Hid(const Hid&) = delete;
  Hid& operator=(const Hid&) = delete;
  ~Hid() { close(); }

  hid_t get() const { return id_; }
  // Closes now; the result lets callers check closes whose failure matters (the file).
  herr_t close() { return id_ >= 0 ? closer_(std::exchange(id_, H5I_INVALID_HID)) : 0; }

 private:
  hid_t id_;
  Closer closer_;
};

// The root cause recorded on HDF5's error stack by the call that just failed.
inline std::string hdf5Detail() {
  std::string detail;
  auto innermost = [](unsigned, const H5E_error2_t* err, void* out) -> herr_t {
    auto& text = *static_cast<std::string*>(out);
    if (text.empty() && err->desc != nullptr) text = err->desc;
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, innermost, &detail);
  return detail.empty() ? std::string() : " (" + detail + ")";
}

// HDF5 prints its whole error stack to stderr by default; we report through exceptions instead,
// so printing is switched off while a snapshot is read or written and restored afterwards.
class QuietHdf5Errors {
 public:
  QuietHdf5Errors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  QuietHdf5Errors(const QuietHdf5Errors&) = delete;
  QuietHdf5Errors& operator=(const QuietHdf5Errors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

[[noreturn]] inline void failHdf5(const std::string& what) {
  throw std::runtime_error(what + hdf5Detail());
}

inline Hid checked(hid_t id, Hid::Closer closer, const std::string& what) {
  if (id < 0) failHdf5(what);
  return Hid(id, closer);
}

inline void check(herr_t rc, const std::string& what) {
  if (rc < 0) failHdf5(what);
}

// Memory type, file type and type class for each stored element type.
template <typename T> struct H5Type;
template <> struct H5Type<double> {
  static hid_t memory() { return H5T_NATIVE_DOUBLE; }
  static hid_t file() { return H5T_IEEE_F64LE; }
  static constexpr H5T_class_t kClass = H5T_FLOAT;
};
template <> struct H5Type<int> {
  static_assert(sizeof(int) == 4, "material is stored as int32");
  static hid_t memory() { return H5T_NATIVE_INT; }
  static hid_t file() { return H5T_STD_I32LE; }
  static constexpr H5T_class_t kClass = H5T_INTEGER;
};
template <> struct H5Type<std::int64_t> {
  static hid_t memory() { return H5T_NATIVE_INT64; }
  static hid_t file() { return H5T_STD_I64LE; }
  static constexpr H5T_class_t kClass = H5T_INTEGER;
};
template <> struct H5Type<std::uint64_t> {
  static hid_t memory() { return H5T_NATIVE_UINT64; }
  static hid_t file() { return H5T_STD_U64LE; }
  static constexpr H5T_class_t kClass = H5T_INTEGER;
};

// Fixed-length UTF-8 string type holding `text` plus its terminating NUL.
inline Hid stringType(const std::string& text) {
  Hid type = checked(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create string type");
  check(H5Tset_size(type.get(), text.size() + 1), "cannot size string type");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), "cannot set string padding");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "cannot set string encoding");
  return type;
}

inline Hid scalarSpace() { return checked(H5Screate(H5S_SCALAR), H5Sclose, "cannot create dataspace"); }

// ---------------------------------------------------------------------------------------------
// Writing
// ---------------------------------------------------------------------------------------------

inline void writeStringAttribute(hid_t obj, const char* name, const std::string& value) {
  const Hid type = stringType(value);
  const Hid space = scalarSpace();
  const Hid attr = checked(H5Acreate2(obj, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                           H5Aclose, std::string("cannot create attribute '") + name + "'");
  check(H5Awrite(attr.get(), type.get(), value.c_str()),
        std::string("cannot write attribute '") + name + "'");
}

template <typename T>
void writeNumericAttribute(hid_t obj, const char* name, const T* values, hsize_t count) {
  const Hid space = count == 1 ? scalarSpace()
                               : checked(H5Screate_simple(1, &count, nullptr), H5Sclose,
                                         "cannot create dataspace");
  const Hid attr =
      checked(H5Acreate2(obj, name, H5Type<T>::file(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose, std::string("cannot create attribute '") + name + "'");
  check(H5Awrite(attr.get(), H5Type<T>::memory(), values),
        std::string("cannot write attribute '") + name + "'");
}

template <typename T>
void writeScalarAttribute(hid_t obj, const char* name, T value) {
  writeNumericAttribute(obj, name, &value, 1);
}

struct DatasetSpec {
  const char* name;
  const char* units;
  const char* description;
};

// Chunked layout with HDF5's Fletcher-32 checksum on every chunk: a flipped byte in a stored
// array fails the read ("data error detected by Fletcher32 checksum") instead of entering a
// restart. Chunks of about 1 MiB of whole rows; an empty dataset stays contiguous (HDF5 chunks
// must not be larger than a fixed-size extent, nor empty).
inline Hid checksummedLayout(const hsize_t* dims, int rank, std::size_t elementBytes) {
  Hid dcpl = checked(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "cannot create property list");
  if (dims[0] == 0) return dcpl;
  const hsize_t rowBytes = elementBytes * (rank == 2 ? dims[1] : 1);
  const hsize_t chunk[2] = {std::min<hsize_t>(dims[0], std::max<hsize_t>(1, (hsize_t{1} << 20) / rowBytes)),
                            rank == 2 ? dims[1] : 1};
  check(H5Pset_chunk(dcpl.get(), rank, chunk), "cannot set the chunk size");
  check(H5Pset_fletcher32(dcpl.get()), "cannot add the Fletcher-32 checksum");
  return dcpl;
}

// Where one writer's rows go in a dataset of `total` rows: rows [first, first + n). `create`:
// the dataset is made by this write (and tagged); otherwise it exists already (the later ranks
// of a distributed snapshot, sim/io/distributed_snapshot.cpp).
struct RowSlot {
  std::size_t first = 0;
  std::size_t total = 0;
  bool create = true;
};

// Writes `data` (n or n * columns values, row-major) as rows `slot` of dataset spec.name in
// `group`, of shape (total) or, for matrix, (total, columns); a created dataset is tagged with
// `units` and `description`.
template <typename T>
void writeRows(hid_t group, const DatasetSpec& spec, const RowSlot& slot, std::size_t n, bool matrix,
               const T* data, hsize_t columns = 3) {
  const std::string label = std::string("dataset '") + spec.name + "'";
  const hsize_t dims[2] = {static_cast<hsize_t>(slot.total), columns};
  auto open = [&] {
    if (!slot.create)
      return checked(H5Dopen2(group, spec.name, H5P_DEFAULT), H5Dclose, "cannot open " + label);
    const Hid space = checked(H5Screate_simple(matrix ? 2 : 1, dims, nullptr), H5Sclose,
                              "cannot create dataspace");
    const Hid layout = checksummedLayout(dims, matrix ? 2 : 1, sizeof(T));
    Hid created = checked(H5Dcreate2(group, spec.name, H5Type<T>::file(), space.get(), H5P_DEFAULT,
                                     layout.get(), H5P_DEFAULT),
                          H5Dclose, "cannot create " + label);
    writeStringAttribute(created.get(), "units", spec.units);
    writeStringAttribute(created.get(), "description", spec.description);
    return created;
  };
  const Hid dset = open();
  // An empty vector's data() may be null, which H5Dwrite rejects; nothing to write anyway.
  if (n == 0) return;
  if (slot.first == 0 && n == slot.total) {
    check(H5Dwrite(dset.get(), H5Type<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          "cannot write " + label);
    return;
  }
  const Hid fileSpace = checked(H5Dget_space(dset.get()), H5Sclose, "cannot get dataspace of " + label);
  const hsize_t start[2] = {static_cast<hsize_t>(slot.first), 0};
  const hsize_t count[2] = {static_cast<hsize_t>(n), columns};
  if (slot.first + n > slot.total) throw std::runtime_error(label + ": rows beyond its end");
  check(H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
        "cannot select rows of " + label);
  const Hid memory = checked(H5Screate_simple(matrix ? 2 : 1, count, nullptr), H5Sclose,
                             "cannot make a dataspace for " + label);
  check(H5Dwrite(dset.get(), H5Type<T>::memory(), memory.get(), fileSpace.get(), H5P_DEFAULT, data),
        "cannot write " + label);
}

// Creates dataset spec.name in `group` with shape (n) or (n, columns) and writes all of it.
template <typename T>
void writeDataset(hid_t group, const DatasetSpec& spec, std::size_t n, bool vector3,
                  const T* data, hsize_t columns = 3) {
  writeRows(group, spec, RowSlot{0, n, true}, n, vector3, data, columns);
}

template <typename T>
void requireSize(const std::vector<T>& values, std::size_t n, const char* name) {
  if (values.size() < n)
    throw std::runtime_error(std::string("particle array for '") + name + "' has " +
                             std::to_string(values.size()) + " entries, fewer than the " +
                             std::to_string(n) + " real particles");
}

template <typename T>
void writeScalarField(hid_t group, const DatasetSpec& spec, const std::vector<T>& values,
                      std::size_t n, const RowSlot& slot) {
  requireSize(values, n, spec.name);
  writeRows(group, spec, slot, n, false, values.data());
}


inline Hid createGroup(hid_t file, const char* name) {
  return checked(H5Gcreate2(file, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                 std::string("cannot create group '") + name + "'");
}

inline void writeStringDataset(hid_t group, const char* name, const std::string& text,
                        const char* description) {
  const Hid type = stringType(text);
  const Hid space = scalarSpace();
  const Hid dset = checked(H5Dcreate2(group, name, type.get(), space.get(), H5P_DEFAULT,
                                      H5P_DEFAULT, H5P_DEFAULT),
                           H5Dclose, std::string("cannot create dataset '") + name + "'");
  check(H5Dwrite(dset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.c_str()),
        std::string("cannot write dataset '") + name + "'");
  writeStringAttribute(dset.get(), "units", "1");
  writeStringAttribute(dset.get(), "description", description);
}

// A 1-D dataset of fixed-length UTF-8 strings, each padded to the longest (h5py reads it as an
// array of bytes; `.astype(str)` gives text).
inline void writeStringArray(hid_t group, const char* name, const std::vector<std::string>& texts,
                             const char* description) {
  std::size_t longest = 0;
  for (const std::string& t : texts) longest = std::max(longest, t.size());
  const Hid type = stringType(std::string(longest, ' '));
  const std::size_t width = longest + 1;
  std::vector<char> buffer(std::max<std::size_t>(1, texts.size() * width), '\0');
  for (std::size_t i = 0; i < texts.size(); ++i) texts[i].copy(buffer.data() + i * width, texts[i].size());
  const hsize_t count = texts.size();
  const Hid space = checked(H5Screate_simple(1, &count, nullptr), H5Sclose, "cannot create dataspace");
  const Hid dset = checked(H5Dcreate2(group, name, type.get(), space.get(), H5P_DEFAULT,
                                      H5P_DEFAULT, H5P_DEFAULT),
                           H5Dclose, std::string("cannot create dataset '") + name + "'");
  if (count > 0)
    check(H5Dwrite(dset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()),
          std::string("cannot write dataset '") + name + "'");
  writeStringAttribute(dset.get(), "units", "1");
  writeStringAttribute(dset.get(), "description", description);
}

// ---------------------------------------------------------------------------------------------
// Reading
// ---------------------------------------------------------------------------------------------

// True if every component of the absolute path `/a/b/c` exists (H5Lexists needs the parents).
inline bool linkExists(hid_t file, const std::string& path) {
  for (std::size_t slash = path.find('/', 1);; slash = path.find('/', slash + 1)) {
    const std::string prefix = path.substr(0, slash);
    const htri_t exists = H5Lexists(file, prefix.c_str(), H5P_DEFAULT);
    if (exists < 0) failHdf5("cannot look up '" + prefix + "'");
    if (exists == 0) return false;
    if (slash == std::string::npos) return true;
  }
}

inline Hid openDataset(hid_t file, const std::string& path) {
  if (!linkExists(file, path)) throw std::runtime_error("missing dataset '" + path + "'");
  return checked(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose,
                 "cannot open dataset '" + path + "'");
}

inline Hid openGroup(hid_t file, const std::string& path) {
  if (!linkExists(file, path)) throw std::runtime_error("missing group '" + path + "'");
  return checked(H5Gopen2(file, path.c_str(), H5P_DEFAULT), H5Gclose,
                 "cannot open group '" + path + "'");
}

inline std::vector<hsize_t> datasetShape(hid_t dset, const std::string& path) {
  const Hid space = checked(H5Dget_space(dset), H5Sclose, "cannot get dataspace of '" + path + "'");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) failHdf5("cannot get rank of '" + path + "'");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
    failHdf5("cannot get shape of '" + path + "'");
  return dims;
}

inline std::string shapeText(const std::vector<hsize_t>& dims) {
  std::string text = "(";
  for (std::size_t i = 0; i < dims.size(); ++i)
    text += (i ? ", " : "") + std::to_string(dims[i]);
  return text + ")";
}

template <typename T>
void requireClass(hid_t type, const std::string& label) {
  if (H5Tget_class(type) != H5Type<T>::kClass)
    throw std::runtime_error(label + " has the wrong element type (expected " +
                             (H5Type<T>::kClass == H5T_FLOAT ? "floating point" : "integer") +
                             ")");
}

// Rows [first, first + count) of a dataset with n rows.
struct RowRange {
  std::size_t first = 0;
  std::size_t count = 0;
};

// A chunked dataset's stored chunks, checked before HDF5 reads them. In the 1.8 file format the
// chunk index (a version-1 B-tree) carries no checksum, and HDF5 allocates whatever chunk size it
// finds there: one flipped byte made it ask for 1.7 GB (found by tests/fuzz). A chunk must lie
// inside the file, hold no more than its values plus Fletcher-32's 4 bytes, and not have skipped
// the checksum filter. Contiguous datasets (empty ones, strings) have no chunks to check.
inline void checkStoredChunks(hid_t dset, const std::string& path) {
  const std::string label = "dataset '" + path + "'";
  const Hid dcpl = checked(H5Dget_create_plist(dset), H5Pclose, "cannot get the layout of " + label);
  if (H5Pget_layout(dcpl.get()) != H5D_CHUNKED) return;
  hsize_t chunk[H5S_MAX_RANK];
  const int rank = H5Pget_chunk(dcpl.get(), H5S_MAX_RANK, chunk);
  if (rank <= 0) throw std::runtime_error("cannot get the chunk shape of " + label);
  const Hid type = checked(H5Dget_type(dset), H5Tclose, "cannot get type of " + label);
  hsize_t chunkBytes = H5Tget_size(type.get());
  for (int d = 0; d < rank; ++d) chunkBytes *= chunk[d];
  const Hid file = checked(H5Iget_file_id(dset), H5Fclose, "cannot get the file of " + label);
  hsize_t fileBytes = 0;
  check(H5Fget_filesize(file.get(), &fileBytes), "cannot get the file size");
  // (HDF5 1.10 takes the dataset's own dataspace here, not H5S_ALL.)
  const Hid space = checked(H5Dget_space(dset), H5Sclose, "cannot get dataspace of " + label);
  hsize_t chunks = 0;
  check(H5Dget_num_chunks(dset, space.get(), &chunks), "cannot count the chunks of " + label);
  for (hsize_t i = 0; i < chunks; ++i) {
    hsize_t offset[H5S_MAX_RANK];
    unsigned skippedFilters = 0;
    haddr_t address = 0;
    hsize_t bytes = 0;
    check(H5Dget_chunk_info(dset, space.get(), i, offset, &skippedFilters, &address, &bytes),
          "cannot read the index of chunk " + std::to_string(i) + " of " + label);
    if (skippedFilters != 0)
      throw std::runtime_error(label + ": chunk " + std::to_string(i) +
                               " was stored without its checksum filter");
    if (bytes > chunkBytes + 4 || address == HADDR_UNDEF || address > fileBytes ||
        bytes > fileBytes - address)
      throw std::runtime_error(label + ": chunk " + std::to_string(i) + " claims " +
                               std::to_string(bytes) + " bytes at offset " + std::to_string(address) +
                               " (a chunk holds at most " + std::to_string(chunkBytes + 4) +
                               ", the file " + std::to_string(fileBytes) + "): the file is corrupt");
  }
}

// Reads dataset `path` that must have shape (n) or, for vector3, (n, columns): all of it, or the
// rows `rows` when given (a hyperslab: a distributed restart reads each rank's slice only).
template <typename T>
std::vector<T> readDataset(hid_t file, const std::string& path, std::size_t n, bool vector3,
                           hsize_t columns = 3, std::optional<RowRange> rows = std::nullopt) {
  const Hid dset = openDataset(file, path);
  const std::vector<hsize_t> dims = datasetShape(dset.get(), path);
  const std::vector<hsize_t> expected =
      vector3 ? std::vector<hsize_t>{n, columns} : std::vector<hsize_t>{n};
  if (dims != expected)
    throw std::runtime_error("dataset '" + path + "' has shape " + shapeText(dims) +
                             ", expected " + shapeText(expected));
  const Hid type = checked(H5Dget_type(dset.get()), H5Tclose, "cannot get type of '" + path + "'");
  requireClass<T>(type.get(), "dataset '" + path + "'");
  checkStoredChunks(dset.get(), path);
  const RowRange range = rows ? *rows : RowRange{0, n};
  std::vector<T> values(vector3 ? columns * range.count : range.count);
  if (values.empty()) return values;
  if (!rows) {
    check(H5Dread(dset.get(), H5Type<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
          "cannot read dataset '" + path + "'");
    return values;
  }
  const Hid file_space = checked(H5Dget_space(dset.get()), H5Sclose, "cannot get dataspace of '" + path + "'");
  const hsize_t start[2] = {range.first, 0};
  const hsize_t count[2] = {range.count, columns};
  check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
        "cannot select rows of '" + path + "'");
  const Hid memory = checked(H5Screate_simple(vector3 ? 2 : 1, count, nullptr), H5Sclose,
                             "cannot make a dataspace for '" + path + "'");
  check(H5Dread(dset.get(), H5Type<T>::memory(), memory.get(), file_space.get(), H5P_DEFAULT, values.data()),
        "cannot read dataset '" + path + "'");
  return values;
}


// Reads a string stored with either fixed or variable length (files touched by h5py or other
// tools may use the latter). `read(memType, buffer)` performs the H5Aread/H5Dread.
template <typename ReadFn>
std::string readString(hid_t storedType, const std::string& label, ReadFn read) {
  if (H5Tget_class(storedType) != H5T_STRING)
    throw std::runtime_error(label + " is not a string");
  const htri_t variable = H5Tis_variable_str(storedType);
  if (variable < 0) failHdf5("cannot inspect type of " + label);
  const Hid memType = checked(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create string type");
  // HDF5 does not convert between character sets, so read in the stored one.
  const H5T_cset_t cset = H5Tget_cset(storedType);
  if (cset < 0) failHdf5("cannot get character set of " + label);
  check(H5Tset_cset(memType.get(), cset), "cannot set string encoding");
  if (variable > 0) {
    check(H5Tset_size(memType.get(), H5T_VARIABLE), "cannot size string type");
    char* buffer = nullptr;
    check(read(memType.get(), static_cast<void*>(&buffer)), "cannot read " + label);
    std::string text = buffer ? buffer : "";
    H5free_memory(buffer);
    return text;
  }
  const std::size_t size = H5Tget_size(storedType);
  if (size == 0) failHdf5("cannot get size of " + label);
  check(H5Tset_size(memType.get(), size), "cannot size string type");
  std::string buffer(size, '\0');
  check(read(memType.get(), static_cast<void*>(buffer.data())), "cannot read " + label);
  return buffer.substr(0, buffer.find('\0'));
}

inline Hid openAttribute(hid_t obj, const char* name, const std::string& owner) {
  const std::string label = std::string("attribute '") + name + "' of " + owner;
  const htri_t exists = H5Aexists(obj, name);
  if (exists < 0) failHdf5("cannot look up " + label);
  if (exists == 0) throw std::runtime_error("missing " + label);
  return checked(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose, "cannot open " + label);
}

inline std::string readStringAttribute(hid_t obj, const char* name, const std::string& owner) {
  const Hid attr = openAttribute(obj, name, owner);
  const Hid type = checked(H5Aget_type(attr.get()), H5Tclose, "cannot get attribute type");
  const std::string label = std::string("attribute '") + name + "' of " + owner;
  return readString(type.get(), label, [&attr](hid_t mem, void* buf) {
    return H5Aread(attr.get(), mem, buf);
  });
}

template <typename T>
std::vector<T> readNumericAttribute(hid_t obj, const char* name, const std::string& owner,
                                    std::size_t count) {
  const Hid attr = openAttribute(obj, name, owner);
  const std::string label = std::string("attribute '") + name + "' of " + owner;
  const Hid type = checked(H5Aget_type(attr.get()), H5Tclose, "cannot get type of " + label);
  requireClass<T>(type.get(), label);
  const Hid space = checked(H5Aget_space(attr.get()), H5Sclose, "cannot get space of " + label);
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  if (points != static_cast<hssize_t>(count))
    throw std::runtime_error(label + " has " + std::to_string(points) + " values, expected " +
                             std::to_string(count));
  std::vector<T> values(count);
  check(H5Aread(attr.get(), H5Type<T>::memory(), values.data()), "cannot read " + label);
  return values;
}

// An attribute of any length that older files may lack (then empty).
inline std::vector<double> readOptionalArrayAttribute(hid_t obj, const char* name, const std::string& owner) {
  const htri_t exists = H5Aexists(obj, name);
  if (exists <= 0) return {};
  const Hid attr = openAttribute(obj, name, owner);
  const Hid space = checked(H5Aget_space(attr.get()), H5Sclose, "cannot get the space of " + std::string(name));
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  return readNumericAttribute<double>(obj, name, owner, static_cast<std::size_t>(points));
}

template <typename T>
T readScalarAttribute(hid_t obj, const char* name, const std::string& owner) {
  return readNumericAttribute<T>(obj, name, owner, 1)[0];
}

inline std::string readStringDataset(hid_t file, const std::string& path) {
  const Hid dset = openDataset(file, path);
  const Hid type = checked(H5Dget_type(dset.get()), H5Tclose, "cannot get type of '" + path + "'");
  return readString(type.get(), "dataset '" + path + "'", [&dset](hid_t mem, void* buf) {
    return H5Dread(dset.get(), mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
  });
}

// A 1-D string dataset (fixed length as writeStringArray writes it, or variable length as h5py
// may) of at most `most` entries of at most 4 kB each.
inline std::vector<std::string> readStringArray(hid_t file, const std::string& path, std::size_t most) {
  const Hid dset = openDataset(file, path);
  const std::string label = "dataset '" + path + "'";
  const std::vector<hsize_t> dims = datasetShape(dset.get(), path);
  if (dims.size() != 1 || dims[0] > most)
    throw std::runtime_error(label + " has shape " + shapeText(dims) + ", expected at most (" +
                             std::to_string(most) + ")");
  const Hid type = checked(H5Dget_type(dset.get()), H5Tclose, "cannot get type of " + label);
  if (H5Tget_class(type.get()) != H5T_STRING) throw std::runtime_error(label + " is not a string array");
  const std::size_t n = dims[0];
  std::vector<std::string> texts(n);
  if (n == 0) return texts;
  const Hid memType = checked(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create string type");
  const H5T_cset_t cset = H5Tget_cset(type.get());
  if (cset < 0) failHdf5("cannot get character set of " + label);
  check(H5Tset_cset(memType.get(), cset), "cannot set string encoding");
  const htri_t variable = H5Tis_variable_str(type.get());
  if (variable < 0) failHdf5("cannot inspect type of " + label);
  if (variable > 0) {
    check(H5Tset_size(memType.get(), H5T_VARIABLE), "cannot size string type");
    std::vector<char*> pointers(n, nullptr);
    check(H5Dread(dset.get(), memType.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()),
          "cannot read " + label);
    for (std::size_t i = 0; i < n; ++i) {
      if (pointers[i]) texts[i] = pointers[i];
      H5free_memory(pointers[i]);
    }
    return texts;
  }
  const std::size_t width = H5Tget_size(type.get());
  if (width == 0 || width > 4096) throw std::runtime_error(label + " has strings of " +
                                                           std::to_string(width) + " bytes");
  check(H5Tset_size(memType.get(), width), "cannot size string type");
  std::vector<char> buffer(n * width, '\0');
  check(H5Dread(dset.get(), memType.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()),
        "cannot read " + label);
  for (std::size_t i = 0; i < n; ++i) {
    const char* start = buffer.data() + i * width;
    texts[i].assign(start, std::find(start, start + width, '\0'));
  }
  return texts;
}

}  // namespace ejecta::hdf5
