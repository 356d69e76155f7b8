#pragma once

// Internal to subdivision: the position pass from a child level through its parent's topology, element by
// element, shared by the drivers in refine_child_positions.cpp and the steps of tile_steps.cpp and
// tile_steps_avx2.cpp.

#include <type_traits>

#include "ops/subdivision/refinement_level.hpp"

namespace nome {

// The G corners whose P face points are already in `out`, written by this thread (see
// refine_child_positions_by_tile): read back there instead of made again. Empty in the phase-by-phase pass.
struct ReadyCorners {
  Index begin = 0, end = 0;
  bool has(Index c) const { return c - begin < end - begin; }
};

// The position pass from a child level P, read through the topology of its parent G. P is numbered
// from G (refine_topology): its vertices are G's face points fp(f) = f, edge points ep(e) = F + e and
// vertex points vp(v) = F + E + v; its quad c (one per G corner) is (vp, ep(leaving edge), fp, ep(arriving
// edge)); its edges are the halves 2e, 2e+1 of G's edges and the face-interior edges 2E + c. So every
// neighbourhood of P is a short arithmetic walk over G's arrays, which are four times smaller and read in
// order, and P itself needs no arrays at all. Each sum below adds the same terms in the same order as
// refine_positions does over P's own fans (refine_positions.cpp), so both give the same bits.
template <class Grandparent>
struct ChildPass {
  const Grandparent& g;
  std::span<const Vec3> in;
  std::span<Vec3> out;
  bool is_classic;
  bool has_creases = true;  // false: no edge of G is a crease, and their flags need not be read
  Index nf = g.num_faces(), ne = g.num_edges(), nc = g.num_corners();
  Index ep = nf, vp = nf + ne;                    // where P's edge and vertex points start in `in`
  Index out_ep = nc, out_interior = nc + 2 * ne;  // P's edge points in `out`, its interior edges'
  Index out_vp = 2 * (nc + ne);                   // P's vertex points in `out`

  // The classic rule's corner sums count each neighbour twice.
  Vec3 smooth(const Vec3& here, const Vec3& edge_sum, const Vec3& face_sum, double n) const {
    return smooth_vertex_point(here, is_classic ? edge_sum * 0.5 : edge_sum, face_sum, n);
  }
  // P's quad c: (vp(corner vertex), ep(leaving edge), fp(face), ep(arriving edge)).
  static Vec3 face_point(const Vec3& vertex, const Vec3& leaving, const Vec3& face, const Vec3& arriving) {
    Vec3 sum = vertex;
    sum += leaving;
    sum += face;
    sum += arriving;
    return sum * 0.25;
  }

  // G face f, what reads only that face: the face points of its P quads, the edge points of its P
  // interior edges (corner c's runs ep(leaving edge) -> fp, between quads c and next(c)), and the vertex
  // point of its P face point, whose fan is the face's quads (P corner 4c+2 sits between ep(edge of c)
  // and ep(edge of prev c); fan edge i is the interior edge of corner b + i - 1; never a crease). Each
  // face point is made once and kept for the next corner's interior edge, not read back.
  // The points around are read into locals once: `in` may alias `out` as far as the compiler knows, so a
  // read through it after a write to `out` would be a load again.
  void face(Index f) const {
    if constexpr (std::is_same_v<Grandparent, Refinement::Level>) {
      if (is_classic) return quad_face(f);
    }
    const Index b = g.face_begin(f), n = g.face_end(f) - b;
    const Vec3 centre = in[f];
    Vec3 arriving = in[ep + g.corner_edge(g.prev_corner(b))], leaving = in[ep + g.corner_edge(b)];
    const Vec3 first = face_point(in[vp + g.corner_vertex(b)], leaving, centre, arriving);
    Vec3 here = first, face_sum(0.0), edge_sum(0.0);
    for (Index c = b; c < b + n; ++c) {
      const Index next = g.next_corner(c);
      const Vec3 next_leaving = next == b ? leaving : in[ep + g.corner_edge(next)];
      const Vec3 there =
          next == b ? first : face_point(in[vp + g.corner_vertex(next)], next_leaving, centre, leaving);
      out[c] = here;
      out[out_interior + c] = (leaving + centre + here + there) * 0.25;
      face_sum += here;
      if (is_classic) edge_sum += arriving + leaving;
      arriving = leaving;
      leaving = next_leaving;
      here = there;
    }
    if (!is_classic)
      for (Index i = 0; i < n; ++i) edge_sum += out[out_interior + b + (i == 0 ? n - 1 : i - 1)];
    out[out_vp + f] = smooth(centre, edge_sum, face_sum, double(n));
  }

