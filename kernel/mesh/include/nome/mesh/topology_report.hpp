#pragma once

#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {

// Topology of one connected component. Genus: for an orientable surface g with chi = 2 - 2g - b;
// for a non-orientable one the number of cross-caps k with chi = 2 - k - b.
struct ComponentTopology {
  Index vertices = 0;
  Index edges = 0;
  Index faces = 0;
  long long chi = 0;
  bool orientable = true;
  Index borders = 0;
  long long genus = 0;
  Index mobius_edges = 0;
};

// "Orientable" means a consistent orientation exists, whatever the given one: a torus with some
// faces reversed is orientable; its reversed faces show up as Möbius edges.
struct TopologyReport {
  Index vertices = 0;
  Index edges = 0;
  Index faces = 0;
  long long chi = 0;
  bool orientable = true;
  Index borders = 0;
  Index mobius_edges = 0;
  Index isolated_vertices = 0;
  std::vector<ComponentTopology> components;
};

TopologyReport topology_report(const Mesh& mesh);

}  // namespace nome
