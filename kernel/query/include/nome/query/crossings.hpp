#pragma once

#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/query/triangle_bvh.hpp"
#include "nome/query/triangle_proximity.hpp"

namespace nome {

// Two faces of the surface that pass through each other, and a piece of the curve where they do.
struct Crossing {
  Index face = no_index, other_face = no_index;
  CrossingSegment segment;
};

// Where distant parts of a surface pass through each other.
struct Crossings {
  std::vector<Crossing> pairs;       // one per crossing pair of display triangles, ordered by face
  std::vector<Index> faces;          // every face in a crossing, ascending
  std::vector<Index> curve_of_pair;  // pairs[i] lies on curve curve_of_pair[i]
  Index curves = 0;  // connected crossing curves: pairs joined through shared or adjacent faces
};

// Triangle pairs of the surface (as `bvh`, built over it, holds them) that intersect, neighbours sharing a
// vertex excluded, found by a box query per triangle on up to `threads` threads.
Crossings find_crossings(const Mesh& surface, const TriangleBvh& bvh, int threads = 1);

}  // namespace nome