  // face() for a quad of a refined level and the classic rule, written out corner by corner: the same sums
  // in the same order, in a sixth fewer instructions than the loop (no values carried between corners).
  void quad_face(Index f) const {
    const Index b = 4 * f;
    const Vec3 centre = in[f];
    const Vec3 e0 = in[ep + g.corner_edge(b)], e1 = in[ep + g.corner_edge(b + 1)];
    const Vec3 e2 = in[ep + g.corner_edge(b + 2)], e3 = in[ep + g.corner_edge(b + 3)];
    const Vec3 p0 = face_point(in[vp + g.corner_vertex(b)], e0, centre, e3);
    const Vec3 p1 = face_point(in[vp + g.corner_vertex(b + 1)], e1, centre, e0);
    const Vec3 p2 = face_point(in[vp + g.corner_vertex(b + 2)], e2, centre, e1);
    const Vec3 p3 = face_point(in[vp + g.corner_vertex(b + 3)], e3, centre, e2);
    out[b] = p0;
    out[b + 1] = p1;
    out[b + 2] = p2;
    out[b + 3] = p3;
    out[out_interior + b] = (e0 + centre + p0 + p1) * 0.25;
    out[out_interior + b + 1] = (e1 + centre + p1 + p2) * 0.25;
    out[out_interior + b + 2] = (e2 + centre + p2 + p3) * 0.25;
    out[out_interior + b + 3] = (e3 + centre + p3 + p0) * 0.25;
    Vec3 face_sum(0.0), edge_sum(0.0);
    face_sum += p0;
    face_sum += p1;
    face_sum += p2;
    face_sum += p3;
    edge_sum += e3 + e0;
    edge_sum += e0 + e1;
    edge_sum += e1 + e2;
    edge_sum += e2 + e3;
    out[out_vp + f] = smooth(centre, edge_sum, face_sum, 4.0);
  }

