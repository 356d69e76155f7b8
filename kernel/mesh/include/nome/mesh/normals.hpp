#pragma once

#include <span>
#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/packed_normal.hpp"

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
// The normals a GPU draws with, packed (PackedNormal), straight into `faces` and `vertices`:
// compute_normals' face normals packed; vertex normals summed from those and packed (within about 0.01 of
// compute_normals', and zero where those are, or where the fan's sum is shorter than 0.01: a fold, which
// the display shades with its faces' normals). A third of the bytes of float vectors to write and upload,
// and the gather's random reads of face normals touch a third of the cache lines. On up to `threads`
// threads, the same normals on any number.
void compute_packed_normals(const Mesh& mesh, Buffer<PackedNormal>& faces, Buffer<PackedNormal>& vertices,
                            int threads);
// Its two passes, for a caller that runs other work beside the second: `faces` from the first.
void compute_packed_face_normals(const Mesh& mesh, Buffer<PackedNormal>& faces, int threads);
void compute_packed_vertex_normals(const Mesh& mesh, std::span<const PackedNormal> faces,
                                   Buffer<PackedNormal>& vertices, int threads = 1);

// A warning naming the degenerate faces and vertices of `normals` (the first few of each, by label),
// or "" when there are none: for the caller to show, since the kernel never prints.
std::string degeneracy_warning(const Mesh& mesh, const Normals& normals);

}  // namespace nome
