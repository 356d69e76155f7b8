#include "nome/mesh/concatenate.hpp"

#include <algorithm>

namespace nome {

PolygonSoup concatenate(std::span<const Mesh> parts) {
  PolygonSoup soup;
  const auto any = [&](auto has) { return std::any_of(parts.begin(), parts.end(), has); };
  const bool has_vertex_names = any([](const Mesh& m) { return !m.vertex_names().empty(); });
  const bool has_face_names = any([](const Mesh& m) { return !m.face_names().empty(); });
  const bool has_face_colors = any([](const Mesh& m) { return !m.face_colors().empty(); });
  for (const Mesh& part : parts) {
    const Index base = soup.num_vertices(), corner_base = Index(soup.face_vertices.size());
    soup.positions.insert(soup.positions.end(), part.positions().begin(), part.positions().end());
    for (Index v : part.corner_vertices()) soup.face_vertices.push_back(v + base);
    for (Index f = 1; f < part.face_offsets().size(); ++f)
      soup.face_offsets.push_back(part.face_offsets()[f] + corner_base);
    if (has_vertex_names) {
      soup.vertex_names.insert(soup.vertex_names.end(), part.vertex_names().begin(),
                               part.vertex_names().end());
      soup.vertex_names.resize(soup.positions.size());
    }
    if (has_face_names) {
      soup.face_names.insert(soup.face_names.end(), part.face_names().begin(), part.face_names().end());
      soup.face_names.resize(soup.num_faces());
    }
    if (has_face_colors) {
      soup.face_colors.insert(soup.face_colors.end(), part.face_colors().begin(), part.face_colors().end());
      soup.face_colors.resize(soup.num_faces(), uncoloured_face_color);
    }
    for (const Edge& e : part.edges())
      if (e.is_sharp) soup.sharp_edges.emplace_back(e.vertices[0] + base, e.vertices[1] + base);
  }
  return soup;
}

}  // namespace nome
