#include <emmintrin.h>

#include <algorithm>
#include <array>
#include <type_traits>
#include <vector>

#include "ops/subdivision/refinement_level.hpp"
#include "support/parallel_for.hpp"

namespace nome {
namespace {

using Level = Refinement::Level;

// The child of parent edge `e` on the side of its end vertex `v`.
template <class Parent>
Index half_edge_child(const Parent& p, Index e, Index v) {
  return 2 * e + (p.edge_ends(e)[0] == v ? 0 : 1);
}

// The children, on corner c's side, of the edges leaving and arriving at c. A refined level tells which
// end is which from its numbering (Level::leaves_first_end): two dependent scattered reads fewer per edge
// (an edge's ends are distinct there, so the arriving edge's first end is c's vertex when it is not
// prev(c)'s).
template <class Parent>
std::array<Index, 2> corner_halves(const Parent& p, Index c, Index leaving, Index arriving) {
  if constexpr (std::is_same_v<Parent, Level>) {
    return {2 * leaving + (p.leaves_first_end(c) ? 0 : 1),
            2 * arriving + (p.leaves_first_end(p.prev_corner(c)) ? 1 : 0)};
  } else {
    const Index v = p.corner_vertex(c);
    return {half_edge_child(p, leaving, v), half_edge_child(p, arriving, v)};
  }
}

// Each parent corner c becomes child quad c: (vertex point, edge point of the edge leaving c, face
// point, edge point of the edge arriving at c), which keeps the parent face's orientation.
template <class Parent>
void child_corners(const Parent& p, Level& child, bool with_edges, int threads) {
  const Index nf = p.num_faces(), ne = p.num_edges();
  parallel_for(p.num_corners(), threads, [&](Index begin, Index end) {
    for (Index c = begin; c < end; ++c) {
      const Index v = p.corner_vertex(c), pc = p.prev_corner(c);
      const Index out = p.corner_edge(c), in = p.corner_edge(pc);
      Index* q = child.corner_vertices.data() + 4 * size_t(c);
      q[0] = nf + ne + v;
      q[1] = nf + out;
      q[2] = p.corner_face(c);
      q[3] = nf + in;
      if (!with_edges) continue;
      const auto [out_half, in_half] = corner_halves(p, c, out, in);
      Index* qe = child.corner_edges.data() + 4 * size_t(c);
      qe[0] = out_half;
      qe[1] = 2 * ne + c;
      qe[2] = 2 * ne + pc;
      qe[3] = in_half;
    }
  });
}

// Parent edge e gives edges 2e (from its first end to the edge point) and 2e+1 (on to its second
// end), keeping its flags; parent corner c gives the face-interior edge 2E+c from the edge point of
// its leaving edge to the face point, never Möbius, never sharp.
template <class Parent>
void child_edges(const Parent& p, Level& child, int threads) {
  const Index ne = p.num_edges();
  parallel_for(ne, threads, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e) {
      const Index ca = p.edge_corner(e, 0), cb = p.edge_corner(e, 1), na = p.next_corner(ca);
      const std::uint8_t flags = (p.is_mobius(e) ? mobius_flag : 0) | (p.is_sharp(e) ? sharp_flag : 0) |
                                 (cb == no_index ? boundary_flag : 0);
      child.edge_flags[2 * e] = child.edge_flags[2 * e + 1] = flags;
      if (cb == no_index) {
        child.edge_corners[2 * e] = {4 * ca, no_index};
        child.edge_corners[2 * e + 1] = {4 * na + 3, no_index};
      } else if (flags & mobius_flag) {  // face b also starts at v0
        child.edge_corners[2 * e] = {4 * ca, 4 * cb};
        child.edge_corners[2 * e + 1] = {4 * na + 3, 4 * p.next_corner(cb) + 3};
      } else {  // face b starts at v1
        child.edge_corners[2 * e] = {4 * ca, 4 * p.next_corner(cb) + 3};
        child.edge_corners[2 * e + 1] = {4 * na + 3, 4 * cb};
      }
    }
  });
  parallel_for(p.num_corners(), threads, [&](Index begin, Index end) {
    for (Index c = begin; c < end; ++c) {
      child.edge_corners[2 * ne + c] = {4 * c + 1, 4 * p.next_corner(c) + 2};
      child.edge_flags[2 * ne + c] = 0;
    }
  });
}

