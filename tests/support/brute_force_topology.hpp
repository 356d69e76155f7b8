#pragma once

#include <string>

#include "nome/mesh/polygon_soup.hpp"
#include "nome/mesh/topology_report.hpp"

// A slow, obviously-correct topology routine for property tests. It shares no code with the kernel:
// edges come from an ordered map of vertex pairs, manifoldness from each vertex's link graph,
// orientability from counting the parts of the orientation double cover.
namespace nome::test {

struct BruteForceTopology {
  bool is_manifold = false;
  std::string problem;    // why not, when not
  TopologyReport report;  // filled when is_manifold
};

BruteForceTopology brute_force_topology(const PolygonSoup& soup);

}  // namespace nome::test