  // G edge e: the edge points of its halves and the vertex point of its P edge point. Half 2e runs
  // vp(v0) -> ep(e) with P quads ca and, on the far side, nb (cb when e is Möbius: face b then starts at
  // v0 too); half 2e+1 runs ep(e) -> vp(v1). The edge point's fan: corners 4ca+1, 4na+3 and face b's two
  // (in the order its direction gives), edges 2e, interior(ca), 2e+1, interior(cb). A crease edge's
  // halves are creases.
  void edge(Index e, ReadyCorners ready = {}) const {
    const Index ca = g.edge_corner(e, 0), cb = g.edge_corner(e, 1), na = g.next_corner(ca);
    const Vec3& here = in[ep + e];
    const Vec3& a0 = in[vp + g.corner_vertex(ca)];
    const Vec3& a1 = in[vp + g.corner_vertex(na)];
    const Vec3 first = a0 + here;
    const Vec3 second = here + a1;
    Vec3& result = out[out_vp + nf + e];
    if (has_creases && g.is_crease(e)) {
      out[out_ep + 2 * e] = first * 0.5;
      out[out_ep + 2 * e + 1] = second * 0.5;
      Vec3 sharp_sum(0.0);
      sharp_sum += a0;
      sharp_sum += a1;
      result = (6.0 * here + sharp_sum) * 0.125;
      return;
    }
    const Index nb = g.next_corner(cb);
    const bool mobius = g.is_mobius(e);
    const Vec3& fa = in[g.corner_face(ca)];
    const Vec3& fb = in[g.corner_face(cb)];
    const Vec3& b0 = in[vp + g.corner_vertex(cb)];
    const Vec3& b1 = in[vp + g.corner_vertex(nb)];
    // The four face points around, made again unless `ready` has them (as in vertex_point).
    const Vec3 fp_ca =
        ready.has(ca) ? out[ca] : face_point(a0, here, fa, in[ep + g.corner_edge(g.prev_corner(ca))]);
    const Vec3 fp_na = ready.has(na) ? out[na] : face_point(a1, in[ep + g.corner_edge(na)], fa, here);
    const Vec3 fp_cb =
        ready.has(cb) ? out[cb] : face_point(b0, here, fb, in[ep + g.corner_edge(g.prev_corner(cb))]);
    const Vec3 fp_nb = ready.has(nb) ? out[nb] : face_point(b1, in[ep + g.corner_edge(nb)], fb, here);
    const Vec3 half0 = (first + fp_ca + (mobius ? fp_cb : fp_nb)) * 0.25;
    const Vec3 half1 = (second + fp_na + (mobius ? fp_nb : fp_cb)) * 0.25;
    out[out_ep + 2 * e] = half0;
    out[out_ep + 2 * e + 1] = half1;
    // Face b's quad at its edge's first corner (cb: neighbours fp(b), vp(v_cb)) and at the next one.
    const Vec3 at_cb = fb + b0;
    const Vec3 at_nb = b1 + fb;
    Vec3 face_sum(0.0), edge_sum(0.0);
    face_sum += fp_ca;
    face_sum += fp_na;
    face_sum += mobius ? fp_nb : fp_cb;
    face_sum += mobius ? fp_cb : fp_nb;
    if (is_classic) {
      edge_sum += fa + a0;
      edge_sum += a1 + fa;
      edge_sum += mobius ? at_nb : at_cb;
      edge_sum += mobius ? at_cb : at_nb;
    } else {
      edge_sum += half0;
      edge_sum += out[out_interior + ca];
      edge_sum += half1;
      edge_sum += out[out_interior + cb];
    }
    result = smooth(here, edge_sum, face_sum, 4.0);
  }

  // G vertex v, the vertex point of P's vertex point: G's fan, quad c for corner c (P corner 4c, between
  // ep(edge of c) and ep(edge of prev c)), half 2e or 2e+1 for edge e; each half keeps its parent's crease
  // flag.
  Vec3 vertex_point(Index v, VertexRules rules, ReadyCorners ready = {}) const {
    const Vec3& here = in[vp + v];
    const auto edges = g.vertex_edges(v);
    Index sharp_count = 0;
    if (has_creases)
      for (Index e : edges) sharp_count += g.is_crease(e) ? 1 : 0;
    if (rules.is_fixed(edges.size(), g.vertex_corners(v).size(), sharp_count)) return here;
    if (sharp_count == 2) {
      Vec3 sharp_sum(0.0);
      for (Index e : edges)
        if (g.is_crease(e)) sharp_sum += in[ep + e];
      return (6.0 * here + sharp_sum) * 0.125;
    }
    // The face points around are made again from what the edge sum reads anyway unless `ready` has them:
    // scattered reads of a region far larger than the cache cost more than the sums.
    Vec3 face_sum(0.0), edge_sum(0.0);
    for (Index c : g.vertex_corners(v)) {
      const Vec3& leaving = in[ep + g.corner_edge(c)];
      const Vec3& arriving = in[ep + g.corner_edge(g.prev_corner(c))];
      face_sum += ready.has(c) ? out[c] : face_point(here, leaving, in[g.corner_face(c)], arriving);
      if (is_classic) edge_sum += leaving + arriving;
    }
    if (!is_classic)
      for (Index e : edges) edge_sum += out[out_ep + 2 * e + (g.edge_ends(e)[0] == v ? 0 : 1)];
    return smooth(here, edge_sum, face_sum, double(edges.size()));
  }
};

}  // namespace nome
