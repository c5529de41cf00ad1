#include "sim/io/xdmf.hpp"

#include <charconv>
#include <sstream>
#include <string_view>

#include "core/atomic_file.hpp"

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

void writeDataItem(std::ostream& out, const std::string& dims, const XdmfAttribute& spec,
                   const std::string& file) {
  out << "        <DataItem Dimensions=\"" << dims << "\" NumberType=\""
      << (spec.integer ? "Int" : "Float") << "\" Precision=\"" << spec.precision
      << "\" Format=\"HDF\">" << file << ":/particles/" << spec.name << "</DataItem>\n";
}

const char* attributeType(int components) {
  switch (components) {
    case 1: return "Scalar";
    case 3: return "Vector";
    case 6: return "Tensor6";
    default: return "Matrix";
  }
}

void writeGrid(std::ostream& out, const XdmfEntry& entry, std::size_t index) {
  const std::string n = std::to_string(entry.numParticles);
  const std::string file = xmlEscape(entry.h5File);
  out << "    <Grid Name=\"snapshot" << index << "\" GridType=\"Uniform\">\n"
      << "      <Time Value=\"" << exactNumber(entry.time) << "\"/>\n"
      << "      <Information Name=\"geometry\" Value=\""
      << geometryLayoutName(entry.geometry) << "\"/>\n"
      << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
      << "\" NodesPerElement=\"1\"/>\n"
      << "      <Geometry GeometryType=\"XYZ\">\n";
  writeDataItem(out, n + " 3", {"position", 3, false, 8}, file);
  out << "      </Geometry>\n";
  for (const XdmfAttribute& spec : entry.attributes) {
    out << "      <Attribute Name=\"" << spec.name << "\" AttributeType=\""
        << attributeType(spec.components) << "\" Center=\"Node\">\n";
    writeDataItem(out, spec.components == 1 ? n : n + " " + std::to_string(spec.components), spec, file);
    out << "      </Attribute>\n";
  }
  out << "    </Grid>\n";
}

}  // namespace

std::vector<XdmfAttribute> xdmfAttributes(const ParticleSet& p) {
  std::vector<XdmfAttribute> scalars, others;
  for (const Field& f : p.fields()) {
    if (!f.spec.xdmf || f.spec.output != FieldOutput::Particles) continue;
    const bool integer = f.spec.type != FieldType::Float64;
    const int precision = f.spec.type == FieldType::Int32 ? 4 : 8;
    (f.spec.components == 1 ? scalars : others)
        .push_back({f.spec.name, f.spec.components, integer, precision});
  }
  scalars.insert(scalars.end(), others.begin(), others.end());
  return scalars;
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
