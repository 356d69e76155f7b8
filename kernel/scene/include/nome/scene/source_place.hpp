#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/polygon_soup.hpp"
#include "nome/scene/diagnostic.hpp"

namespace nome::scene {

// A place in a named source file: what a diagnostic's `file:line:col` and a face's origin say.
struct SourcePlace {
  std::string file;
  SourceLocation location;
  bool operator==(const SourcePlace&) const = default;
};

// The `file:line:col` a text starts with (a diagnostic as Diagnostic::to_string writes it, a face origin);
// none when it starts with none. The file may hold ':' itself: the place ends at the first `:LINE:COL`
// followed by ':' or the end of the text.
std::optional<SourcePlace> parse_source_place(std::string_view text);

// The statement that made face `face` of a scene's polygons (the face statement, or the generator's
// definition for the faces it makes), from the soup's face origins; none for a face no statement made
// (a consolidated or temporary face) or past the end.
std::optional<SourcePlace> face_statement(const PolygonSoup& soup, Index face);

// The statement that made face `face` of `shown`, a mesh made from the soup at any stage: through the input
// face its faces carry (mark_input_faces), or, where they carry none, the soup's face of the same number
// (the scene and merged stages keep the soup's faces in order).
std::optional<SourcePlace> shown_face_statement(const Mesh& shown, const PolygonSoup& soup, Index face);

// The statement that made a vertex of `shown` (as above): that of its first face (the lowest index); none for
// an isolated vertex.
std::optional<SourcePlace> vertex_statement(const Mesh& shown, const PolygonSoup& soup, Index vertex);

}  // namespace nome::scene
