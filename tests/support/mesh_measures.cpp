#include "support/mesh_measures.hpp"

#include <glm/geometric.hpp>

namespace nome::test {

double signed_volume(const Mesh& mesh) {
  double volume = 0.0;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto vs = mesh.face_vertices(f);
    for (size_t i = 1; i + 1 < vs.size(); ++i)
      volume +=
          glm::dot(mesh.position(vs[0]), glm::cross(mesh.position(vs[i]), mesh.position(vs[i + 1]))) / 6.0;
  }
  return volume;
}

Vec3 face_centre(const PolygonSoup& soup, Index f) {
  Vec3 sum(0.0);
  for (Index k = soup.face_offsets[f]; k < soup.face_offsets[f + 1]; ++k)
    sum += soup.positions[soup.face_vertices[k]];
  return sum / double(soup.face_offsets[f + 1] - soup.face_offsets[f]);
}

}  // namespace nome::test
