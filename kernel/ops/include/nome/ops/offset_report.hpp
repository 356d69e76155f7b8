#pragma once

#include "nome/mesh/topology_report.hpp"

namespace nome {

// The topology report of offset(mesh, ...) found from `mesh` alone, without building the solid: each
// part becomes a closed orientable part of twice its chi, or two copies of itself when it is closed and
// orientable (its two sides); V, E, F become 2V, 2E + B, 2F + B for B border edges, and no Möbius edge is
// left. Isolated vertices give nothing.
TopologyReport offset_topology_report(const Mesh& mesh);

}  // namespace nome
