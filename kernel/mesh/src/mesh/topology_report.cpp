#include "nome/mesh/topology_report.hpp"

#include "nome/mesh/face_orientation.hpp"

namespace nome {

TopologyReport topology_report(const Mesh& mesh) {
  TopologyReport report;
  std::vector<ComponentTopology>& parts = report.components;
  parts.resize(mesh.num_components());

  for (Index f = 0; f < mesh.num_faces(); ++f) ++parts[mesh.face_component(f)].faces;
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const Index c = mesh.vertex_component(v);
    if (c == no_index)
      ++report.isolated_vertices;
    else
      ++parts[c].vertices;
  }
  for (const Edge& e : mesh.edges()) {
    ComponentTopology& part = parts[mesh.face_component(e.faces[0])];
    ++part.edges;
    if (e.is_mobius) ++part.mobius_edges;
  }
  for (Index l = 0; l < mesh.num_boundary_loops(); ++l)
    ++parts[mesh.face_component(mesh.edge(mesh.loop_edges(l).front()).faces[0])].borders;

  // Orientability: only the Möbius parity of the face-to-face walks matters, not the given orientation.
  const FaceOrientation orientation = face_orientation(mesh);
  for (Index k = 0; k < mesh.num_components(); ++k) parts[k].orientable = orientation.component_orientable[k];

  for (ComponentTopology& part : parts) {
    part.chi = static_cast<long long>(part.vertices) - part.edges + part.faces;
    const long long handles = 2 - part.chi - part.borders;
    part.genus = part.orientable ? handles / 2 : handles;
    report.vertices += part.vertices;
    report.edges += part.edges;
    report.faces += part.faces;
    report.borders += part.borders;
    report.mobius_edges += part.mobius_edges;
    report.orientable = report.orientable && part.orientable;
  }
  report.chi = static_cast<long long>(report.vertices) - report.edges + report.faces;
  return report;
}

}  // namespace nome
