#include "nome/mesh/polygon_soup.hpp"

#include <algorithm>

namespace nome {

namespace {

bool is_empty(const PolygonSoup& s) {
  return s.positions.empty() && s.face_vertices.empty() && s.face_offsets.size() == 1 &&
         s.vertex_names.empty() && s.face_names.empty() && s.face_attributes.empty() &&
         s.sharp_edges.empty() && s.sharp_edge_weights.empty() && s.sharp_vertices.empty() &&
         s.hole_faces.empty() && s.face_origins.empty() && !s.grid;
}

}  // namespace

void append_soup(PolygonSoup& into, const PolygonSoup& part) {
  if (is_empty(into)) {
    into = part;  // the same as appending, and the names are shared rather than copied
    return;
  }
  into.grid.reset();  // the layout described the whole soup
  const Index base = into.num_vertices(), corner_base = Index(into.face_vertices.size());
  // The origins first, while into.num_faces() is where the part's faces will start.
  if (part.face_origins.empty() || part.face_origins.front().first_face != 0) into.note_origin({});
  const Index face_base = into.num_faces();
  for (const FaceOrigin& o : part.face_origins) {
    if (!into.face_origins.empty() && into.face_origins.back().first_face == o.first_face + face_base)
      into.face_origins.back().where = o.where;
    else
      into.face_origins.push_back({o.first_face + face_base, o.where});
  }
  const bool has_names = !into.vertex_names.empty() || !part.vertex_names.empty();
  const bool has_face_names = !into.face_names.empty() || !part.face_names.empty();
  if (has_names) into.vertex_names.resize(into.positions.size());
  if (has_face_names) into.face_names.resize(into.num_faces());

  into.face_attributes.append(part.face_attributes, face_base);
  into.positions.insert(into.positions.end(), part.positions.begin(), part.positions.end());
  for (Index v : part.face_vertices) into.face_vertices.push_back(v + base);
  for (size_t f = 1; f < part.face_offsets.size(); ++f)
    into.face_offsets.push_back(part.face_offsets[f] + corner_base);
  if (has_names) {
    into.vertex_names.append(part.vertex_names);
    into.vertex_names.resize(into.positions.size());
  }
  if (has_face_names) {
    into.face_names.append(part.face_names);
    into.face_names.resize(into.num_faces());
  }
  // Weights: where only one side has them, the other's sharp edges are infinitely sharp.
  if (!into.sharp_edge_weights.empty() || !part.sharp_edge_weights.empty()) {
    into.sharp_edge_weights.resize(into.sharp_edges.size(), infinite_sharpness);
    into.sharp_edge_weights.insert(into.sharp_edge_weights.end(), part.sharp_edge_weights.begin(),
                                   part.sharp_edge_weights.end());
    into.sharp_edge_weights.resize(into.sharp_edges.size() + part.sharp_edges.size(), infinite_sharpness);
  }
  for (auto [a, b] : part.sharp_edges) into.sharp_edges.emplace_back(a + base, b + base);
  for (auto [v, w] : part.sharp_vertices) into.sharp_vertices.emplace_back(v + base, w);
  for (Index f : part.hole_faces) into.hole_faces.push_back(f + face_base);
}

void PolygonSoup::add_sharp_edge(Index a, Index b, float weight) {
  if (weight != infinite_sharpness || !sharp_edge_weights.empty()) {
    sharp_edge_weights.resize(sharp_edges.size(), infinite_sharpness);
    sharp_edge_weights.push_back(weight);
  }
  sharp_edges.emplace_back(a, b);
}

void PolygonSoup::note_origin(const std::string& where) {
  const Index next = num_faces();
  if (face_origins.empty() ? where.empty() : face_origins.back().where == where) return;
  if (!face_origins.empty() && face_origins.back().first_face == next)
    face_origins.back().where = where;
  else
    face_origins.push_back({next, where});
}

const std::string& PolygonSoup::origin(Index f) const {
  static const std::string unknown;
  const auto after = std::upper_bound(face_origins.begin(), face_origins.end(), f,
                                      [](Index face, const FaceOrigin& o) { return face < o.first_face; });
  return after == face_origins.begin() ? unknown : std::prev(after)->where;
}

}  // namespace nome
