#include "support/brute_force_topology.hpp"
#include "support/union_find.hpp"

#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace nome::test {
namespace {

struct Side {
  Index face;
  bool runs_low_to_high;
};

BruteForceTopology refuse(std::string why) {
  BruteForceTopology out;
  out.problem = std::move(why);
  return out;
}

}  // namespace

BruteForceTopology brute_force_topology(const PolygonSoup& soup) {
  const size_t nv = soup.positions.size(), nf = soup.face_offsets.size() - 1;
  auto face = [&](size_t f) {
    return std::vector<Index>(soup.face_vertices.begin() + soup.face_offsets[f],
                              soup.face_vertices.begin() + soup.face_offsets[f + 1]);
  };
  for (const Vec3& p : soup.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return refuse("non-finite position");

  // Faces, and every side keyed by its unordered vertex pair.
  std::map<std::pair<Index, Index>, std::vector<Side>> sides;
  std::vector<std::vector<std::pair<Index, Index>>> link(nv);  // per vertex: (previous, next) per face
  std::vector<Index> first_face(nv, no_index);
  for (size_t f = 0; f < nf; ++f) {
    const std::vector<Index> vs = face(f);
    if (vs.size() < 3) return refuse("face with fewer than 3 vertices");
    for (Index v : vs)
      if (v >= nv) return refuse("vertex index out of range");
    if (std::set<Index>(vs.begin(), vs.end()).size() != vs.size()) return refuse("repeated vertex in a face");
    for (size_t i = 0; i < vs.size(); ++i) {
      const Index a = vs[i], b = vs[(i + 1) % vs.size()], before = vs[(i + vs.size() - 1) % vs.size()];
      sides[{std::min(a, b), std::max(a, b)}].push_back({Index(f), a < b});
      link[a].emplace_back(before, b);
      if (first_face[a] == no_index) first_face[a] = Index(f);
    }
  }
  for (const auto& [pair, list] : sides)
    if (list.size() > 2) return refuse("edge with more than two faces");

  // Each vertex's link graph (neighbours as nodes, one edge per incident face) must be one cycle or
  // one path.
  for (size_t v = 0; v < nv; ++v) {
    if (link[v].empty()) continue;
    std::map<Index, int> degree;
    std::map<Index, size_t> node;
    for (const auto& [a, b] : link[v]) {
      ++degree[a], ++degree[b];
      node.emplace(a, node.size());
      node.emplace(b, node.size());
    }
    UnionFind parts(node.size());
    for (const auto& [a, b] : link[v]) parts.unite(node[a], node[b]);
    int ends = 0;
    std::set<size_t> roots;
    for (const auto& [n, d] : degree) {
      ends += d == 1;
      roots.insert(parts.find(node[n]));
    }
    if (roots.size() != 1 || (ends != 0 && ends != 2)) return refuse("vertex whose faces are not one fan");
  }

  // Parts: faces joined across shared edges, numbered by their first face.
  UnionFind face_parts(nf);
  UnionFind cover(2 * nf);  // node 2f: face f as given, 2f+1: face f reversed
  for (const auto& [pair, list] : sides) {
    if (list.size() != 2) continue;
    const Index f = list[0].face, g = list[1].face;
    face_parts.unite(f, g);
    // Two faces that run along the edge in opposite directions agree; in the same direction they
    // agree only once one of them is reversed.
    const bool same_direction = list[0].runs_low_to_high == list[1].runs_low_to_high;
    cover.unite(2 * f, 2 * g + (same_direction ? 1 : 0));
    cover.unite(2 * f + 1, 2 * g + (same_direction ? 0 : 1));
  }
  std::map<size_t, size_t> part_of_root;
  std::vector<size_t> part(nf);
  for (size_t f = 0; f < nf; ++f)
    part[f] = part_of_root.emplace(face_parts.find(f), part_of_root.size()).first->second;

  BruteForceTopology out;
  out.is_manifold = true;
  TopologyReport& r = out.report;
  r.components.resize(part_of_root.size());
  for (size_t f = 0; f < nf; ++f) ++r.components[part[f]].faces;
  // Any face at v names its part (the link is connected).
  for (size_t v = 0; v < nv; ++v) {
    if (first_face[v] == no_index)
      ++r.isolated_vertices;
    else
      ++r.components[part[first_face[v]]].vertices;
  }
  UnionFind border_vertices(nv);
  std::vector<std::pair<Index, Index>> border_edges;
  for (const auto& [pair, list] : sides) {
    ComponentTopology& c = r.components[part[list[0].face]];
    ++c.edges;
    if (list.size() == 2 && list[0].runs_low_to_high == list[1].runs_low_to_high) ++c.mobius_edges;
    if (list.size() == 1) {
      border_vertices.unite(pair.first, pair.second);
      border_edges.push_back(pair);
    }
  }
  std::map<size_t, size_t> loop_part;
  for (const auto& [a, b] : border_edges) {
    const Index f = sides[{a, b}][0].face;
    loop_part[border_vertices.find(a)] = part[f];
  }
  for (const auto& [root, p] : loop_part) ++r.components[p].borders;
  // The double cover of an orientable part falls apart into two copies; of a non-orientable one, not.
  std::vector<std::set<size_t>> cover_parts(r.components.size());
  for (size_t f = 0; f < nf; ++f) {
    cover_parts[part[f]].insert(cover.find(2 * f));
    cover_parts[part[f]].insert(cover.find(2 * f + 1));
  }
  for (size_t p = 0; p < r.components.size(); ++p) {
    ComponentTopology& c = r.components[p];
    c.orientable = cover_parts[p].size() == 2;
    c.chi = static_cast<long long>(c.vertices) - c.edges + c.faces;
    const long long handles = 2 - c.chi - c.borders;
    c.genus = c.orientable ? handles / 2 : handles;
    r.vertices += c.vertices;
    r.edges += c.edges;
    r.faces += c.faces;
    r.borders += c.borders;
    r.mobius_edges += c.mobius_edges;
    r.orientable = r.orientable && c.orientable;
  }
  r.chi = static_cast<long long>(r.vertices) - r.edges + r.faces;
  return out;
}

}  // namespace nome::test
