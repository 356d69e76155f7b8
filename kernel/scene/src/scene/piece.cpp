#include "nome/scene/piece.hpp"

#include <algorithm>

namespace nome::scene {

namespace {

bool same_rims(const std::vector<RimLine>& a, const std::vector<RimLine>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const RimLine& x, const RimLine& y) {
    return x.name == y.name && x.vertices == y.vertices && x.is_loop == y.is_loop && x.color == y.color;
  });
}

bool same_origins(const std::vector<FaceOrigin>& a, const std::vector<FaceOrigin>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const FaceOrigin& x, const FaceOrigin& y) {
    return x.first_face == y.first_face && x.where == y.where;
  });
}

}  // namespace

bool has_same_topology(const Piece& a, const Piece& b) {
  const PolygonSoup& s = a.soup;
  const PolygonSoup& t = b.soup;
  return s.positions.size() == t.positions.size() && s.face_offsets == t.face_offsets &&
         s.face_vertices == t.face_vertices && s.vertex_names == t.vertex_names &&
         s.face_names == t.face_names && s.face_attributes == t.face_attributes &&
         s.sharp_edges == t.sharp_edges && s.sharp_edge_weights == t.sharp_edge_weights &&
         s.sharp_vertices == t.sharp_vertices && s.hole_faces == t.hole_faces &&
         same_origins(s.face_origins, t.face_origins) && s.grid == t.grid && same_rims(a.rims, b.rims);
}

}  // namespace nome::scene
