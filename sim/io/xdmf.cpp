#include "sim/io/xdmf.hpp"

#include <charconv>
#include <sstream>
#include <string_view>

#include "sim/io/atomic_file.hpp"

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

struct AttributeSpec {
  const char* name;
  const char* numberType;  // XDMF NumberType
  int precision;           // bytes
};

// The per-particle datasets published to visualisation tools (all in /particles).
constexpr AttributeSpec kScalars[] = {
    {"density", "Float", 8},         {"pressure", "Float", 8},
    {"internal_energy", "Float", 8}, {"smoothing_length", "Float", 8},
    {"sound_speed", "Float", 8},     {"mass", "Float", 8},
    {"material", "Int", 4},          {"id", "Int", 8},
};

void writeDataItem(std::ostream& out, const std::string& dims, const AttributeSpec& spec,
                   const std::string& file) {
  out << "        <DataItem Dimensions=\"" << dims << "\" NumberType=\"" << spec.numberType
      << "\" Precision=\"" << spec.precision << "\" Format=\"HDF\">" << file
      << ":/particles/" << spec.name << "</DataItem>\n";
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
  writeDataItem(out, n + " 3", {"position", "Float", 8}, file);
  out << "      </Geometry>\n";
  for (const AttributeSpec& spec : kScalars) {
    out << "      <Attribute Name=\"" << spec.name
        << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
    writeDataItem(out, n, spec, file);
    out << "      </Attribute>\n";
  }
  out << "      <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n";
  writeDataItem(out, n + " 3", {"velocity", "Float", 8}, file);
  out << "      </Attribute>\n"
      << "    </Grid>\n";
}

}  // namespace

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
