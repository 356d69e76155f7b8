#pragma once

#include <array>
#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {

// The triangles that display and picking share, so a pick lands on the triangle the user sees.
// Triangles name global corner ids (per-corner attributes and the face follow from them) and keep
// their face's orientation.
struct Triangulation {
  std::vector<std::array<Index, 3>> corners;
  std::vector<Index> faces;  // the face of each triangle
};

// Each n-gon becomes n - 2 triangles: a fan when the polygon is convex in the plane of its Newell
// normal, ear clipping in that plane otherwise (concave faces of consolidated meshes), and a fan for a
// degenerate face.
Triangulation triangulate(const Mesh& mesh);

}  // namespace nome
