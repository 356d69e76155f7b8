#include "nome/ops/offset_report.hpp"

#include <vector>

namespace nome {

TopologyReport offset_topology_report(const Mesh& mesh) {
  const TopologyReport surface = topology_report(mesh);
  std::vector<Index> border_edges(surface.components.size(), 0);
  for (Index l = 0; l < mesh.num_boundary_loops(); ++l)
    border_edges[mesh.face_component(mesh.edge(mesh.loop_edges(l).front()).faces[0])] +=
        Index(mesh.loop_edges(l).size());
  TopologyReport report;
  for (size_t k = 0; k < surface.components.size(); ++k) {
    const ComponentTopology& part = surface.components[k];
    ComponentTopology side{.vertices = part.vertices, .edges = part.edges, .faces = part.faces};
    const bool splits = part.orientable && part.borders == 0;
    if (!splits) {
      side.vertices *= 2;
      side.edges = 2 * side.edges + border_edges[k];
      side.faces = 2 * side.faces + border_edges[k];
    }
    side.chi = static_cast<long long>(side.vertices) - side.edges + side.faces;
    side.genus = (2 - side.chi) / 2;
    for (int copy = 0; copy < (splits ? 2 : 1); ++copy) {
      report.components.push_back(side);
      report.vertices += side.vertices;
      report.edges += side.edges;
      report.faces += side.faces;
    }
  }
  report.chi = static_cast<long long>(report.vertices) - report.edges + report.faces;
  return report;
}

}  // namespace nome
