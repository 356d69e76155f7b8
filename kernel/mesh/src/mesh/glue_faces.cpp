#include "nome/mesh/glue_faces.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "nome/error.hpp"

namespace nome {
namespace {

Index find(std::vector<Index>& parent, Index v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// The source's sharp edges and corners on the glued soup, whose corner c (same numbering as the source's)
// holds the glued vertex of source corner c: a glued edge takes the weight of its source pair.
void carry_sharpness(const PolygonSoup& soup, PolygonSoup& glued) {
  const Index num_corners = Index(soup.face_vertices.size());
  const auto next = [&](Index c) {
    const Index f = Index(std::upper_bound(soup.face_offsets.begin(), soup.face_offsets.end(), c) -
                          soup.face_offsets.begin() - 1);
    return c + 1 == soup.face_offsets[f + 1] ? soup.face_offsets[f] : c + 1;
  };
  if (!soup.sharp_edges.empty()) {
    // (low, high, weight), sorted: a glued edge takes the weight of its source pair.
    std::vector<std::tuple<Index, Index, float>> sharp;
    for (size_t i = 0; i < soup.sharp_edges.size(); ++i) {
      const auto [a, b] = soup.sharp_edges[i];
      const float w = soup.sharp_edge_weights.empty() ? infinite_sharpness : soup.sharp_edge_weights[i];
      sharp.emplace_back(std::min(a, b), std::max(a, b), w);
    }
    std::sort(sharp.begin(), sharp.end());
    for (Index c = 0; c < num_corners; ++c) {
      const Index u = soup.face_vertices[c], w = soup.face_vertices[next(c)];
      const auto key = std::tuple{std::min(u, w), std::max(u, w), -INFINITY};
      const auto found = std::lower_bound(sharp.begin(), sharp.end(), key);
      if (found == sharp.end() || std::get<0>(*found) != std::get<0>(key) ||
          std::get<1>(*found) != std::get<1>(key))
        continue;
      glued.sharp_edges.emplace_back(glued.face_vertices[c], glued.face_vertices[next(c)]);
      if (!soup.sharp_edge_weights.empty()) glued.sharp_edge_weights.push_back(std::get<2>(*found));
    }
  }
  if (!soup.sharp_vertices.empty()) {
    std::vector<float> corner_weight(soup.num_vertices(), 0.0f);
    for (auto [v, w] : soup.sharp_vertices) corner_weight.at(v) = w;
    std::vector<bool> done(glued.num_vertices(), false);
    for (Index c = 0; c < num_corners; ++c) {
      const Index v = glued.face_vertices[c];
      if (done[v] || corner_weight[soup.face_vertices[c]] <= 0.0f) continue;
      done[v] = true;
      glued.sharp_vertices.emplace_back(v, corner_weight[soup.face_vertices[c]]);
    }
  }
}

// Every corner its own vertex at first; corners are joined across each edge with exactly two faces. Returns
// the union-find parents of the corners (find() gives a group's root); edges of more faces go to `problems`.
std::vector<Index> joined_corners(const PolygonSoup& soup, std::vector<std::string>& problems) {
  const Index num_corners = Index(soup.face_vertices.size());
  auto face_of = [&](Index c) {
    return Index(std::upper_bound(soup.face_offsets.begin(), soup.face_offsets.end(), c) -
                 soup.face_offsets.begin() - 1);
  };
  auto next = [&](Index c) {
    const Index f = face_of(c);
    return c + 1 == soup.face_offsets[f + 1] ? soup.face_offsets[f] : c + 1;
  };
  struct HalfEdge {
    Index low, high, corner;
  };
  std::vector<HalfEdge> half_edges(num_corners);
  for (Index c = 0; c < num_corners; ++c) {
    const Index u = soup.face_vertices[c], w = soup.face_vertices[next(c)];
    half_edges[c] = {std::min(u, w), std::max(u, w), c};
  }
  std::sort(half_edges.begin(), half_edges.end(), [](const HalfEdge& a, const HalfEdge& b) {
    return a.low != b.low ? a.low < b.low : a.high != b.high ? a.high < b.high : a.corner < b.corner;
  });
  std::vector<Index> parent(num_corners);
  std::iota(parent.begin(), parent.end(), 0);
  auto label = [&](Index v) {
    return v < soup.vertex_names.size() && !soup.vertex_names[v].empty() ? soup.vertex_names[v]
                                                                         : "v" + std::to_string(v);
  };
  for (size_t i = 0; i < half_edges.size();) {
    size_t end = i + 1;
    while (end < half_edges.size() && half_edges[end].low == half_edges[i].low &&
           half_edges[end].high == half_edges[i].high)
      ++end;
    if (end - i == 2) {
      // Corner c runs from its vertex to next(c): join the corners that sit at the same vertex.
      const Index c1 = half_edges[i].corner, c2 = half_edges[i + 1].corner;
      const bool same_way = soup.face_vertices[c1] == soup.face_vertices[c2];
      parent[find(parent, c1)] = find(parent, same_way ? c2 : next(c2));
      parent[find(parent, next(c1))] = find(parent, same_way ? next(c2) : c2);
    } else if (end - i > 2) {
      const std::string& where = soup.origin(face_of(half_edges[i].corner));
      problems.push_back((where.empty() ? "" : where + ": ") + "edge (" + label(half_edges[i].low) + ", " +
                         label(half_edges[i].high) + ") has " + std::to_string(end - i) + " faces");
    }
    i = end;
  }
  return parent;
}

}  // namespace

GluedFaces glue_faces(const PolygonSoup& soup) {
  const Index num_corners = Index(soup.face_vertices.size());
  GluedFaces out;
  std::vector<Index> parent = joined_corners(soup, out.problems);

  // phase: one vertex per group of joined corners.
  PolygonSoup glued;
  std::vector<Index> id(num_corners, no_index);
  const bool has_names = !soup.vertex_names.empty();
  for (Index c = 0; c < num_corners; ++c) {
    Index& v = id[find(parent, c)];
    if (v == no_index) {
      const Index source = soup.face_vertices[c];
      v = glued.add_vertex(soup.positions.at(source));
      out.vertex_sources.push_back(source);
      if (has_names) glued.vertex_names.push_back(soup.vertex_names[source]);
    }
    glued.face_vertices.push_back(v);
  }
  carry_sharpness(soup, glued);
  glued.hole_faces = soup.hole_faces;
  glued.face_offsets = soup.face_offsets;
  glued.face_names = soup.face_names;
  glued.face_attributes = soup.face_attributes;
  out.mesh = build_mesh(std::move(glued));
  return out;
}

}  // namespace nome
