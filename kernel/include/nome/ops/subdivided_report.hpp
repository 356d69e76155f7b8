#pragma once

#include "nome/mesh/topology_report.hpp"

namespace nome {

// The topology report of `mesh` after `levels` levels of Catmull-Clark that output every face (no holes,
// no border dropped by BoundaryMode::none), found from `mesh` alone: subdivision keeps each part's chi,
// orientability, borders and genus, and each level turns V, E, F, corners C into V + E + F, 2E + C, C, 4C
// and doubles the Möbius edges (a face's interior children are regular). Isolated vertices stay isolated.
TopologyReport subdivided_topology_report(const Mesh& mesh, int levels);

}  // namespace nome
