#pragma once

#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/normals.hpp"

namespace nome {

// Faces of `surface` whose copy in the offset by `distance` (either side: v + d s n_v or v - d s n_v, as
// ops/offset places it) has a Newell normal opposing the face's own, or has passed through the copy of a
// face sharing an edge with it on the same side (the angle between the two closed through zero): where the
// distance exceeds the surface's local radius of curvature (or a crease's inside is narrower than the slab)
// the offset turns inside out and the printed solid is broken. Faces with a zero normal are skipped by the
// first rule. In face order.
std::vector<Index> find_fold_overs(const Mesh& surface, const Normals& normals, double distance,
                                   int threads = 1);

}  // namespace nome
