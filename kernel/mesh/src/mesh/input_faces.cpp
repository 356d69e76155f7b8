#include "nome/mesh/input_faces.hpp"

#include <numeric>

namespace nome {

void mark_input_faces(PolygonSoup& soup) {
  mark_input_faces(soup.face_attributes, soup.num_faces());
}

void mark_input_faces(Attributes& faces, Index num_faces) {
  std::vector<Index>& numbers = faces.add<Index>(input_face_attribute, no_index).values();
  numbers.resize(num_faces);
  std::iota(numbers.begin(), numbers.end(), Index(0));
}

std::optional<Index> input_face(const Mesh& mesh, Index face) {
  const Column<Index>* faces = mesh.face_attributes().find<Index>(input_face_attribute);
  if (!faces || face >= mesh.num_faces() || (*faces)[face] == no_index) return std::nullopt;
  return (*faces)[face];
}

}  // namespace nome
