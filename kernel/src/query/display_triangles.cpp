#include "nome/query/display_triangles.hpp"

namespace nome {

DisplayTriangles display_triangles(const Mesh& mesh) {
  DisplayTriangles out;
  const Index count = mesh.num_corners() - 2 * mesh.num_faces();
  out.corners.reserve(count);
  out.faces.reserve(count);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Index first = mesh.face_first_corner(f);
    const Index degree = mesh.face_degree(f);
    for (Index i = 1; i + 1 < degree; ++i) {
      out.corners.push_back({first, first + i, first + i + 1});
      out.faces.push_back(f);
    }
  }
  return out;
}

}  // namespace nome
