#include "nome/mesh/face_orientation.hpp"

namespace nome {

FaceOrientation face_orientation(const Mesh& mesh) {
  FaceOrientation out;
  std::vector<signed char>& sign = out.face_signs;
  sign.assign(mesh.num_faces(), 0);
  out.component_orientable.assign(mesh.num_components(), 1);
  std::vector<Index> queue;
  queue.reserve(mesh.num_faces());
  for (Index f0 = 0; f0 < mesh.num_faces(); ++f0) {
    if (sign[f0] != 0) continue;
    char& orientable = out.component_orientable[mesh.face_component(f0)];
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
          orientable = 0;
        }
      }
    }
  }
  return out;
}

}  // namespace nome
