#include "sim/io/snapshot.hpp"

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sim/io/atomic_file.hpp"

namespace ejecta {

namespace {

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
std::string hdf5Detail() {
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

[[noreturn]] void failHdf5(const std::string& what) {
  throw std::runtime_error(what + hdf5Detail());
}

Hid checked(hid_t id, Hid::Closer closer, const std::string& what) {
  if (id < 0) failHdf5(what);
  return Hid(id, closer);
}

void check(herr_t rc, const std::string& what) {
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

// Fixed-length UTF-8 string type holding `text` plus its terminating NUL.
Hid stringType(const std::string& text) {
  Hid type = checked(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create string type");
  check(H5Tset_size(type.get(), text.size() + 1), "cannot size string type");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), "cannot set string padding");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "cannot set string encoding");
  return type;
}

Hid scalarSpace() { return checked(H5Screate(H5S_SCALAR), H5Sclose, "cannot create dataspace"); }

// ---------------------------------------------------------------------------------------------
// Writing
// ---------------------------------------------------------------------------------------------

void writeStringAttribute(hid_t obj, const char* name, const std::string& value) {
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

// Creates dataset spec.name in `group` with shape (n) or (n, 3), writes `data` (n or 3n values,
// row-major) and tags it with `units` and `description`.
template <typename T>
void writeDataset(hid_t group, const DatasetSpec& spec, std::size_t n, bool vector3,
                  const T* data, hsize_t columns = 3) {
  const hsize_t dims[2] = {static_cast<hsize_t>(n), columns};
  const Hid space = checked(H5Screate_simple(vector3 ? 2 : 1, dims, nullptr), H5Sclose,
                            "cannot create dataspace");
  const std::string label = std::string("dataset '") + spec.name + "'";
  const Hid dset = checked(H5Dcreate2(group, spec.name, H5Type<T>::file(), space.get(),
                                      H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                           H5Dclose, "cannot create " + label);
  // An empty vector's data() may be null, which H5Dwrite rejects; nothing to write anyway.
  if (n > 0)
    check(H5Dwrite(dset.get(), H5Type<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          "cannot write " + label);
  writeStringAttribute(dset.get(), "units", spec.units);
  writeStringAttribute(dset.get(), "description", spec.description);
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
                      std::size_t n) {
  requireSize(values, n, spec.name);
  writeDataset(group, spec, n, false, values.data());
}

// Interleaves the first n entries of the three components into an (n, 3) dataset; components
// at index >= keepComponents are written as zero.
void writeVectorField(hid_t group, const DatasetSpec& spec, const Vec3Array& values,
                      std::size_t n, int keepComponents = 3) {
  for (const auto& component : values) requireSize(component, n, spec.name);
  std::vector<double> rows(3 * n, 0.0);
  for (int d = 0; d < keepComponents; ++d)
    for (std::size_t i = 0; i < n; ++i) rows[3 * i + d] = values[d][i];
  writeDataset(group, spec, n, true, rows.data());
}

// The first `columns` stress components as an (n, columns) dataset.
void writeStressField(hid_t group, const DatasetSpec& spec,
                      const std::array<std::vector<double>, 6>& values, std::size_t n,
                      int columns) {
  std::vector<double> rows(static_cast<std::size_t>(columns) * n);
  for (int c = 0; c < columns; ++c) {
    requireSize(values[c], n, spec.name);
    for (std::size_t i = 0; i < n; ++i) rows[columns * i + c] = values[c][i];
  }
  writeDataset(group, spec, n, true, rows.data(), static_cast<hsize_t>(columns));
}

Hid createGroup(hid_t file, const char* name) {
  return checked(H5Gcreate2(file, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                 std::string("cannot create group '") + name + "'");
}

void writeRootAttributes(hid_t file, const SnapshotInfo& info) {
  writeScalarAttribute(file, "time", info.time);
  writeScalarAttribute<int>(file, "dimension", spatialDimension(info.geometry));
  writeStringAttribute(file, "geometry", std::string(geometryLayoutName(info.geometry)));
  writeScalarAttribute<std::int64_t>(file, "step", info.step);
  writeStringAttribute(file, "scene", info.scene);
  writeStringAttribute(file, "ejecta_version", std::string(kEjectaVersion));
}

void writeParticles(hid_t file, const ParticleSet& p, Geometry geometry) {
  const std::size_t n = p.numReal;
  const Hid group = createGroup(file, "/particles");
  const hid_t g = group.get();
  writeVectorField(g, {"position", "m", "particle position: 1D (x,0,0), 2D (x,y,0), RZ (r,z,0)"},
                   p.x, n, spatialDimension(geometry));
  writeVectorField(g, {"velocity", "m/s", "particle velocity; RZ: (v_r, v_z, v_phi)"}, p.v, n);
  writeScalarField(g, {"density", "kg/m^3", "mass density"}, p.rho, n);
  writeScalarField(g, {"pressure", "Pa", "pressure from the equation of state"}, p.P, n);
  writeScalarField(g, {"internal_energy", "J/kg", "specific internal energy"}, p.u, n);
  writeScalarField(g, {"smoothing_length", "m", "SPH smoothing length h"}, p.h, n);
  writeScalarField(g, {"mass", "kg", "particle mass; RZ: whole ring; 2D planar: per metre of depth"},
                   p.mass, n);
  writeScalarField(g, {"material", "1", "index into the run's material table"}, p.material, n);
  writeScalarField(g, {"id", "1", "stable particle identity"}, p.id, n);
  writeScalarField(g, {"sound_speed", "m/s",
                       "signal speed: the equation of state's sound speed; for materials with "
                       "strength the longitudinal speed sqrt(c^2 + 4G/(3 rho))"}, p.cs, n);
  writeScalarField(g, {"temperature", "K", "temperature T0 + u / c_v of the material"},
                   p.temperature, n);
  if (p.stressComponents() > 0) {
    writeStressField(g, {"stress", "Pa",
                         p.stressComponents() == 6
                             ? "deviatoric stress: xx, yy, zz, xy, xz, yz"
                             : "deviatoric stress: xx, yy, zz, xy (RZ: rr, zz, theta-theta, rz)"},
                     p.stress, n, p.stressComponents());
    writeScalarField(g, {"plastic_strain", "1", "equivalent plastic strain"}, p.plasticStrain, n);
  }
  if (p.hasFracture()) {
    std::vector<double> damage(n);
    for (std::size_t i = 0; i < n; ++i) damage[i] = p.damage(i);
    writeScalarField(g, {"damage", "1", "damage D in [0, 1] (1: no tension, no shear)"}, damage, n);
  }
  if (p.hasBurn())
    writeScalarField(g, {"burn_fraction", "1",
                         "programmed-burn fraction F in [0, 1] (the factor on the JWL pressure)"},
                     p.burnFraction, n);
  if (p.hasViscositySwitch())
    writeScalarField(g, {"viscosity_alpha", "1",
                         "artificial-viscosity coefficient alpha of the Morris-Monaghan switch"},
                     p.alpha, n);
}

void writeStringDataset(hid_t group, const char* name, const std::string& text,
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

void writeRestart(hid_t file, const ParticleSet& p, const SnapshotInfo& info) {
  const std::size_t n = p.numReal;
  const Hid group = createGroup(file, "/restart");
  const hid_t g = group.get();
  writeVectorField(g, {"acceleration", "m/s^2", "acceleration of the last force evaluation"},
                   p.a, n);
  writeScalarField(g, {"du_dt", "J/kg/s", "rate of change of specific internal energy"},
                   p.du_dt, n);
  writeScalarField(g, {"drho_dt", "kg/m^3/s", "rate of change of density (continuity)"},
                   p.drho_dt, n);
  writeScalarField(g, {"dh_dt", "m/s", "rate of change of smoothing length"}, p.dh_dt, n);
  if (p.stressComponents() > 0) {
    writeStressField(g, {"dstress_dt", "Pa/s", "rate of the deviatoric stress"}, p.dstress_dt, n,
                     p.stressComponents());
    writeScalarField(g, {"total_strain", "1", "equivalent total strain"}, p.totalStrain, n);
    writeScalarField(g, {"strain_rate", "1/s", "equivalent strain rate"}, p.strainRate, n);
  }
  if (p.hasFracture()) {
    writeScalarField(g, {"crack", "1", "crack fraction D^(1/3)"}, p.crack, n);
    writeScalarField(g, {"dcrack_dt", "1/s", "rate of the crack fraction"}, p.dcrack_dt, n);
  }
  if (p.hasBurn())
    writeScalarField(g, {"lighting_time", "s",
                         "programmed-burn lighting time (-inf: not an explosive)"},
                     p.lightingTime, n);
  if (p.hasViscositySwitch())
    writeScalarField(g, {"dalpha_dt", "1/s", "rate of the viscosity switch's alpha"},
                     p.dalpha_dt, n);
  writeStringDataset(g, "scene_source", info.sceneSource, "text of the scene file of the run");
  writeScalarAttribute(g, "dt_next", info.dtNext);
  writeScalarAttribute<std::int64_t>(g, "snapshot_index", info.snapshotIndex);
  writeScalarAttribute(g, "next_output_time", info.nextOutputTime);
  writeScalarAttribute(g, "initial_energy", info.initialEnergy);
  writeNumericAttribute(g, "initial_momentum", info.initialMomentum.data(), 3);
  if (!info.initialMaterialKinetic.empty()) {
    writeNumericAttribute(g, "initial_material_kinetic", info.initialMaterialKinetic.data(),
                          info.initialMaterialKinetic.size());
    writeNumericAttribute(g, "initial_material_internal", info.initialMaterialInternal.data(),
                          info.initialMaterialInternal.size());
  }
  writeScalarAttribute(g, "wall_seconds", info.wallSeconds);
}

void writeSnapshotFile(const std::filesystem::path& tempPath, const ParticleSet& p,
                       const SnapshotInfo& info) {
  const Hid fapl = checked(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create property list");
  // STRONG: closing the file closes everything in it, so it is complete before the rename.
  check(H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG), "cannot set file close degree");
  Hid file = checked(H5Fcreate(tempPath.c_str(), H5F_ACC_EXCL, H5P_DEFAULT, fapl.get()),
                     H5Fclose, "cannot create temporary file '" + tempPath.string() + "'");
  writeRootAttributes(file.get(), info);
  writeParticles(file.get(), p, info.geometry);
  writeRestart(file.get(), p, info);
  check(file.close(), "cannot close temporary file '" + tempPath.string() + "'");
}

// ---------------------------------------------------------------------------------------------
// Reading
// ---------------------------------------------------------------------------------------------

// True if every component of the absolute path `/a/b/c` exists (H5Lexists needs the parents).
bool linkExists(hid_t file, const std::string& path) {
  for (std::size_t slash = path.find('/', 1);; slash = path.find('/', slash + 1)) {
    const std::string prefix = path.substr(0, slash);
    const htri_t exists = H5Lexists(file, prefix.c_str(), H5P_DEFAULT);
    if (exists < 0) failHdf5("cannot look up '" + prefix + "'");
    if (exists == 0) return false;
    if (slash == std::string::npos) return true;
  }
}

Hid openDataset(hid_t file, const std::string& path) {
  if (!linkExists(file, path)) throw std::runtime_error("missing dataset '" + path + "'");
  return checked(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose,
                 "cannot open dataset '" + path + "'");
}

Hid openGroup(hid_t file, const std::string& path) {
  if (!linkExists(file, path)) throw std::runtime_error("missing group '" + path + "'");
  return checked(H5Gopen2(file, path.c_str(), H5P_DEFAULT), H5Gclose,
                 "cannot open group '" + path + "'");
}

std::vector<hsize_t> datasetShape(hid_t dset, const std::string& path) {
  const Hid space = checked(H5Dget_space(dset), H5Sclose, "cannot get dataspace of '" + path + "'");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) failHdf5("cannot get rank of '" + path + "'");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
    failHdf5("cannot get shape of '" + path + "'");
  return dims;
}

std::string shapeText(const std::vector<hsize_t>& dims) {
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

// Reads dataset `path` that must have shape (n) or, for vector3, (n, 3).
template <typename T>
std::vector<T> readDataset(hid_t file, const std::string& path, std::size_t n, bool vector3,
                           hsize_t columns = 3) {
  const Hid dset = openDataset(file, path);
  const std::vector<hsize_t> dims = datasetShape(dset.get(), path);
  const std::vector<hsize_t> expected =
      vector3 ? std::vector<hsize_t>{n, columns} : std::vector<hsize_t>{n};
  if (dims != expected)
    throw std::runtime_error("dataset '" + path + "' has shape " + shapeText(dims) +
                             ", expected " + shapeText(expected));
  const Hid type = checked(H5Dget_type(dset.get()), H5Tclose, "cannot get type of '" + path + "'");
  requireClass<T>(type.get(), "dataset '" + path + "'");
  std::vector<T> values(vector3 ? columns * n : n);
  if (!values.empty())
    check(H5Dread(dset.get(), H5Type<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
          "cannot read dataset '" + path + "'");
  return values;
}

Vec3Array readVectorField(hid_t file, const std::string& path, std::size_t n) {
  const std::vector<double> rows = readDataset<double>(file, path, n, true);
  Vec3Array out;
  for (int d = 0; d < 3; ++d) {
    out[d].resize(n);
    for (std::size_t i = 0; i < n; ++i) out[d][i] = rows[3 * i + d];
  }
  return out;
}

std::size_t particleCount(hid_t file) {
  const std::string path = "/particles/position";
  const Hid dset = openDataset(file, path);
  const std::vector<hsize_t> dims = datasetShape(dset.get(), path);
  if (dims.size() != 2 || dims[1] != 3)
    throw std::runtime_error("dataset '" + path + "' has shape " + shapeText(dims) +
                             ", expected (N, 3)");
  return static_cast<std::size_t>(dims[0]);
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

Hid openAttribute(hid_t obj, const char* name, const std::string& owner) {
  const std::string label = std::string("attribute '") + name + "' of " + owner;
  const htri_t exists = H5Aexists(obj, name);
  if (exists < 0) failHdf5("cannot look up " + label);
  if (exists == 0) throw std::runtime_error("missing " + label);
  return checked(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose, "cannot open " + label);
}

std::string readStringAttribute(hid_t obj, const char* name, const std::string& owner) {
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
std::vector<double> readOptionalArrayAttribute(hid_t obj, const char* name, const std::string& owner) {
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

std::string readStringDataset(hid_t file, const std::string& path) {
  const Hid dset = openDataset(file, path);
  const Hid type = checked(H5Dget_type(dset.get()), H5Tclose, "cannot get type of '" + path + "'");
  return readString(type.get(), "dataset '" + path + "'", [&dset](hid_t mem, void* buf) {
    return H5Dread(dset.get(), mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
  });
}

void readRootAttributes(hid_t file, SnapshotInfo& info) {
  const std::string owner = "'/'";
  info.time = readScalarAttribute<double>(file, "time", owner);
  info.step = static_cast<long>(readScalarAttribute<std::int64_t>(file, "step", owner));
  info.scene = readStringAttribute(file, "scene", owner);
  const std::string geometry = readStringAttribute(file, "geometry", owner);
  if (!parseGeometry(geometry, info.geometry))
    throw std::runtime_error("attribute 'geometry' of '/' has unknown value '" + geometry + "'");
  const int dimension = readScalarAttribute<int>(file, "dimension", owner);
  if (dimension != spatialDimension(info.geometry))
    throw std::runtime_error("attribute 'dimension' of '/' is " + std::to_string(dimension) +
                             " but geometry '" + geometry + "' has dimension " +
                             std::to_string(spatialDimension(info.geometry)));
}

void readRestartAttributes(hid_t file, SnapshotInfo& info) {
  const Hid group = openGroup(file, "/restart");
  const hid_t g = group.get();
  const std::string owner = "'/restart'";
  info.dtNext = readScalarAttribute<double>(g, "dt_next", owner);
  info.snapshotIndex =
      static_cast<long>(readScalarAttribute<std::int64_t>(g, "snapshot_index", owner));
  info.nextOutputTime = readScalarAttribute<double>(g, "next_output_time", owner);
  info.initialEnergy = readScalarAttribute<double>(g, "initial_energy", owner);
  const std::vector<double> momentum = readNumericAttribute<double>(g, "initial_momentum", owner, 3);
  for (int d = 0; d < 3; ++d) info.initialMomentum[d] = momentum[d];
  info.wallSeconds = readScalarAttribute<double>(g, "wall_seconds", owner);
  info.initialMaterialKinetic = readOptionalArrayAttribute(g, "initial_material_kinetic", owner);
  info.initialMaterialInternal = readOptionalArrayAttribute(g, "initial_material_internal", owner);
  info.sceneSource = readStringDataset(file, "/restart/scene_source");
}

ParticleSet readParticles(hid_t file) {
  const std::size_t n = particleCount(file);
  ParticleSet p;
  p.resize(n);  // zeroes everything, omega = 1
  p.numReal = n;
  p.x = readVectorField(file, "/particles/position", n);
  p.v = readVectorField(file, "/particles/velocity", n);
  p.rho = readDataset<double>(file, "/particles/density", n, false);
  p.P = readDataset<double>(file, "/particles/pressure", n, false);
  p.u = readDataset<double>(file, "/particles/internal_energy", n, false);
  p.h = readDataset<double>(file, "/particles/smoothing_length", n, false);
  p.mass = readDataset<double>(file, "/particles/mass", n, false);
  p.material = readDataset<int>(file, "/particles/material", n, false);
  p.id = readDataset<std::int64_t>(file, "/particles/id", n, false);
  p.cs = readDataset<double>(file, "/particles/sound_speed", n, false);
  p.a = readVectorField(file, "/restart/acceleration", n);
  p.du_dt = readDataset<double>(file, "/restart/du_dt", n, false);
  p.drho_dt = readDataset<double>(file, "/restart/drho_dt", n, false);
  p.dh_dt = readDataset<double>(file, "/restart/dh_dt", n, false);
  if (linkExists(file, "/particles/temperature"))
    p.temperature = readDataset<double>(file, "/particles/temperature", n, false);
  if (linkExists(file, "/particles/stress")) {
    const Hid dset = openDataset(file, "/particles/stress");
    const std::vector<hsize_t> dims = datasetShape(dset.get(), "/particles/stress");
    const int columns = dims.size() == 2 ? static_cast<int>(dims[1]) : 0;
    if (columns != 4 && columns != 6)
      throw std::runtime_error("dataset '/particles/stress' has shape " + shapeText(dims) +
                               ", expected (N, 4) or (N, 6)");
    p.enableStrength(columns);
    const std::vector<double> stress = readDataset<double>(file, "/particles/stress", n, true, columns);
    const std::vector<double> rate = readDataset<double>(file, "/restart/dstress_dt", n, true, columns);
    for (int c = 0; c < columns; ++c)
      for (std::size_t i = 0; i < n; ++i) {
        p.stress[c][i] = stress[columns * i + c];
        p.dstress_dt[c][i] = rate[columns * i + c];
      }
    p.plasticStrain = readDataset<double>(file, "/particles/plastic_strain", n, false);
    p.totalStrain = readDataset<double>(file, "/restart/total_strain", n, false);
    p.strainRate = readDataset<double>(file, "/restart/strain_rate", n, false);
  }
  if (linkExists(file, "/restart/crack")) {
    p.enableFracture();
    p.crack = readDataset<double>(file, "/restart/crack", n, false);
    p.dcrack_dt = readDataset<double>(file, "/restart/dcrack_dt", n, false);
  }
  if (linkExists(file, "/restart/lighting_time")) {
    p.enableBurn();
    p.lightingTime = readDataset<double>(file, "/restart/lighting_time", n, false);
    p.burnFraction = readDataset<double>(file, "/particles/burn_fraction", n, false);
  }
  if (linkExists(file, "/particles/viscosity_alpha")) {
    p.enableViscositySwitch(0.0);
    p.alpha = readDataset<double>(file, "/particles/viscosity_alpha", n, false);
    p.dalpha_dt = readDataset<double>(file, "/restart/dalpha_dt", n, false);
  }
  return p;
}

}  // namespace

void writeSnapshot(const std::string& path, const ParticleSet& p, const SnapshotInfo& info) {
  try {
    const QuietHdf5Errors quiet;
    AtomicFileTarget target(path);
    writeSnapshotFile(target.tempPath(), p, info);
    target.commit();
  } catch (const std::exception& e) {
    throw std::runtime_error("snapshot '" + path + "': " + e.what());
  }
}

ParticleSet readSnapshot(const std::string& path, SnapshotInfo& info) {
  try {
    // Checked first so the common mistake gets a plain message rather than HDF5's.
    if (!std::filesystem::exists(path)) throw std::runtime_error("no such file");
    const QuietHdf5Errors quiet;
    const Hid file = checked(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                             "cannot open as HDF5");
    SnapshotInfo read;
    readRootAttributes(file.get(), read);
    readRestartAttributes(file.get(), read);
    ParticleSet p = readParticles(file.get());
    info = std::move(read);
    return p;
  } catch (const std::exception& e) {
    throw std::runtime_error("snapshot '" + path + "': " + e.what());
  }
}

}  // namespace ejecta
