#pragma once
// Mesh files: Wavefront OBJ and STL (ASCII and binary), read into a TriangleMesh with patches.
//   OBJ: `v x y z [w | r g b]`, `f a b c ...` (forms i, i/t, i//n, i/t/n; negative indices count back
//        from the latest vertex; polygons are split into a fan of triangles). `g NAME` and
//        `o NAME` start a patch of that name (a name seen again continues the same patch).
//        vt, vn, vp, s, l, p, usemtl and mtllib are read past; anything else is an error.
//   STL: ASCII `solid NAME` ... `endsolid` blocks each become a patch named NAME; a binary file
//        (80-byte header, triangle count, 50 bytes a triangle) is one patch. Vertices are welded
//        where they coincide exactly. Where a facet's stored normal is non-zero and points
//        against its vertices' winding, the winding is reversed: the stored normal says which
//        side is the outside.
// Faces outside any named group or solid go to a patch named MeshReadOptions::patchName, or the
// file's stem ("craft" for craft.stl). Malformed files throw MeshError naming the file, the line
// (ASCII) or triangle (binary) and the reason.
#include <filesystem>
#include <string>

#include "radiation/mesh.hpp"

namespace ejecta::radiation {

struct MeshReadOptions {
  std::string patchName;  // unnamed faces and binary STL; empty: the file's stem
  double scale = 1.0;     // multiplies every coordinate: file units to metres (1e-3 for mm)
};

TriangleMesh readObj(const std::filesystem::path& path, const MeshReadOptions& options = {});
TriangleMesh readStl(const std::filesystem::path& path, const MeshReadOptions& options = {});
// By extension, case-insensitive: .obj or .stl.
TriangleMesh readMesh(const std::filesystem::path& path, const MeshReadOptions& options = {});

}  // namespace ejecta::radiation
