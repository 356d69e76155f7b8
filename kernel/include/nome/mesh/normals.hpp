#pragma once

#include <span>
#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {

// Newell's normal of face f (unnormalized: its length is twice the polygon's area), robust for
// non-planar and non-convex polygons.
Vec3 face_area_normal(const Mesh& mesh, Index f);
// The same for the polygon `vertices` (indices into `positions`), with the same arithmetic.
Vec3 polygon_area_normal(std::span<const Index> vertices, std::span<const Vec3> positions);

struct Normals {
  Buffer<Vec3> faces;     // unit face normals (zero for a degenerate face)
  Buffer<Vec3> vertices;  // unit vertex normals, relative to the first face of each vertex's fan
  std::vector<Index> degenerate_faces;     // zero area or coinciding vertices
  std::vector<Index> degenerate_vertices;  // the signed sum over the fan vanished
};

// Face normals by Newell; vertex normal = normalize(sum over the fan of s(f) * n_f), s the corner's
// orientation sign (Möbius-aware: no dot-product guessing). Degenerate elements get a zero normal and
// are listed, never NaN.
Normals compute_normals(const Mesh& mesh);
// The same into `out`, reusing its arrays' blocks (no fresh pages for a mesh no larger than the last).
void compute_normals(const Mesh& mesh, Normals& out);
// The same normals rounded to single precision (what a GPU draws with), rounded on up to `threads`
// threads; `scratch` keeps the double-precision normals and the degenerate elements.
void compute_float_normals(const Mesh& mesh, Normals& scratch, Buffer<glm::vec3>& faces,
                           Buffer<glm::vec3>& vertices, int threads);

// A warning naming the degenerate faces and vertices of `normals` (the first few of each, by label),
// or "" when there are none: for the caller to show, since the kernel never prints.
std::string degeneracy_warning(const Mesh& mesh, const Normals& normals);

}  // namespace nome
