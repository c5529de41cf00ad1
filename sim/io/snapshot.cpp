#include "sim/io/snapshot.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/atomic_file.hpp"
#include "sim/io/hdf5_io.hpp"
#include "sim/io/snapshot_checks.hpp"
#include "sim/io/snapshot_rows.hpp"
#include "sim/state/builtin_fields.hpp"
#include "sim/io/xdmf.hpp"

namespace ejecta {

namespace {

using namespace hdf5;

// Writes field f of the real particles as dataset f.spec.name in `group`: shape (n) for a scalar,
// (n, components) otherwise, row-major; components beyond the geometry's dimension as zero when
// the field says so (positions).
void writeField(hid_t group, const ParticleSet& p, const Field& f, Geometry geometry,
                const RowSlot& slot) {
  const std::size_t n = p.numReal;
  const DatasetSpec spec{f.spec.name.c_str(), f.spec.units.c_str(), f.spec.description.c_str()};
  switch (f.storage.kind) {
    case FieldStorage::Kind::Int32: writeScalarField(group, spec, p.*f.storage.int32, n, slot); return;
    case FieldStorage::Kind::Int64: writeScalarField(group, spec, p.*f.storage.int64, n, slot); return;
    case FieldStorage::Kind::Derived: {
      std::vector<double> values(n);
      for (std::size_t i = 0; i < n; ++i) values[i] = f.spec.derive(p, i);
      writeScalarField(group, spec, values, n, slot);
      return;
    }
    default: break;
  }
  const int columns = f.spec.components;
  if (columns == 1) {
    writeScalarField(group, spec, p.column(f, 0), n, slot);
    return;
  }
  const int keep = f.spec.writeDimensionOnly ? std::min(columns, spatialDimension(geometry)) : columns;
  std::vector<double> rows(static_cast<std::size_t>(columns) * n, 0.0);
  for (int c = 0; c < columns; ++c) {
    const std::vector<double>& values = p.column(f, c);
    requireSize(values, n, spec.name);
    if (c < keep)
      for (std::size_t i = 0; i < n; ++i) rows[columns * i + c] = values[i];
  }
  writeRows(group, spec, slot, n, true, rows.data(), static_cast<hsize_t>(columns));
}

// Every field of `p` whose declaration stores it in `output`, in registry order.
void writeFields(hid_t group, const ParticleSet& p, FieldOutput output, Geometry geometry,
                 const RowSlot& slot) {
  for (const Field& f : p.fields())
    if (f.spec.output == output) writeField(group, p, f, geometry, slot);
}


// FNV-1a, 64 bit (Fowler, Noll and Vo; http://www.isthe.com/chongo/tech/comp/fnv/).
std::uint64_t textChecksum(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
  return hash;
}

void writeRootAttributes(hid_t file, const SnapshotInfo& info) {
  writeScalarAttribute(file, "time", info.time);
  writeScalarAttribute<int>(file, "dimension", spatialDimension(info.geometry));
  writeStringAttribute(file, "geometry", std::string(geometryLayoutName(info.geometry)));
  writeScalarAttribute<std::int64_t>(file, "step", info.step);
  writeStringAttribute(file, "scene", info.scene);
  writeStringAttribute(file, "ejecta_version", std::string(kEjectaVersion));
}

void writeParticles(hid_t file, const ParticleSet& p, Geometry geometry, const RowSlot& slot) {
  const Hid group = createGroup(file, "/particles");
  writeFields(group.get(), p, FieldOutput::Particles, geometry, slot);
}


void writeRestart(hid_t file, const ParticleSet& p, const SnapshotInfo& info, const RowSlot& slot) {
  const Hid group = createGroup(file, "/restart");
  const hid_t g = group.get();
  writeFields(g, p, FieldOutput::Restart, info.geometry, slot);
  writeStringDataset(g, "scene_source", info.sceneSource, "text of the scene file of the run");
  {
    // A string dataset cannot carry HDF5's Fletcher-32 filter (it is not chunked): its own sum.
    const Hid dset = openDataset(g, "scene_source");
    writeScalarAttribute<std::uint64_t>(dset.get(), "checksum_fnv1a", textChecksum(info.sceneSource));
  }
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

// /materials: one row per material id, as parallel string arrays (h5py and ParaView read them
// without a compound type).
void writeMaterials(hid_t file, const SnapshotInfo& info) {
  if (info.materials.empty()) return;
  const Hid group = createGroup(file, "/materials");
  std::vector<int> ids;
  std::vector<std::string> names, eos, strength, fracture;
  for (std::size_t m = 0; m < info.materials.size(); ++m) {
    ids.push_back(static_cast<int>(m));
    names.push_back(info.materials[m].name);
    eos.push_back(info.materials[m].eos);
    strength.push_back(info.materials[m].strength);
    fracture.push_back(info.materials[m].fracture);
  }
  writeScalarField(group.get(), {"id", "1", "material id: the value of /particles/material"}, ids,
                   ids.size(), RowSlot{0, ids.size(), true});
  writeStringArray(group.get(), "name", names, "material name, as the scene gives it");
  writeStringArray(group.get(), "eos", eos, "equation of state (library entry)");
  writeStringArray(group.get(), "strength", strength, "strength model, or none (a fluid)");
  writeStringArray(group.get(), "fracture", fracture, "fracture model, or none");
}

// /xdmf/vertices = 0, 1, ..., N-1: the Polyvertex connectivity of the XDMF series (ParaView's
// Xdmf3 readers make no cells without it, and a Points view then draws nothing). Written whole
// when the file is created, so a distributed snapshot's ranks need not write it.
void writeVertexIndex(hid_t file, std::size_t totalRows) {
  const Hid group = createGroup(file, "/xdmf");
  const DatasetSpec spec{"vertices", "1", "0 .. N-1: the Polyvertex connectivity snapshots.xdmf points to"};
  const RowSlot slot{0, totalRows, true};
  if (xdmfVertexPrecision(totalRows) == 4) {
    std::vector<int> index(totalRows);
    for (std::size_t i = 0; i < totalRows; ++i) index[i] = static_cast<int>(i);
    writeScalarField(group.get(), spec, index, totalRows, slot);
  } else {
    std::vector<std::int64_t> index(totalRows);
    for (std::size_t i = 0; i < totalRows; ++i) index[i] = static_cast<std::int64_t>(i);
    writeScalarField(group.get(), spec, index, totalRows, slot);
  }
}

// At most this many materials: far above any scene, low enough that a corrupt extent cannot
// make the reader allocate much.
constexpr std::size_t kMostMaterials = 1u << 12;

void readMaterials(hid_t file, SnapshotInfo& info) {
  info.materials.clear();
  if (!linkExists(file, "/materials")) return;
  const std::vector<std::string> names = readStringArray(file, "/materials/name", kMostMaterials);
  const std::vector<std::string> eos = readStringArray(file, "/materials/eos", kMostMaterials);
  const std::vector<std::string> strength = readStringArray(file, "/materials/strength", kMostMaterials);
  const std::vector<std::string> fracture = readStringArray(file, "/materials/fracture", kMostMaterials);
  if (eos.size() != names.size() || strength.size() != names.size() || fracture.size() != names.size())
    throw std::runtime_error("group '/materials' has arrays of different lengths (" +
                             std::to_string(names.size()) + " names, " + std::to_string(eos.size()) +
                             " eos, " + std::to_string(strength.size()) + " strength, " +
                             std::to_string(fracture.size()) + " fracture)");
  for (std::size_t m = 0; m < names.size(); ++m)
    info.materials.push_back({names[m], eos[m], strength[m], fracture[m]});
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
  const Hid source = openDataset(file, "/restart/scene_source");
  if (H5Aexists(source.get(), "checksum_fnv1a") > 0 &&
      readScalarAttribute<std::uint64_t>(source.get(), "checksum_fnv1a", "'/restart/scene_source'") !=
          textChecksum(info.sceneSource))
    throw std::runtime_error("dataset '/restart/scene_source' does not match its checksum (the "
                             "file is corrupt)");
}

std::string groupPath(FieldOutput output) {
  return output == FieldOutput::Particles ? "/particles" : "/restart";
}

// Reads field f (a stored one) from `path`, shape (n) or (n, components): rows `range` of it.
void readField(hid_t file, const std::string& path, ParticleSet& p, const Field& f, std::size_t n,
               RowRange range) {
  switch (f.storage.kind) {
    case FieldStorage::Kind::Int32: p.*f.storage.int32 = readDataset<int>(file, path, n, false, 3, range); return;
    case FieldStorage::Kind::Int64:
      p.*f.storage.int64 = readDataset<std::int64_t>(file, path, n, false, 3, range);
      return;
    default: break;
  }
  const int columns = f.spec.components;
  if (columns == 1) {
    p.column(f, 0) = readDataset<double>(file, path, n, false, 3, range);
    return;
  }
  const std::vector<double> rows =
      readDataset<double>(file, path, n, true, static_cast<hsize_t>(columns), range);
  for (int c = 0; c < columns; ++c) {
    std::vector<double>& column = p.column(f, c);
    column.resize(range.count);
    for (std::size_t i = 0; i < range.count; ++i) column[i] = rows[columns * i + c];
  }
}

// The names of the datasets in group `path`, in name order.
std::vector<std::string> datasetNames(hid_t file, const std::string& path) {
  std::vector<std::string> names;
  const Hid group = openGroup(file, path);
  auto collect = [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
    static_cast<std::vector<std::string>*>(out)->push_back(name);
    return 0;
  };
  hsize_t index = 0;
  check(H5Literate(group.get(), H5_INDEX_NAME, H5_ITER_INC, &index, collect, &names),
        "cannot list '" + path + "'");
  return names;
}

// The fields of packages (ones no built-in group declares): every floating-point dataset of
// shape (n) or (n, k) in /particles or /restart that is not a carried field, declared with its
// stored units and description so the package that owns it finds its values when it declares
// it again (ParticleSet::declare keeps them).
void readPackageFields(hid_t file, ParticleSet& p, std::size_t n, RowRange range) {
  std::vector<std::string> builtin;
  for (const Field& f : allBuiltinFields()) builtin.push_back(f.spec.name);
  for (const FieldOutput output : {FieldOutput::Particles, FieldOutput::Restart}) {
    const std::string group = groupPath(output);
    for (const std::string& name : datasetNames(file, group)) {
      if (p.field(name) || std::find(builtin.begin(), builtin.end(), name) != builtin.end()) continue;
      const std::string path = group + "/" + name;
      const Hid dset = openDataset(file, path);
      const Hid type = checked(H5Dget_type(dset.get()), H5Tclose, "cannot get type of '" + path + "'");
      const std::vector<hsize_t> dims = datasetShape(dset.get(), path);
      if (H5Tget_class(type.get()) != H5T_FLOAT || dims.empty() || dims.size() > 2 || dims[0] != n) continue;
      FieldSpec spec = scalarField(name, readStringAttribute(dset.get(), "units", "'" + path + "'"),
                                   readStringAttribute(dset.get(), "description", "'" + path + "'"),
                                   output);
      spec.components = dims.size() == 2 ? static_cast<int>(dims[1]) : 1;
      p.declare(spec);
      readField(file, path, p, *p.field(name), n, range);
    }
  }
}

// Slice `part` of `parts` equal slices of the stored rows.
ParticleSet readParticles(hid_t file, int part, int parts, SnapshotValues values) {
  const std::size_t n = particleCount(file);
  const std::size_t k = static_cast<std::size_t>(part), m = static_cast<std::size_t>(parts);
  const std::size_t first = n / m * k + n % m * k / m;
  const RowRange range{first, n / m * (k + 1) + n % m * (k + 1) / m - first};
  ParticleSet p;
  // The optional groups a snapshot carries, each known by one of its datasets.
  if (linkExists(file, "/particles/stress")) {
    const Hid dset = openDataset(file, "/particles/stress");
    const std::vector<hsize_t> dims = datasetShape(dset.get(), "/particles/stress");
    const int columns = dims.size() == 2 ? static_cast<int>(dims[1]) : 0;
    if (columns != 4 && columns != 6)
      throw std::runtime_error("dataset '/particles/stress' has shape " + shapeText(dims) +
                               ", expected (N, 4) or (N, 6)");
    p.enableStrength(columns);
  }
  if (linkExists(file, "/restart/crack")) p.enableFracture();
  if (linkExists(file, "/restart/lighting_time")) p.enableBurn();
  if (linkExists(file, "/particles/viscosity_alpha")) p.enableViscositySwitch(0.0);
  p.resize(range.count);  // zeroes everything, omega = 1
  p.numReal = range.count;
  for (const Field& f : p.fields()) {
    if (f.spec.output == FieldOutput::None || f.spec.derive) continue;
    const std::string path = groupPath(f.spec.output) + "/" + f.spec.name;
    if (!f.spec.required && !linkExists(file, path)) continue;
    readField(file, path, p, f, n, range);
  }
  readPackageFields(file, p, n, range);
  if (values == SnapshotValues::Checked) checkSnapshotParticles(p, range.first);
  return p;
}

}  // namespace

void createSnapshotFile(const std::filesystem::path& tempPath, const ParticleSet& p,
                        const SnapshotInfo& info, std::size_t totalRows) {
  const Hid fapl = checked(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create property list");
  // STRONG: closing the file closes everything in it, so it is complete before the rename.
  check(H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG), "cannot set file close degree");
  // The 1.8 file format: its superblock and object headers (the attributes: time, step, the
  // restart state) carry checksums that HDF5 verifies on open; the arrays carry Fletcher-32
  // (hdf5_io.hpp). Readable by HDF5 1.8 and later, h5py and ParaView.
  check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_V18), "cannot set the file format");
  Hid file = checked(H5Fcreate(tempPath.c_str(), H5F_ACC_EXCL, H5P_DEFAULT, fapl.get()),
                     H5Fclose, "cannot create temporary file '" + tempPath.string() + "'");
  const RowSlot slot{0, totalRows, true};
  writeRootAttributes(file.get(), info);
  writeParticles(file.get(), p, info.geometry, slot);
  writeRestart(file.get(), p, info, slot);
  writeMaterials(file.get(), info);
  writeVertexIndex(file.get(), totalRows);
  check(file.close(), "cannot close temporary file '" + tempPath.string() + "'");
}

