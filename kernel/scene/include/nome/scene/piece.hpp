#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "nome/mesh/color_attribute.hpp"
#include "nome/mesh/polygon_soup.hpp"

namespace nome::scene {

// A rim line (`polyline`, `circle`): drawn, selectable and zippable, but no face.
struct RimLine {
  std::string name;
  std::vector<Index> vertices;  // into the positions of the geometry that holds it
  bool is_loop = false;
  std::optional<Color> color = std::nullopt;  // the surface of the nearest instance that names one
};

// The geometry of one definition or one placed instance: named vertices and faces, rim lines, and which
// faces carry their own colour (the others take the colour of the instance that places them).
struct Piece {
  // vertex_names and face_names always filled; the colour attribute absent while no face has a colour of
  // its own (most pieces: no array of a colour per face to write and copy).
  PolygonSoup soup;
  std::vector<RimLine> rims;
  // Nonzero when the generator can tell its topology without making it: two pieces of one definition with
  // the same key have the same faces and names (a slider that only moves vertices keeps it).
  std::uint64_t topology_key = 0;

  Index add_vertex(const Vec3& p, std::string name) {
    soup.vertex_names.push_back(std::move(name));
    return soup.add_vertex(p);
  }
  template <typename Range>
  void add_face(const Range& vertices, std::string name) {
    soup.add_face(vertices);
    soup.face_names.push_back(std::move(name));
  }
  bool has_face_color(Index f) const {
    const Column<Color>* colors = find_colors(soup.face_attributes);
    return colors && (*colors)[f] != no_face_color;
  }
  bool has_face_colors() const {
    const Column<Color>* colors = find_colors(soup.face_attributes);
    return colors && !colors->values().empty();
  }
  // Gives face f a colour of its own.
  void set_face_color(Index f, const Color& color) { add_colors(soup.face_attributes).set(f, color); }
};

// Whether b differs from a in its positions alone: the same faces, names, colours, sharp marks and rims.
bool has_same_topology(const Piece& a, const Piece& b);

// What a generator that knows its topology without making it gives on a slider move: the positions its
// piece would have, and that piece's topology key.
struct PiecePositions {
  Buffer<Vec3> positions;
  std::uint64_t topology_key = 0;
};

}  // namespace nome::scene
