#pragma once

#include "nome/mesh/topology_report.hpp"
#include "nome/ops/boundary_mode.hpp"

namespace nome {

// The topology report of `mesh` after `levels` levels of Catmull-Clark that output every face (no holes,
// no border dropped by BoundaryMode::none), found from `mesh` alone: subdivision keeps each part's chi,
// orientability, borders and genus, and each level turns V, E, F, corners C into V + E + F, 2E + C, C, 4C
// and doubles the Möbius edges (a face's interior children are regular). Isolated vertices stay isolated.
TopologyReport subdivided_topology_report(const Mesh& mesh, int levels);
// Whether subdividing `mesh` outputs every face: holes and BoundaryMode::none (where there are borders)
// drop faces and renumber vertices, which only the subdivided Mesh has.
bool subdivision_outputs_every_face(const Mesh& mesh, BoundaryMode boundary);

}  // namespace nome
