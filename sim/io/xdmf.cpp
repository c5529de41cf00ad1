#include "sim/io/xdmf.hpp"

#include <charconv>
#include <sstream>
#include <string_view>

#include "core/atomic_file.hpp"
#include "core/join.hpp"

namespace ejecta {

namespace {

std::string xmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// Shortest text that reads back as the same double, so times match the snapshots exactly.
std::string exactNumber(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string numberType(const XdmfAttribute& spec) {
  return std::string("NumberType=\"") + (spec.integer ? "Int" : "Float") + "\" Precision=\"" +
         std::to_string(spec.precision) + "\"";
}

void writeDataItem(std::ostream& out, const std::string& dims, const XdmfAttribute& spec,
                   const std::string& file, const char* indent) {
  out << indent << "<DataItem Dimensions=\"" << dims << "\" " << numberType(spec)
      << " Format=\"HDF\">" << file << ":/particles/" << spec.name << "</DataItem>\n";
}

void writeUnits(std::ostream& out, const XdmfAttribute& spec) {
  out << "        <Information Name=\"units\" Value=\"" << xmlEscape(spec.units) << "\"/>\n";
}

void writeAttribute(std::ostream& out, const XdmfEntry& entry, const XdmfAttribute& spec,
                    const std::string& file) {
  const std::string n = std::to_string(entry.numParticles);
  const bool vector = spec.components == 3 && !spec.tensor;
  // A tensor's order (xx, yy, zz, xy, ...; RZ rr, zz, theta-theta, rz) is not XDMF's Tensor6
  // order, and the 4-component 2D/RZ tensor has no XDMF type: a Matrix, its columns named.
  // (ParaView's Xdmf3 readers skip HyperSlab items, so columns cannot be split out here.)
  const char* type = spec.components == 1 ? "Scalar" : vector ? "Vector" : "Matrix";
  out << "      <Attribute Name=\"" << xmlEscape(spec.name) << "\" AttributeType=\"" << type
      << "\" Center=\"Node\">\n";
  writeUnits(out, spec);
  if (spec.components > 1 && !vector) {
    const std::string names = joinList(xdmfComponentNames(spec, entry.geometry));
    out << "        <Information Name=\"components\" Value=\"" << xmlEscape(names) << "\"/>\n";
  }
  writeDataItem(out, spec.components == 1 ? n : n + " " + std::to_string(spec.components), spec,
                file, "        ");
  out << "      </Attribute>\n";
}

std::string materialList(const std::vector<std::string>& names) {
  std::string list;
  for (std::size_t m = 0; m < names.size(); ++m)
    list += (m ? ", " : "") + std::to_string(m) + ": " + names[m];
  return list;
}

void writeGrid(std::ostream& out, const XdmfEntry& entry, std::size_t index) {
  const std::string n = std::to_string(entry.numParticles);
  const std::string file = xmlEscape(entry.h5File);
  out << "    <Grid Name=\"snapshot" << index << "\" GridType=\"Uniform\">\n"
      << "      <Time Value=\"" << exactNumber(entry.time) << "\"/>\n"
      << "      <Information Name=\"geometry\" Value=\""
      << geometryLayoutName(entry.geometry) << "\"/>\n";
  if (!entry.materials.empty())
    out << "      <Information Name=\"materials\" Value=\"" << xmlEscape(materialList(entry.materials))
        << "\"/>\n";
  const int precision = xdmfVertexPrecision(entry.numParticles);
  out << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
      << "\" NodesPerElement=\"1\"";
  if (entry.vertices)
    out << ">\n        <DataItem Dimensions=\"" << n << "\" NumberType=\"Int\" Precision=\"" << precision
        << "\" Format=\"HDF\">" << file << ":/xdmf/vertices</DataItem>\n"
        << "      </Topology>\n";
  else
    out << "/>\n";  // an older snapshot: the legacy reader still draws it
  out << "      <Geometry GeometryType=\"XYZ\">\n";
  writeDataItem(out, n + " 3", {"position", "m", 3, false, false, 8}, file, "        ");
  out << "      </Geometry>\n";
  for (const XdmfAttribute& spec : entry.attributes) writeAttribute(out, entry, spec, file);
  out << "    </Grid>\n";
}

}  // namespace

std::vector<XdmfAttribute> xdmfAttributes(const ParticleSet& p) {
  std::vector<XdmfAttribute> scalars, others;
  for (const Field& f : p.fields()) {
    if (f.spec.output != FieldOutput::Particles || f.spec.name == "position") continue;
    const bool integer = f.spec.type != FieldType::Float64;
    const int precision = f.spec.type == FieldType::Int32 ? 4 : 8;
    const bool tensor = f.spec.parity == MirrorParity::SymmetricTensor;
    (f.spec.components == 1 ? scalars : others)
        .push_back({f.spec.name, f.spec.units, f.spec.components, tensor, integer, precision});
  }
  scalars.insert(scalars.end(), others.begin(), others.end());
  return scalars;
}

std::vector<std::string> xdmfComponentNames(const XdmfAttribute& attribute, Geometry geometry) {
  const bool rz = geometry == Geometry::Axisymmetric;
  if (attribute.tensor && attribute.components == 4)
    return rz ? std::vector<std::string>{"rr", "zz", "tt", "rz"}
              : std::vector<std::string>{"xx", "yy", "zz", "xy"};
  if (attribute.tensor && attribute.components == 6) return {"xx", "yy", "zz", "xy", "xz", "yz"};
  if (attribute.components == 3) return rz ? std::vector<std::string>{"r", "z", "phi"}
                                           : std::vector<std::string>{"x", "y", "z"};
  std::vector<std::string> names;
  for (int c = 0; c < attribute.components; ++c) names.push_back(std::to_string(c));
  return names;
}

void writeXdmfSeries(const std::string& xdmfPath, const std::vector<XdmfEntry>& entries) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
      << "  <Domain>\n"
      << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t i = 0; i < entries.size(); ++i) writeGrid(out, entries[i], i);
  out << "  </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
  writeFileAtomically(xdmfPath, out.str());
}

}  // namespace ejecta