// Fan sizes of the child vertices as CSR offsets: a face point has the face's degree, an edge point
// 4 corners and 4 edges (2 and 3 on a border), a vertex point its parent's fan. Written in parallel: the
// face points' offsets are the parent's face offsets, the vertex points' its fan offsets, and the edge
// points' follow from the border edges before each, counted range by range first.
template <class Parent>
void child_fan_offsets(const Parent& p, Level& child, int threads) {
  const Index nf = p.num_faces(), ne = p.num_edges(), nv = p.num_vertices(), nc = p.num_corners();
  auto& co = child.fan_corner_offsets;
  auto& eo = child.fan_edge_offsets;
  resize_for_overwrite(co, size_t(nf) + ne + nv + 1);
  resize_for_overwrite(eo, co.size());
  co[0] = eo[0] = 0;
  parallel_for(nf, threads, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f) co[f + 1] = eo[f + 1] = p.face_end(f);
  });
  // One part a thread, as parallel_for splits the edges.
  const Index parts = parallel_parts(ne, threads);
  const Index part = (ne + parts - 1) / parts;
  std::vector<Index> borders_before(parts + 1, 0);
  const auto each_part = [&](const auto& body) {
    parallel_for(
        parts, threads,
        [&](Index begin, Index end) {
          for (Index t = begin; t < end; ++t) body(t, std::min(ne, t * part), std::min(ne, (t + 1) * part));
        },
        1);
  };
  each_part([&](Index t, Index begin, Index end) {
    for (Index e = begin; e < end; ++e) borders_before[t + 1] += p.is_boundary(e) ? 1 : 0;
  });
  for (Index t = 0; t < parts; ++t) borders_before[t + 1] += borders_before[t];
  each_part([&](Index t, Index begin, Index end) {
    Index borders = borders_before[t];
    for (Index e = begin; e < end; ++e) {
      borders += p.is_boundary(e) ? 1 : 0;
      co[nf + e + 1] = nc + 4 * (e + 1) - 2 * borders;
      eo[nf + e + 1] = nc + 4 * (e + 1) - borders;
    }
  });
  const Index corners_before = co[nf + ne], edges_before = eo[nf + ne];
  parallel_for(nv, threads, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v) {
      co[nf + ne + v + 1] = corners_before + p.fan_corner_offset(v + 1);
      eo[nf + ne + v + 1] = edges_before + p.fan_edge_offset(v + 1);
    }
  });
}

// The fans themselves, in order (see Mesh).
template <class Parent>
void child_fans(const Parent& p, Level& child, int threads) {
  const Index nf = p.num_faces(), ne = p.num_edges();
  child_fan_offsets(p, child, threads);
  resize_for_overwrite(child.fan_corners, child.fan_corner_offsets.back());
  resize_for_overwrite(child.fan_edges, child.fan_edge_offsets.back());
  Index* fc = child.fan_corners.data();
  Index* fe = child.fan_edges.data();
  const Index* co = child.fan_corner_offsets.data();
  const Index* eo = child.fan_edge_offsets.data();

  // Face point: child quads of corners c0..c(n-1) in face order; edge i (2E + c(i-1)) lies between
  // quads i-1 and i.
  parallel_for(nf, threads, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f) {
      const Index b = p.face_begin(f), n = p.face_end(f) - b;
      for (Index i = 0; i < n; ++i) {
        fc[co[f] + i] = 4 * (b + i) + 2;
        fe[eo[f] + i] = 2 * ne + b + (i == 0 ? n - 1 : i - 1);
      }
    }
  });
  // Edge point: half 2e, quad of face a at v0, interior edge of face a, quad of face a at v1, half 2e+1,
  // then face b's two quads around its interior edge.
  parallel_for(ne, threads, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e) {
      const Index ca = p.edge_corner(e, 0), cb = p.edge_corner(e, 1), na = p.next_corner(ca);
      Index* corners = fc + co[nf + e];
      Index* edges = fe + eo[nf + e];
      corners[0] = 4 * ca + 1;
      corners[1] = 4 * na + 3;
      edges[0] = 2 * e;
      edges[1] = 2 * ne + ca;
      edges[2] = 2 * e + 1;
      if (cb == no_index) continue;
      const Index nb = p.next_corner(cb);
      const bool mobius = p.is_mobius(e);
      corners[2] = mobius ? 4 * nb + 3 : 4 * cb + 1;
      corners[3] = mobius ? 4 * cb + 1 : 4 * nb + 3;
      edges[3] = 2 * ne + cb;
    }
  });
  // Vertex point: the parent's fan, corner by corner and edge by edge.
  parallel_for(p.num_vertices(), threads, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v) {
      const auto corners = p.vertex_corners(v);
      const auto edges = p.vertex_edges(v);
      Index* cs = fc + co[nf + ne + v];
      Index* es = fe + eo[nf + ne + v];
      for (size_t i = 0; i < corners.size(); ++i) cs[i] = 4 * corners[i];
      for (size_t i = 0; i < edges.size(); ++i) es[i] = half_edge_child(p, edges[i], v);
    }
  });
}

