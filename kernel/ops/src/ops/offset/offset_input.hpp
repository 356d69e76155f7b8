#pragma once

#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {

// What offset() and OffsetSurface both read of their input.

// Throws InvalidInputError, naming `who`, unless the distance is positive and finite.
void check_offset_distance(const char* who, double distance);

// The offset's numbering: input vertex v on side 0 (v+) or 1 (v-) is output vertex 2 rank(v) + side,
// vertices without faces getting none. Returns the ranks, empty when every vertex has faces (the usual
// case: the identity, for which an array would cost fresh pages); `count` gets the number of vertices
// with faces.
std::vector<Index> vertex_ranks(const Mesh& mesh, Index& count);

}  // namespace nome
