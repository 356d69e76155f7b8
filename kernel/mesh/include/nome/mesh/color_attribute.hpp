#pragma once

#include <string_view>

#include "nome/mesh/attributes.hpp"
#include "nome/mesh/types.hpp"

namespace nome {

// Faces' colours are the face attribute "color": a Color per face, no_face_color where a face has none,
// copied to every face made from one (children, copies, the rim of a border).
inline constexpr std::string_view color_attribute = "color";

inline const Column<Color>* find_colors(const Attributes& faces) {
  return faces.find<Color>(color_attribute);
}
// Face f's colour, no_face_color when it has none.
inline Color face_color(const Attributes& faces, Index f) {
  const Column<Color>* colors = find_colors(faces);
  return colors ? (*colors)[f] : no_face_color;
}
inline Column<Color>& add_colors(Attributes& faces) {
  return faces.add<Color>(color_attribute, no_face_color);
}

}  // namespace nome