// Frees the edges and fans of a level built without them (left by an earlier build, see
// Refinement::rebuild).
void drop_adjacency(Level& level) {
  level.edge_corners = {};
  level.edge_flags = {};
  level.fan_corner_offsets = level.fan_corners = level.fan_edge_offsets = level.fan_edges = {};
}

}  // namespace

template <class Parent>
void refine_topology(const Parent& p, Level& child, LevelDetail detail, int threads) {
  const size_t nc = p.num_corners();
  const bool full = detail == LevelDetail::full;
  child.vertex_count = p.num_faces() + p.num_edges() + p.num_vertices();
  child.edge_count = Index(2 * size_t(p.num_edges()) + nc);
  resize_for_overwrite(child.corner_vertices, detail == LevelDetail::counts ? 0 : 4 * nc);
  resize_for_overwrite(child.corner_edges, full ? 4 * nc : 0);
  if (detail != LevelDetail::counts) child_corners(p, child, full, threads);
  if (!full) {
    drop_adjacency(child);
    return;
  }
  resize_for_overwrite(child.edge_corners, child.edge_count);
  resize_for_overwrite(child.edge_flags, child.edge_count);
  child_edges(p, child, threads);
  child_fans(p, child, threads);
}

namespace {

// refine_grandchild_quads over the faces [begin, end) of a refined level, whose faces are all quads: the
// four corners of a face side by side in the lanes of SSE2 registers (x86-64's baseline), written as 16
// stores of four corners each instead of 64 of one (the scalar loop was bound by its stores).
void level_grandchild_quads(const Level& g, Index* out, Index begin, Index end) {
  const Index nf = g.num_faces(), ne = g.num_edges(), nc = g.num_corners();
  const Index ep = nc, vp = nc + 2 * ne + nc;
  const __m128i lanes = _mm_setr_epi32(0, 1, 2, 3);
  // Level::leaves_first_end for the four corners of a face: ((odd ^ flip) & keep) | always.
  const __m128i flip = _mm_setr_epi32(1, 0, 0, 0), keep = _mm_setr_epi32(1, 0, 0, 1);
  const __m128i always = _mm_setr_epi32(0, 1, 0, 0), one = _mm_set1_epi32(1);
  const auto previous = [](__m128i x) { return _mm_shuffle_epi32(x, _MM_SHUFFLE(2, 1, 0, 3)); };
  const auto splat = [](Index x) { return _mm_set1_epi32(int(x)); };
  const auto load = [](const Index* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); };
  for (Index f = begin; f < end; ++f) {
    const Index b = 4 * f;
    const __m128i vertex = load(g.corner_vertices.data() + b), leaving = load(g.corner_edges.data() + b);
    const __m128i arriving = previous(leaving);
    const __m128i corner = _mm_add_epi32(splat(b), lanes);
    const __m128i first_end =
        _mm_or_si128(_mm_and_si128(_mm_xor_si128(_mm_and_si128(leaving, one), flip), keep), always);
    // Per lane k (corner b + k), child quad b + k's vertices j = 0..3 and edges j = 0..3, as grandchild
    // points.
    const __m128i vertices[4] = {_mm_add_epi32(vertex, splat(vp + nf + ne)),
                                 _mm_add_epi32(leaving, splat(vp + nf)), splat(vp + f),
                                 _mm_add_epi32(arriving, splat(vp + nf))};
    const __m128i edges[4] = {
        _mm_add_epi32(_mm_add_epi32(leaving, leaving), _mm_sub_epi32(splat(ep + 1), first_end)),
        _mm_add_epi32(corner, splat(ep + 2 * ne)), _mm_add_epi32(previous(corner), splat(ep + 2 * ne)),
        _mm_add_epi32(_mm_add_epi32(arriving, arriving), _mm_add_epi32(splat(ep), previous(first_end)))};
    Index* q = out + 16 * std::size_t(b);
    for (int j = 0; j < 4; ++j) {
      // Rows k of (vertex j, edge j, the corner, edge j - 1): a 4x4 transpose.
      const __m128i low = _mm_unpacklo_epi32(vertices[j], edges[j]);
      const __m128i high = _mm_unpackhi_epi32(vertices[j], edges[j]);
      const __m128i low_corner = _mm_unpacklo_epi32(corner, edges[(j + 3) & 3]);
      const __m128i high_corner = _mm_unpackhi_epi32(corner, edges[(j + 3) & 3]);
      const __m128i rows[4] = {_mm_unpacklo_epi64(low, low_corner), _mm_unpackhi_epi64(low, low_corner),
                               _mm_unpacklo_epi64(high, high_corner), _mm_unpackhi_epi64(high, high_corner)};
      for (int k = 0; k < 4; ++k) _mm_storeu_si128(reinterpret_cast<__m128i*>(q + 16 * k + 4 * j), rows[k]);
    }
  }
}

}  // namespace

