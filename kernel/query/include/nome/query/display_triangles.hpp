#pragma once

#include <array>

#include "nome/mesh/mesh.hpp"

namespace nome {

// The triangles a polygon mesh is drawn with (app/render) and picked on (TriangleBvh), each knowing its
// face: a fan from the face's first corner when the face is convex in the plane of its Newell normal (or
// degenerate), ear clipping in that plane otherwise (concave faces of consolidated meshes), so a fan
// never covers a notch. Triangles keep their face's orientation. Triangle t has global corner ids corners[t]
// (in face order, cyclically), so its vertices are mesh.corner_vertex(corners[t][i]), and its side
// corners[t][i] -> corners[t][(i+1)%3] is a real polygon edge (not a fan diagonal) exactly when the second
// corner follows the first in the face.
struct DisplayTriangles {
  Buffer<std::array<Index, 3>> corners;
  Buffer<Index> faces;

  Index size() const { return static_cast<Index>(faces.size()); }
};

// On up to `threads` threads.
DisplayTriangles display_triangles(const Mesh& mesh, int threads = 1);

}  // namespace nome
