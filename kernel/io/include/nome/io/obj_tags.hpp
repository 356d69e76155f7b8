#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/ops/boundary_mode.hpp"
#include "nome/ops/crease_options.hpp"

namespace nome {

// The subdivision options of an OBJ file's OpenSubdiv tag lines (`t NAME I/F/S ints floats strings`, the
// convention of OpenSubdiv's regression shapes). read_obj applies the tags on elements itself: `t crease
// 2/1/0 a b w` (edge a-b weighs w; vertices count from 0), `t corner 1/1/0 v w`, `t hole 1/0/0 f`, and
// Nome's own `t splitvertex 1/0/0 v`: faces touch at vertex v without sharing an edge there (where holes
// leave two fans meeting at a point), so v is one vertex of the file but one per fan of the surface.
struct ObjSubdivisionTags {
  std::optional<BoundaryMode>
      boundary;  // t interpolateboundary 1/0/0 N: 0 none, 1 edge-and-corner, 2 edge-only
  std::optional<CreaseMethod> crease_method;  // t creasemethod 0/0/1 chaikin|normal|uniform
  std::optional<bool> smooth_triangles;       // t smoothtriangles 0/0/1 smooth|catmark
  // One note per kind of tag not applied (hierarchical edits such as `t vertexedit`, which OpenSubdiv's
  // refiner ignores too, face-varying options), naming its first line.
  std::vector<std::string> notes;
  bool operator==(const ObjSubdivisionTags&) const = default;
};

// The subdivision tags of an OBJ file. Throws IoError with file:line:col for a malformed tag line.
ObjSubdivisionTags read_obj_subdivision_tags(const std::filesystem::path& path);

// The tag lines for `tags` and for the mesh's crease weights, corner weights and holes (what read_obj
// and read_obj_subdivision_tags read back).
void write_obj_tags(std::ostream& out, const Mesh& mesh, const ObjSubdivisionTags& tags);

}  // namespace nome
