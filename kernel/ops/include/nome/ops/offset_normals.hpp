#pragma once

#include "nome/buffer.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/mesh/packed_normal.hpp"

namespace nome {

// Whether offset(mesh, ...) is two parallel copies of `mesh` and nothing else: no border (so no rim
// quads), no Möbius edge (every corner sign +1) and no vertex without faces (solid vertices 2v and 2v+1
// are v+ and v-). On up to `threads` threads.
bool is_two_copy_offset(const Mesh& mesh, int threads = 1);

// The normals a display draws offset(mesh, {distance}) with, for any distance, when it is two parallel
// copies (is_two_copy_offset): v+ and face f take the surface's n_v and n_f, v- and f's reversed copy
// -n_v and -n_f, packed (PackedNormal). These are the normals of the exact offset surface (the
// surface moved by d along its normals has, at p + d n(p), the normal n(p)) rather than a new estimate
// from the offset's own polygons, and they cost a copy instead of two normal passes over twice the faces.
// `normals` are compute_normals(mesh)'. On up to `threads` threads. Returns false, leaving `faces` and
// `vertices` as they were, when the offset has rims or Möbius crossings (whose normals are new);
// throws InvalidInputError when `normals` do not fit the mesh.
bool offset_packed_normals(const Mesh& mesh, const Normals& normals, Buffer<PackedNormal>& faces,
                           Buffer<PackedNormal>& vertices, int threads = 1);

}  // namespace nome
