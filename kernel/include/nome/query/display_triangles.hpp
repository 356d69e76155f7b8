#pragma once

#include <array>
#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {

// The triangles a polygon mesh is drawn with, each knowing its face: a fan from each face's first
// corner. Triangle t has global corner ids corners[t] (in face order), so its vertices are
// mesh.corner_vertex(corners[t][i]), and its side corners[t][i] -> corners[t][(i+1)%3] is a real polygon
// edge (not a fan diagonal) exactly when the second corner follows the first in the face.
struct DisplayTriangles {
  std::vector<std::array<Index, 3>> corners;
  std::vector<Index> faces;

  Index size() const { return static_cast<Index>(faces.size()); }
};

DisplayTriangles display_triangles(const Mesh& mesh);

}  // namespace nome
