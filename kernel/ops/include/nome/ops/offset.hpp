#pragma once

#include <span>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/ops/subdivide.hpp"

namespace nome {

struct OffsetOptions {
  double distance = 0.05;      // half the slab's thickness; must be positive and finite
  int subdivision_levels = 0;  // Catmull-Clark levels after the offset, to round the rims
  SubdivisionRule rule = SubdivisionRule::classic;
  int threads = 1;  // the solid's arrays are built on up to two threads
};

// Thickens a surface into a solid (Wang's 2016 report, section 5). Vertex v
// gives v+ = v + d n_v and v- = v - d n_v (n_v Möbius-aware, see compute_normals); face f's positive
// copy uses v+ where its corner sign is +1 and v- where it is -1, its negative copy the other ones,
// reversed; each border edge gets one quad joining its positive and negative copies. The result is
// closed, orientable, consistently oriented with normals pointing out of the slab, free of Möbius
// edges, and has chi = 2 chi(M): a disk gives a sphere, an annulus or a Möbius band a torus, a Klein
// bottle a torus. Output vertex 2i is v+ and 2i+1 is v- of the i-th vertex that has faces; faces are
// the positive copies, then the negative copies, then the border quads in loop order. Throws
// InvalidInputError when the distance is not positive and finite.
Mesh offset(const Mesh& mesh, const OffsetOptions& options);

// For each face of the offset of `mesh`: the face of `mesh` it copies (both copies of a face) or the face
// whose border edge its rim quad stands on.
ElementOrigins offset_face_origins(const Mesh& mesh);

// The same with the mesh's normals already computed (a caller that also wants their warnings).
Mesh offset(const Mesh& mesh, const Normals& normals, const OffsetOptions& options);

// The same as offset(mesh, normals, {distance}) into `solid`, replacing what it held and reusing its
// arrays' blocks: a rebuild no larger than the solid it replaces touches no fresh pages (the viewer's
// rebuild when the surface under the offset changes its topology). Throws as offset() does, before
// `solid` is touched. Uses up to `threads` threads (two at most).
void offset_into(const Mesh& mesh, const Normals& normals, double distance, Mesh& solid, int threads = 1);

// The position pass alone: writes the positions offset(mesh, {distance}) would have into `out`
// (2 per vertex that has faces), for a caller that keeps the topology and moves only the vertices; on up
// to `threads` threads when every vertex has faces.
void offset_positions(const Mesh& mesh, double distance, std::span<Vec3> out);
void offset_positions(const Mesh& mesh, const Normals& normals, double distance, std::span<Vec3> out,
                      int threads = 1);

}  // namespace nome
