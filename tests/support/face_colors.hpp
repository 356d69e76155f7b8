#pragma once

#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome::test {

// The colour attribute as one colour per face (no_face_color where a face has none); empty when there is
// no colour attribute with a value.
std::vector<Color> face_colors(const Attributes& faces, Index num_faces);
inline std::vector<Color> face_colors(const PolygonSoup& soup) {
  return face_colors(soup.face_attributes, soup.num_faces());
}
inline std::vector<Color> face_colors(const Mesh& mesh) {
  return face_colors(mesh.face_attributes(), mesh.num_faces());
}
// Gives the faces these colours (the attribute removed for an empty list).
void set_face_colors(Attributes& faces, const std::vector<Color>& colors);

}  // namespace nome::test
