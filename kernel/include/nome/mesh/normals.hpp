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
// The same into `out`, reusing its arrays' blocks (no fresh pages for a mesh no larger than the last), on
// up to `threads` threads (the same normals and lists on any number).
void compute_normals(const Mesh& mesh, Normals& out, int threads = 1);
// The normals a GPU draws with, straight into `faces` and `vertices`: compute_normals' face normals
// rounded; vertex normals summed and normalized in single precision (within about 1e-6 of
// compute_normals' rounded, and zero where those are). On up to `threads` threads, the same normals on
// any number: the vertex sums take a second thread only where the faces split into two halves that share
// no vertex (an offset's two sides), as do compute_normals'.
void compute_float_normals(const Mesh& mesh, Buffer<glm::vec3>& faces, Buffer<glm::vec3>& vertices,
                           int threads);
// Its two passes, for a caller that runs other work beside the second: `faces` from the first.
void compute_float_face_normals(const Mesh& mesh, Buffer<glm::vec3>& faces, int threads);
void compute_float_vertex_normals(const Mesh& mesh, std::span<const glm::vec3> faces,
                                  Buffer<glm::vec3>& vertices, int threads = 1);

// A warning naming the degenerate faces and vertices of `normals` (the first few of each, by label),
// or "" when there are none: for the caller to show, since the kernel never prints.
std::string degeneracy_warning(const Mesh& mesh, const Normals& normals);

}  // namespace nome
