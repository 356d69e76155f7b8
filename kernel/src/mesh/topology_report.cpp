#include "nome/mesh/topology_report.hpp"

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

  // Orientability: propagate an orientation sign face to face; a face reached with both signs means
  // no consistent orientation exists (the given orientation does not matter, only the Möbius parity).
  std::vector<signed char> sign(mesh.num_faces(), 0);
  std::vector<Index> queue;
  for (Index f0 = 0; f0 < mesh.num_faces(); ++f0) {
    if (sign[f0] != 0) continue;
    ComponentTopology& part = parts[mesh.face_component(f0)];
    sign[f0] = 1;
    queue.assign(1, f0);
    for (size_t q = 0; q < queue.size(); ++q) {
      const Index f = queue[q];
      for (Index e : mesh.face_edges(f)) {
        const Edge& edge = mesh.edge(e);
        const Index g = edge.other_face(f);
        if (g == no_index) continue;
        const signed char expected = static_cast<signed char>(edge.is_mobius ? -sign[f] : sign[f]);
        if (sign[g] == 0) {
          sign[g] = expected;
          queue.push_back(g);
        } else if (sign[g] != expected) {
          part.orientable = false;
        }
      }
    }
  }

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
