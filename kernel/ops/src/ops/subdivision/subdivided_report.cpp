#include "nome/ops/subdivided_report.hpp"

#include <vector>

namespace nome {

bool subdivision_outputs_every_face(const Mesh& mesh, BoundaryMode boundary) {
  return !mesh.has_holes() && !(boundary == BoundaryMode::none && mesh.num_boundary_loops() > 0);
}

TopologyReport subdivided_topology_report(const Mesh& mesh, int levels) {
  TopologyReport report = topology_report(mesh);
  std::vector<Index> corners(report.components.size(), 0);
  for (Index f = 0; f < mesh.num_faces(); ++f) corners[mesh.face_component(f)] += mesh.face_degree(f);
  report.vertices = report.edges = report.faces = report.mobius_edges = 0;
  for (size_t k = 0; k < report.components.size(); ++k) {
    ComponentTopology& part = report.components[k];
    for (int level = 0; level < levels; ++level) {
      part.vertices += part.edges + part.faces;
      part.edges = 2 * part.edges + corners[k];
      part.faces = corners[k];
      corners[k] *= 4;
      part.mobius_edges *= 2;
    }
    report.vertices += part.vertices;
    report.edges += part.edges;
    report.faces += part.faces;
    report.mobius_edges += part.mobius_edges;
  }
  return report;
}

}  // namespace nome