void writeSnapshotRows(const std::filesystem::path& tempPath, const ParticleSet& p, Geometry geometry,
                       std::size_t first, std::size_t totalRows) {
  if (p.numReal == 0) return;
  const Hid fapl = checked(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create property list");
  check(H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG), "cannot set file close degree");
  Hid file = checked(H5Fopen(tempPath.c_str(), H5F_ACC_RDWR, fapl.get()), H5Fclose,
                     "cannot open temporary file '" + tempPath.string() + "'");
  const RowSlot slot{first, totalRows, false};
  for (const FieldOutput output : {FieldOutput::Particles, FieldOutput::Restart}) {
    const Hid group = openGroup(file.get(), groupPath(output));
    writeFields(group.get(), p, output, geometry, slot);
  }
  check(file.close(), "cannot close temporary file '" + tempPath.string() + "'");
}

void writeSnapshot(const std::string& path, const ParticleSet& p, const SnapshotInfo& info) {
  try {
    const QuietHdf5Errors quiet;
    AtomicFileTarget target(path);
    createSnapshotFile(target.tempPath(), p, info, p.numReal);
    target.commit();
  } catch (const std::exception& e) {
    throw std::runtime_error("snapshot '" + path + "': " + e.what());
  }
}

ParticleSet readSnapshot(const std::string& path, SnapshotInfo& info) {
  return readSnapshot(path, info, 0, 1);
}