// Grandparent corner c gives child quad c (child_corners), whose corner 4c+k gives grandchild quad
// 4c+k: (vertex point of the child quad's k-th vertex, edge point of its k-th edge, face point of child
// quad c, edge point of its edge k-1). The 16 corners of c are written in one go, in order.
template <class Grandparent>
void refine_grandchild_quads(const Grandparent& g, Level& grandchild, int threads) {
  const Index nf = g.num_faces(), ne = g.num_edges(), nc = g.num_corners();
  const Index child_edges = 2 * ne + nc;
  const Index ep = nc, vp = nc + child_edges;  // the grandchild's edge and vertex points
  grandchild.vertex_count = vp + nf + ne + g.num_vertices();
  grandchild.edge_count = 2 * child_edges + 4 * nc;
  resize_for_overwrite(grandchild.corner_vertices, 16 * size_t(nc));
  grandchild.corner_edges = {};
  drop_adjacency(grandchild);
  Index* out = grandchild.corner_vertices.data();
  if constexpr (std::is_same_v<Grandparent, Level>) {
    parallel_for(nf, threads, [&](Index begin, Index end) { level_grandchild_quads(g, out, begin, end); });
  } else {
    parallel_for(nc, threads, [&](Index begin, Index end) {
      for (Index c = begin; c < end; ++c) {
        const Index v = g.corner_vertex(c), pc = g.prev_corner(c);
        const Index leaving = g.corner_edge(c), arriving = g.corner_edge(pc);
        const auto [leaving_half, arriving_half] = corner_halves(g, c, leaving, arriving);
        const Index vertices[4] = {vp + nf + ne + v, vp + nf + leaving, vp + g.corner_face(c),
                                   vp + nf + arriving};
        const Index edges[4] = {ep + leaving_half, ep + 2 * ne + c, ep + 2 * ne + pc, ep + arriving_half};
        Index* q = out + 16 * size_t(c);
        for (int k = 0; k < 4; ++k) {
          q[4 * k] = vertices[k];
          q[4 * k + 1] = edges[k];
          q[4 * k + 2] = c;
          q[4 * k + 3] = edges[(k + 3) & 3];
        }
      }
    });
  }
}

template void refine_topology(const MeshLevelView&, Level&, LevelDetail, int);
template void refine_topology(const Level&, Level&, LevelDetail, int);
template void refine_grandchild_quads(const MeshLevelView&, Level&, int);
template void refine_grandchild_quads(const Level&, Level&, int);

}  // namespace nome
