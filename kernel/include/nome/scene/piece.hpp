#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "nome/mesh/polygon_soup.hpp"

namespace nome::scene {

// A rim line (`polyline`, `circle`): drawn, selectable and zippable, but no face.
struct RimLine {
  std::string name;
  std::vector<Index> vertices;  // into the positions of the geometry that holds it
  bool is_loop = false;
};

// The geometry of one definition or one placed instance: named vertices and faces, rim lines, and which
// faces carry their own colour (the others take the colour of the instance that places them).
struct Piece {
  PolygonSoup soup;  // vertex_names and face_names always filled; face_colors one per face
  std::vector<unsigned char> face_has_color;
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
    soup.face_colors.push_back(Color(0));
    face_has_color.push_back(0);
  }
};

// What a generator that knows its topology without making it gives on a slider move: the positions its
// piece would have, and that piece's topology key.
struct PiecePositions {
  Buffer<Vec3> positions;
  std::uint64_t topology_key = 0;
};

}  // namespace nome::scene