namespace {

// Opens snapshot `path` read-only, reads its info and calls read(file, info); every error names
// the file.
template <typename Read>
auto readSnapshotFile(const std::string& path, Read&& read) {
  try {
    // Checked first so the common mistake gets a plain message rather than HDF5's.
    if (!std::filesystem::exists(path)) throw std::runtime_error("no such file");
    const QuietHdf5Errors quiet;
    const Hid file = checked(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                             "cannot open as HDF5");
    SnapshotInfo info;
    readRootAttributes(file.get(), info);
    readRestartAttributes(file.get(), info);
    readMaterials(file.get(), info);
    checkSnapshotInfo(info);
    return read(file.get(), std::move(info));
  } catch (const std::exception& e) {
    throw std::runtime_error("snapshot '" + path + "': " + e.what());
  }
}

}  // namespace

SnapshotInfo readSnapshotInfo(const std::string& path) {
  return readSnapshotFile(path, [](hid_t, SnapshotInfo info) { return info; });
}

ParticleSet readSnapshot(const std::string& path, SnapshotInfo& info, int part, int parts) {
  return readSnapshotFile(path, [&](hid_t file, SnapshotInfo read) {
    ParticleSet p = readParticles(file, part, parts, SnapshotValues::Checked);
    info = std::move(read);
    return p;
  });
}

ParticleSet readSnapshot(const std::string& path, SnapshotInfo& info, SnapshotValues values) {
  return readSnapshotFile(path, [&](hid_t file, SnapshotInfo read) {
    ParticleSet p = readParticles(file, 0, 1, values);
    info = std::move(read);
    return p;
  });
}

SnapshotLayout readSnapshotLayout(const std::string& path) {
  try {
    const QuietHdf5Errors quiet;
    const Hid file = checked(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open as HDF5");
    SnapshotLayout layout;
    layout.xdmfVertices = linkExists(file.get(), "/xdmf/vertices");
    const Hid group = openGroup(file.get(), "/particles");
    H5G_info_t info;
    check(H5Gget_info(group.get(), &info), "cannot list '/particles'");
    for (hsize_t k = 0; k < info.nlinks; ++k) {
      char name[256] = {};
      if (H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, name, sizeof name, H5P_DEFAULT) > 0)
        layout.particleDatasets.emplace_back(name);
    }
    return layout;
  } catch (const std::exception& e) {
    throw std::runtime_error("snapshot '" + path + "': " + e.what());
  }
}

}  // namespace ejecta
