#include "radiation/mesh_io.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ejecta::radiation {

namespace {

namespace fs = std::filesystem;

std::string readWholeFile(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw MeshError(path.string() + ": is a directory, not a mesh file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError(path.string() + ": cannot open the mesh file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string defaultPatchName(const fs::path& path, const MeshReadOptions& options) {
  if (!options.patchName.empty()) return options.patchName;
  const std::string stem = path.stem().string();
  return stem.empty() ? std::string("mesh") : stem;
}

void checkScale(const fs::path& path, const MeshReadOptions& options) {
  if (!(options.scale > 0.0) || !std::isfinite(options.scale))
    throw MeshError(path.string() + ": the scale must be a positive finite number");
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Splits a line into whitespace-separated tokens (views into the line).
std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isSpace(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !isSpace(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

bool parseDouble(std::string_view s, double& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);  // from_chars takes no leading '+'
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

bool parseInteger(std::string_view s, long long& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// Welds exactly coincident vertices (STL stores every triangle's corners separately).
class VertexWelder {
 public:
  explicit VertexWelder(TriangleMesh& mesh) : mesh_(mesh) {}
  std::uint32_t add(const Vec3& v) {
    Key k{};
    std::memcpy(k.data(), v.data(), sizeof(Key));
    const auto [it, inserted] = index_.try_emplace(k, 0u);
    if (inserted) it->second = mesh_.addVertex(v);
    return it->second;
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 0x9e3779b97f4a7c15ull;
      for (std::uint64_t w : k) h = (h ^ w) * 0xbf58476d1ce4e5b9ull + (h >> 29);
      return static_cast<std::size_t>(h);
    }
  };
  TriangleMesh& mesh_;
  std::unordered_map<Key, std::uint32_t, KeyHash> index_;
};

// Adds a triangle, reversing its winding when a non-zero stored normal points the other way.
void addFacet(TriangleMesh& mesh, VertexWelder& welder, const Vec3 (&v)[3], const Vec3& normal,
              std::uint32_t patch) {
  const Vec3 winding = vec3::cross(vec3::sub(v[1], v[0]), vec3::sub(v[2], v[0]));
  const bool reversed = vec3::dot(winding, normal) < 0.0;
  const std::uint32_t a = welder.add(v[0]), b = welder.add(v[1]), c = welder.add(v[2]);
  if (reversed) mesh.addTriangle(a, c, b, patch);
  else mesh.addTriangle(a, b, c, patch);
}

// ---------------------------------------------------------------------------------------- OBJ

struct PendingFace {
  std::array<long long, 3> index;  // resolved 0-based (may be out of range: checked at the end)
  std::uint32_t patch;
  std::size_t line;
};

TriangleMesh parseObj(const std::string& text, const fs::path& path,
                      const MeshReadOptions& options) {
  const std::string file = path.string();
  TriangleMesh mesh;
  std::vector<PendingFace> faces;
  std::string currentPatch = defaultPatchName(path, options);
  std::size_t lineNo = 0;
  std::size_t pos = 0;
  auto fail = [&](const std::string& why) -> void {
    throw MeshError(file + ":" + std::to_string(lineNo) + ": " + why);
  };
  while (pos <= text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++lineNo;
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    const std::vector<std::string_view> tok = tokens(line);
    if (tok.empty()) continue;
    const std::string_view key = tok[0];
    if (key == "v") {
      // x y z, x y z w, or x y z r g b (vertex colours, as some exporters write).
      if (tok.size() != 4 && tok.size() != 5 && tok.size() != 7)
        fail("a vertex needs 3 coordinates (then an optional w, or r g b)");
      Vec3 v{};
      for (int k = 0; k < 3; ++k)
        if (!parseDouble(tok[1 + k], v[k]))
          fail("vertex coordinate '" + std::string(tok[1 + k]) + "' is not a number");
      if (!vec3::finite(v)) fail("vertex is not finite");
      mesh.addVertex(vec3::scale(v, options.scale));
    } else if (key == "f") {
      if (tok.size() < 4) fail("a face needs at least 3 vertices");
      std::vector<long long> idx;
      for (std::size_t k = 1; k < tok.size(); ++k) {
        const std::string_view ref = tok[k].substr(0, tok[k].find('/'));
        long long i = 0;
        if (!parseInteger(ref, i)) fail("face vertex '" + std::string(tok[k]) + "' is not an index");
        if (i == 0) fail("face vertex index 0 (OBJ indices start at 1)");
        // Negative: relative to the vertices defined so far (-1 is the latest).
        const long long resolved = i > 0 ? i - 1 : static_cast<long long>(mesh.vertices.size()) + i;
        if (resolved < 0)
          fail("face vertex index " + std::to_string(i) + " reaches before the first vertex");
        idx.push_back(resolved);
      }
      const std::uint32_t patch = mesh.patchIndex(currentPatch);
      for (std::size_t k = 1; k + 1 < idx.size(); ++k)  // a fan over a convex polygon
        faces.push_back({{idx[0], idx[k], idx[k + 1]}, patch, lineNo});
    } else if (key == "g" || key == "o") {
      std::string name;
      for (std::size_t k = 1; k < tok.size(); ++k) {
        if (k > 1) name += ' ';  // appended stepwise: GCC 12 warns falsely (-Wrestrict) on "x" + s
        name.append(tok[k]);
      }
      currentPatch = name.empty() ? defaultPatchName(path, options) : name;
    } else if (key == "vt" || key == "vn" || key == "vp" || key == "s" || key == "l" ||
               key == "p" || key == "usemtl" || key == "mtllib") {
      continue;  // texture, normals, smoothing, lines, materials: nothing the radiation needs
    } else {
      fail("unsupported OBJ statement '" + std::string(key) + "'");
    }
  }
  for (const PendingFace& f : faces) {
    for (long long i : f.index)
      if (i >= static_cast<long long>(mesh.vertices.size()))
        throw MeshError(file + ":" + std::to_string(f.line) + ": face refers to vertex " +
                        std::to_string(i + 1) + " but the file defines " +
                        std::to_string(mesh.vertices.size()));
    mesh.addTriangle(static_cast<std::uint32_t>(f.index[0]), static_cast<std::uint32_t>(f.index[1]),
                     static_cast<std::uint32_t>(f.index[2]), f.patch);
  }
  if (mesh.triangles.empty()) throw MeshError(file + ": the mesh has no faces");
  validateMesh(mesh, file);
  return mesh;
}

// ---------------------------------------------------------------------------------------- STL

constexpr std::size_t kStlHeader = 80, kStlPrefix = 84, kStlRecord = 50;

std::uint32_t littleEndian32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

double littleEndianFloat(const unsigned char* p) {
  return static_cast<double>(std::bit_cast<float>(littleEndian32(p)));
}

TriangleMesh parseBinaryStl(const std::string& bytes, const fs::path& path,
                            const MeshReadOptions& options) {
  const std::string file = path.string();
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::uint64_t count = littleEndian32(data + kStlHeader);
  const std::uint64_t expected = kStlPrefix + kStlRecord * count;
  if (bytes.size() != expected)
    throw MeshError(file + ": binary STL " + (bytes.size() < expected ? "truncated" : "too long") +
                    ": the header announces " + std::to_string(count) + " triangles (" +
                    std::to_string(expected) + " bytes) but the file has " +
                    std::to_string(bytes.size()) + " bytes");
  if (count == 0) throw MeshError(file + ": the binary STL has no triangles");
  TriangleMesh mesh;
  VertexWelder welder(mesh);
  const std::uint32_t patch = mesh.patchIndex(defaultPatchName(path, options));
  for (std::uint64_t t = 0; t < count; ++t) {
    const unsigned char* rec = data + kStlPrefix + kStlRecord * t;
    double f[12];
    for (int k = 0; k < 12; ++k) f[k] = littleEndianFloat(rec + 4 * k);
    const Vec3 normal{f[0], f[1], f[2]};
    Vec3 v[3];
    for (int c = 0; c < 3; ++c) {
      v[c] = {f[3 + 3 * c] * options.scale, f[4 + 3 * c] * options.scale, f[5 + 3 * c] * options.scale};
      if (!vec3::finite(v[c]))
        throw MeshError(file + ": triangle " + std::to_string(t) + " (byte " +
                        std::to_string(kStlPrefix + kStlRecord * t) + "): vertex " +
                        std::to_string(c + 1) + " is not finite");
    }
    addFacet(mesh, welder, v, vec3::finite(normal) ? normal : Vec3{}, patch);
  }
  validateMesh(mesh, file);
  return mesh;
}

// Token stream over ASCII STL with line numbers.
class StlTokens {
 public:
  StlTokens(const std::string& text, std::string file) : text_(text), file_(std::move(file)) {}
  bool next(std::string_view& tok) {
    while (pos_ < text_.size() && (isSpace(text_[pos_]) || text_[pos_] == '\n')) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= text_.size()) return false;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !isSpace(text_[pos_]) && text_[pos_] != '\n') ++pos_;
    tok = std::string_view(text_).substr(start, pos_ - start);
    tokenLine_ = line_;
    return true;
  }
  // The rest of the current line (a solid's name), trimmed.
  std::string restOfLine() {
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    std::string_view rest = std::string_view(text_).substr(pos_, end - pos_);
    pos_ = end;
    while (!rest.empty() && isSpace(rest.front())) rest.remove_prefix(1);
    while (!rest.empty() && isSpace(rest.back())) rest.remove_suffix(1);
    return std::string(rest);
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw MeshError(file_ + ":" + std::to_string(tokenLine_) + ": " + why);
  }
  std::string_view expectAny(const char* what) {
    std::string_view tok;
    if (!next(tok)) {
      tokenLine_ = line_;
      fail(std::string("unexpected end of file, expected ") + what);
    }
    return tok;
  }
  void expect(std::string_view word) {
    const std::string_view tok = expectAny(std::string(word).c_str());
    if (tok != word) fail("expected '" + std::string(word) + "', got '" + std::string(tok) + "'");
  }
  double number(const char* what) {
    const std::string_view tok = expectAny(what);
    double x = 0.0;
    if (!parseDouble(tok, x)) fail(std::string(what) + " '" + std::string(tok) + "' is not a number");
    if (!std::isfinite(x)) fail(std::string(what) + " is not finite");
    return x;
  }

 private:
  const std::string& text_;
  std::string file_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1, tokenLine_ = 1;
};

TriangleMesh parseAsciiStl(const std::string& text, const fs::path& path,
                           const MeshReadOptions& options) {
  TriangleMesh mesh;
  VertexWelder welder(mesh);
  StlTokens in(text, path.string());
  std::string_view tok;
  while (in.next(tok)) {
    if (tok != "solid") in.fail("expected 'solid', got '" + std::string(tok) + "'");
    std::string name = in.restOfLine();
    const std::uint32_t patch = mesh.patchIndex(name.empty() ? defaultPatchName(path, options) : name);
    for (;;) {
      const std::string_view word = in.expectAny("'facet' or 'endsolid'");
      if (word == "endsolid") {
        in.restOfLine();
        break;
      }
      if (word != "facet") in.fail("expected 'facet' or 'endsolid', got '" + std::string(word) + "'");
      in.expect("normal");
      Vec3 normal{};
      for (int k = 0; k < 3; ++k) normal[k] = in.number("normal component");
      in.expect("outer");
      in.expect("loop");
      Vec3 v[3];
      for (int c = 0; c < 3; ++c) {
        in.expect("vertex");
        for (int k = 0; k < 3; ++k) v[c][k] = in.number("vertex coordinate") * options.scale;
      }
      in.expect("endloop");
      in.expect("endfacet");
      addFacet(mesh, welder, v, normal, patch);
    }
  }
  if (mesh.triangles.empty()) throw MeshError(path.string() + ": the STL has no facets");
  validateMesh(mesh, path.string());
  return mesh;
}

// ASCII STL starts with "solid" and is text; a binary header may also start with "solid", but
// its count and float fields nearly always hold zero bytes.
bool looksLikeAsciiStl(const std::string& bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && (isSpace(bytes[i]) || bytes[i] == '\n')) ++i;
  if (bytes.compare(i, 5, "solid") != 0) return false;
  const std::size_t probe = std::min<std::size_t>(bytes.size(), 4096);
  return std::find(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(probe), '\0') ==
         bytes.begin() + static_cast<std::ptrdiff_t>(probe);
}

std::string lowercaseExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

TriangleMesh readObj(const fs::path& path, const MeshReadOptions& options) {
  checkScale(path, options);
  return parseObj(readWholeFile(path), path, options);
}

TriangleMesh readStl(const fs::path& path, const MeshReadOptions& options) {
  checkScale(path, options);
  const std::string bytes = readWholeFile(path);
  if (looksLikeAsciiStl(bytes)) return parseAsciiStl(bytes, path, options);
  if (bytes.size() < kStlPrefix)
    throw MeshError(path.string() + ": " + std::to_string(bytes.size()) +
                    " bytes: too short for a binary STL (84-byte header) and not ASCII STL");
  return parseBinaryStl(bytes, path, options);
}

TriangleMesh readMesh(const fs::path& path, const MeshReadOptions& options) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw MeshError(path.string() + ": is a directory, not a mesh file");
  const std::string ext = lowercaseExtension(path);
  if (ext == ".obj") return readObj(path, options);
  if (ext == ".stl") return readStl(path, options);
  throw MeshError(path.string() + ": unknown mesh format '" + ext + "' (expected .obj or .stl)");
}

}  // namespace ejecta::radiation
