#include "support/random_manifold.hpp"

#include <cstdlib>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>

#include "support/shapes.hpp"
#include "support/union_find.hpp"

namespace nome::test {
namespace {

// Polygons with glued sides. Corner c of a face is also the side from corner c to the next corner;
// each side lies on an edge id and runs along the edge's own direction (forward) or against it.
struct Complex {
  std::vector<Index> face_offsets{0};
  std::vector<Index> corner_vertex;
  std::vector<Index> side_edge;
  std::vector<char> side_forward;
  std::vector<Index> face_part;
  Index num_vertices = 0;
  Index num_edges = 0;

  Index num_faces() const { return Index(face_offsets.size() - 1); }
  Index next(Index c, Index f) const { return c + 1 == face_offsets[f + 1] ? face_offsets[f] : c + 1; }
  Index prev(Index c, Index f) const { return c == face_offsets[f] ? face_offsets[f + 1] - 1 : c - 1; }
};

// A mesh without repeated vertices in a face, loops, or two edges on the same vertex pair: what a
// polygon soup can describe.
bool is_simple(const Complex& k) {
  std::map<std::pair<Index, Index>, Index> edge_of_pair;
  for (Index f = 0; f < k.num_faces(); ++f) {
    std::set<Index> seen;
    for (Index c = k.face_offsets[f]; c < k.face_offsets[f + 1]; ++c) {
      const Index a = k.corner_vertex[c], b = k.corner_vertex[k.next(c, f)];
      if (!seen.insert(a).second || a == b) return false;
      const auto [it, inserted] = edge_of_pair.emplace(std::minmax(a, b), k.side_edge[c]);
      if (!inserted && it->second != k.side_edge[c]) return false;
    }
  }
  return true;
}

// Each n-gon becomes n quads (vertex, edge point, face point, edge point), keeping its orientation:
// the topology of Catmull-Clark, written independently of the kernel.
Complex refine(const Complex& k) {
  Complex out;
  const Index nv = k.num_vertices, ne = k.num_edges;
  out.num_vertices = nv + ne + k.num_faces();
  out.num_edges = 2 * ne + Index(k.corner_vertex.size());
  auto edge_point = [&](Index e) { return nv + e; };
  for (Index f = 0; f < k.num_faces(); ++f) {
    for (Index c = k.face_offsets[f]; c < k.face_offsets[f + 1]; ++c) {
      const Index p = k.prev(c, f), e = k.side_edge[c], ep = k.side_edge[p];
      out.corner_vertex.insert(out.corner_vertex.end(),
                               {k.corner_vertex[c], edge_point(e), nv + ne + f, edge_point(ep)});
      // Half 2e runs from the edge's start to its midpoint, half 2e+1 from the midpoint to its end.
      out.side_edge.insert(out.side_edge.end(), {k.side_forward[c] ? 2 * e : 2 * e + 1, 2 * ne + c,
                                                 2 * ne + p, k.side_forward[p] ? 2 * ep + 1 : 2 * ep});
      out.side_forward.insert(out.side_forward.end(), {k.side_forward[c], 1, 0, k.side_forward[p]});
      out.face_offsets.push_back(Index(out.corner_vertex.size()));
      out.face_part.push_back(k.face_part[f]);
    }
  }
  return out;
}

struct Gluing {
  Complex complex;
  std::vector<ExpectedPart> parts;  // chi, orientability and borders: invariant under refinement
};

// Random polygons with randomly paired sides; none folds a corner onto itself (a cone point of one
// face, which no refinement can turn into a mesh).
Gluing random_gluing(std::mt19937& rng, const RandomManifoldOptions& options) {
  std::uniform_int_distribution<int> polygon_count(1, options.max_polygons);
  std::bernoulli_distribution is_quad(0.5), closed(options.closed_chance), twisted(options.twist_chance);
  const int np = polygon_count(rng);
  std::vector<Index> degrees(np);
  for (Index& d : degrees) d = is_quad(rng) ? 4 : 3;
  Index num_sides = std::accumulate(degrees.begin(), degrees.end(), Index(0));
  const bool is_closed = closed(rng);
  if (is_closed && num_sides % 2 == 1) {
    degrees[0] = 7 - degrees[0];
    num_sides += degrees[0] == 4 ? 1 : -1;
  }
  Index num_free = 0;
  if (!is_closed) {
    num_free = std::uniform_int_distribution<Index>(1, num_sides)(rng);
    if ((num_sides - num_free) % 2 == 1) --num_free;
    if (num_free == 0) num_free = 2;
  }

  Complex k;
  for (Index d : degrees) {
    k.face_offsets.push_back(k.face_offsets.back() + d);
    k.face_part.push_back(0);
  }
  std::vector<Index> face_of_side(num_sides);
  for (Index f = 0; f < k.num_faces(); ++f)
    std::fill(face_of_side.begin() + k.face_offsets[f], face_of_side.begin() + k.face_offsets[f + 1], f);

  std::vector<Index> order(num_sides);
  std::iota(order.begin(), order.end(), 0);
  UnionFind corners(num_sides);
  for (;;) {
    std::shuffle(order.begin(), order.end(), rng);
    k.side_edge.assign(num_sides, no_index);
    k.side_forward.assign(num_sides, 1);
    k.num_edges = 0;
    corners = UnionFind(num_sides);
    bool folds = false;
    const Index paired = num_sides - num_free;
    for (Index i = 0; i < paired; i += 2) {
      const Index s = order[i], t = order[i + 1];
      const bool twist = twisted(rng);
      k.side_edge[s] = k.side_edge[t] = k.num_edges++;
      k.side_forward[t] = twist;
      const Index s_end = k.next(s, face_of_side[s]), t_end = k.next(t, face_of_side[t]);
      // A regular join matches start to end (the two faces run along the edge in opposite directions).
      const std::pair<Index, Index> ties[2] = {{s, twist ? t : t_end}, {s_end, twist ? t_end : t}};
      for (const auto& [a, b] : ties) {
        folds = folds || a == b;
        corners.unite(a, b);
      }
    }
    if (folds) continue;
    for (Index i = paired; i < num_sides; ++i) k.side_edge[order[i]] = k.num_edges++;
    break;
  }
  std::map<size_t, Index> vertex_of_root;
  k.corner_vertex.resize(num_sides);
  for (Index c = 0; c < num_sides; ++c)
    k.corner_vertex[c] = vertex_of_root.emplace(corners.find(c), Index(vertex_of_root.size())).first->second;
  k.num_vertices = Index(vertex_of_root.size());

  // phase: what the gluing is. Parts and orientability by propagating a sign per face across joins.
  std::vector<std::vector<Index>> sides_of_edge(k.num_edges);
  for (Index c = 0; c < num_sides; ++c) sides_of_edge[k.side_edge[c]].push_back(c);
  std::vector<int> sign(k.num_faces(), 0);
  std::vector<char> part_orientable;
  Index num_parts = 0;
  for (Index f0 = 0; f0 < k.num_faces(); ++f0) {
    if (sign[f0] != 0) continue;
    const Index part = num_parts++;
    part_orientable.push_back(1);
    sign[f0] = 1;
    k.face_part[f0] = part;
    std::vector<Index> stack{f0};
    while (!stack.empty()) {
      const Index f = stack.back();
      stack.pop_back();
      for (Index c = k.face_offsets[f]; c < k.face_offsets[f + 1]; ++c) {
        const auto& pair = sides_of_edge[k.side_edge[c]];
        if (pair.size() != 2) continue;
        const Index g = face_of_side[pair[0] == c ? pair[1] : pair[0]];
        const int want = k.side_forward[pair[0]] == k.side_forward[pair[1]] ? -sign[f] : sign[f];
        if (sign[g] == 0) {
          sign[g] = want;
          k.face_part[g] = part;
          stack.push_back(g);
        } else if (sign[g] != want) {
          part_orientable[part] = 0;
        }
      }
    }
  }
  Gluing g;
  g.parts.resize(num_parts);
  for (Index p = 0; p < num_parts; ++p) g.parts[p].orientable = part_orientable[p];
  // chi = V - E + F of the glued polygons themselves, before any refinement.
  std::vector<std::set<Index>> part_vertices(num_parts);
  for (Index c = 0; c < num_sides; ++c)
    part_vertices[k.face_part[face_of_side[c]]].insert(k.corner_vertex[c]);
  for (Index p = 0; p < num_parts; ++p) g.parts[p].chi += (long long)part_vertices[p].size();
  for (Index f = 0; f < k.num_faces(); ++f) ++g.parts[k.face_part[f]].chi;
  for (const auto& sides : sides_of_edge) --g.parts[k.face_part[face_of_side[sides[0]]]].chi;
  // Border loops: the free sides joined at the vertices they share.
  UnionFind border(k.num_vertices);
  std::map<Index, Index> part_of_border_vertex;
  for (Index c = 0; c < num_sides; ++c) {
    if (sides_of_edge[k.side_edge[c]].size() != 1) continue;
    const Index a = k.corner_vertex[c], b = k.corner_vertex[k.next(c, face_of_side[c])];
    border.unite(a, b);
    part_of_border_vertex[a] = k.face_part[face_of_side[c]];
  }
  std::set<size_t> loops;
  for (const auto& [v, p] : part_of_border_vertex)
    if (loops.insert(border.find(v)).second) ++g.parts[p].borders;
  g.complex = std::move(k);
  return g;
}

}  // namespace

RandomManifold random_manifold(std::mt19937& rng, const RandomManifoldOptions& options) {
  Gluing gluing = random_gluing(rng, options);
  Complex k = std::move(gluing.complex);
  RandomManifold out;
  std::bernoulli_distribution refine_more(0.3);
  while (!is_simple(k) || (out.refinement_levels < 2 && refine_more(rng))) {
    if (out.refinement_levels == 3)
      throw std::logic_error("random_manifold: still not simple after 3 levels");
    k = refine(k);
    ++out.refinement_levels;
  }

  // phase: the soup, with some quads split into triangles along a diagonal that is not an edge yet.
  std::set<std::pair<Index, Index>> edges;
  for (Index f = 0; f < k.num_faces(); ++f)
    for (Index c = k.face_offsets[f]; c < k.face_offsets[f + 1]; ++c)
      edges.insert(std::minmax(k.corner_vertex[c], k.corner_vertex[k.next(c, f)]));
  std::vector<std::vector<Index>> faces;
  std::vector<Index> face_part;
  std::vector<long long> extra_edges(gluing.parts.size(), 0);
  std::bernoulli_distribution split(0.2), other_diagonal(0.5);
  for (Index f = 0; f < k.num_faces(); ++f) {
    std::vector<Index> vs(k.corner_vertex.begin() + k.face_offsets[f],
                          k.corner_vertex.begin() + k.face_offsets[f + 1]);
    if (vs.size() == 4 && split(rng)) {
      if (other_diagonal(rng)) std::rotate(vs.begin(), vs.begin() + 1, vs.end());
      if (edges.insert(std::minmax(vs[0], vs[2])).second) {
        faces.push_back({vs[0], vs[1], vs[2]});
        faces.push_back({vs[0], vs[2], vs[3]});
        face_part.insert(face_part.end(), 2, k.face_part[f]);
        ++extra_edges[k.face_part[f]];
        continue;
      }
    }
    faces.push_back(vs);
    face_part.push_back(k.face_part[f]);
  }
  std::vector<Index> order(faces.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);

  PolygonSoup soup;
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (Index v = 0; v < k.num_vertices; ++v)
    soup.add_vertex(Vec3(coordinate(rng), coordinate(rng), coordinate(rng)));
  std::map<Index, Index> new_part;  // gluing part -> position in first-face order
  std::vector<Index> old_part;
  for (Index i : order) {
    soup.add_face(faces[i]);
    if (new_part.emplace(face_part[i], Index(new_part.size())).second) old_part.push_back(face_part[i]);
  }

  // phase: counts by construction (vertex and edge ids of the complex, not vertex pairs).
  std::vector<std::set<Index>> part_vertices(gluing.parts.size()), part_edges(gluing.parts.size());
  std::vector<long long> part_faces(gluing.parts.size(), 0);
  for (Index f = 0; f < k.num_faces(); ++f)
    for (Index c = k.face_offsets[f]; c < k.face_offsets[f + 1]; ++c) {
      part_vertices[k.face_part[f]].insert(k.corner_vertex[c]);
      part_edges[k.face_part[f]].insert(k.side_edge[c]);
    }
  for (Index p : face_part) ++part_faces[p];
  for (Index p : old_part) {
    ExpectedPart e = gluing.parts[p];
    e.vertices = (long long)part_vertices[p].size();
    e.edges = (long long)part_edges[p].size() + extra_edges[p];
    e.faces = part_faces[p];
    if (e.vertices - e.edges + e.faces != e.chi)
      throw std::logic_error("random_manifold: refinement changed chi");
    out.parts.push_back(e);
  }

  std::bernoulli_distribution reversal_fraction(0.5);
  soup = reverse_random_faces(std::move(soup), reversal_fraction(rng) ? 0.3 : 0.0, rng);
  soup = rotate_corners(renumber_vertices(std::move(soup), rng), rng);
  out.soup = std::move(soup);
  return out;
}

unsigned seed_base() {
  const char* text = std::getenv("NOME_SEED");
  return text ? unsigned(std::strtoul(text, nullptr, 10)) : 0u;
}

}  // namespace nome::test
