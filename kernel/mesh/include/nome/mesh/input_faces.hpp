#pragma once

#include <optional>
#include <string_view>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/polygon_soup.hpp"

namespace nome {

// The face attribute "input face": each face of an input soup its own number, carried (copied) to every face
// made from it, so that a face of any later stage (a child of a subdivision, either copy or a rim quad of
// the offset) finds the input face it came from. A caller that asks (the viewer) marks its input; exports
// of unmarked inputs carry nothing more.
inline constexpr std::string_view input_face_attribute = "input face";

// Gives every face of `soup` its own number as its input face.
void mark_input_faces(PolygonSoup& soup);
void mark_input_faces(Attributes& faces, Index num_faces);

// The input face that face `face` of `mesh` came from; none when the mesh's input was not marked or there
// is no such face.
std::optional<Index> input_face(const Mesh& mesh, Index face);

}  // namespace nome
