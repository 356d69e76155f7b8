#pragma once

#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {

struct GluedFaces {
  Mesh mesh;
  std::vector<Index> vertex_sources;  // mesh vertex -> soup vertex it copies
  // Edges left apart because more than two faces use them, each `file:line:col: ` first where the soup
  // knows the origin of a face on it.
  std::vector<std::string> problems;
};

// Builds a mesh from polygons that share vertices by id but need not be a 2-manifold at every vertex:
// faces are joined only across shared edges, so a vertex where faces merely touch (the report's
// "two triangles sharing one vertex", or what deleting faces leaves behind) becomes one vertex per fan.
// An edge used by more than two faces joins none of them and is listed in `problems`. Vertices used by
// no face are dropped. Throws TopologyError only for faces that are not polygons (fewer than three
// vertices, a repeated vertex).
GluedFaces glue_faces(const PolygonSoup& soup);

}  // namespace nome
