#include "face_colors.hpp"

#include "nome/mesh/color_attribute.hpp"

namespace nome::test {

std::vector<Color> face_colors(const Attributes& faces, Index num_faces) {
  const Column<Color>* colors = find_colors(faces);
  if (!colors || colors->values().empty()) return {};
  std::vector<Color> out;
  for (Index f = 0; f < num_faces; ++f) out.push_back((*colors)[f]);
  return out;
}

void set_face_colors(Attributes& faces, const std::vector<Color>& colors) {
  faces.remove(color_attribute);
  if (!colors.empty()) add_colors(faces).values() = colors;
}

}  // namespace nome::test
