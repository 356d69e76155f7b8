#pragma once

#include "nome/id.hpp"

namespace nome {

// The elements of a Mesh, each kind its own id type (Mesh's arrays are indexed by id.index()).
using VertexId = Id<struct VertexKind>;
using EdgeId = Id<struct EdgeKind>;
using FaceId = Id<struct FaceKind>;
// One side of an edge in one face: a face's corner, where the half-edge leaving it starts.
using CornerId = Id<struct CornerKind>;

}  // namespace nome
