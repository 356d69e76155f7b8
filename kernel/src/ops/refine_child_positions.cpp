#include "ops/parallel_for.hpp"
#include "ops/refinement_level.hpp"

namespace nome {

// The position pass from a child level P, read through the topology of its parent G. P is numbered
// from G (refine_topology): its vertices are G's face points fp(f) = f, edge points ep(e) = F + e and
// vertex points vp(v) = F + E + v; its quad c (one per G corner) is (vp, ep(leaving edge), fp, ep(arriving
// edge)); its edges are the halves 2e, 2e+1 of G's edges and the face-interior edges 2E + c. So every
// neighbourhood of P is a short arithmetic walk over G's arrays, which are four times smaller and read in
// order, and P itself needs no arrays at all. Each sum below adds the same terms in the same order as
// refine_positions does over P's own fans (refine_positions.cpp), so both give the same bits.
template <class Grandparent>
void refine_child_positions(const Grandparent& g, std::span<const Vec3> in, VertexRules rules,
                            std::span<Vec3> out, int threads) {
  const Index nf = g.num_faces(), ne = g.num_edges(), nc = g.num_corners();
  const Index ep = nf, vp = nf + ne;                    // where P's edge and vertex points start in `in`
  const Index out_ep = nc, out_interior = nc + 2 * ne;  // P's edge points in `out`, its interior edges'
  const Index out_vp = 2 * (nc + ne);                   // P's vertex points in `out`
  const bool classic = rules.rule == SubdivisionRule::classic;

  // The classic rule's corner sums count each neighbour twice.
  auto smooth = [classic](const Vec3& here, const Vec3& edge_sum, const Vec3& face_sum, double n) {
    return smooth_vertex_point(here, classic ? edge_sum * 0.5 : edge_sum, face_sum, n);
  };

  // phase: G face by G face, what reads only that face: the face points of its P quads, the edge points
  // of its P interior edges (corner c's runs ep(leaving edge) -> fp, between quads c and next(c)), and the
  // vertex point of its P face point, whose fan is the face's quads (P corner 4c+2 sits between ep(edge
  // of c) and ep(edge of prev c); fan edge i is the interior edge of corner b + i - 1; never a crease).
  parallel_for(nf, threads, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f) {
      const Index b = g.face_begin(f), n = g.face_end(f) - b;
      for (Index c = b; c < b + n; ++c) {
        Vec3 sum = in[vp + g.corner_vertex(c)];
        sum += in[ep + g.corner_edge(c)];
        sum += in[f];
        sum += in[ep + g.corner_edge(g.prev_corner(c))];
        out[c] = sum * 0.25;
      }
      for (Index c = b; c < b + n; ++c) {
        const Vec3 sum = in[ep + g.corner_edge(c)] + in[f];
        out[out_interior + c] = (sum + out[c] + out[g.next_corner(c)]) * 0.25;
      }
      Vec3 face_sum(0.0), edge_sum(0.0);
      for (Index c = b; c < b + n; ++c) {
        face_sum += out[c];
        if (classic) edge_sum += in[ep + g.corner_edge(g.prev_corner(c))] + in[ep + g.corner_edge(c)];
      }
      if (!classic)
        for (Index i = 0; i < n; ++i) edge_sum += out[out_interior + b + (i == 0 ? n - 1 : i - 1)];
      out[out_vp + f] = smooth(in[f], edge_sum, face_sum, double(n));
    }
  });

  // phase: G edge by G edge: the edge points of its halves and the vertex point of its P edge point.
  // Half 2e runs vp(v0) -> ep(e) with P quads ca and, on the far side, nb (cb when e is Möbius: face b
  // then starts at v0 too); half 2e+1 runs ep(e) -> vp(v1). The edge point's fan: corners 4ca+1, 4na+3
  // and face b's two (in the order its direction gives), edges 2e, interior(ca), 2e+1, interior(cb). A
  // crease edge's halves are creases.
  parallel_for(ne, threads, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e) {
      const Index ca = g.edge_corner(e, 0), cb = g.edge_corner(e, 1), na = g.next_corner(ca);
      const Vec3& here = in[ep + e];
      const Vec3& a0 = in[vp + g.corner_vertex(ca)];
      const Vec3& a1 = in[vp + g.corner_vertex(na)];
      const Vec3 first = a0 + here;
      const Vec3 second = here + a1;
      Vec3& result = out[out_vp + nf + e];
      if (g.is_crease(e)) {
        out[out_ep + 2 * e] = first * 0.5;
        out[out_ep + 2 * e + 1] = second * 0.5;
        Vec3 sharp_sum(0.0);
        sharp_sum += a0;
        sharp_sum += a1;
        result = (6.0 * here + sharp_sum) * 0.125;
        continue;
      }
      const Index nb = g.next_corner(cb);
      const bool mobius = g.is_mobius(e);
      out[out_ep + 2 * e] = (first + out[ca] + out[mobius ? cb : nb]) * 0.25;
      out[out_ep + 2 * e + 1] = (second + out[na] + out[mobius ? nb : cb]) * 0.25;
      const Vec3& fa = in[g.corner_face(ca)];
      const Vec3& fb = in[g.corner_face(cb)];
      // Face b's quad at its edge's first corner (cb: neighbours fp(b), vp(v_cb)) and at the next one.
      const Vec3 at_cb = fb + in[vp + g.corner_vertex(cb)];
      const Vec3 at_nb = in[vp + g.corner_vertex(nb)] + fb;
      Vec3 face_sum(0.0), edge_sum(0.0);
      face_sum += out[ca];
      face_sum += out[na];
      face_sum += out[mobius ? nb : cb];
      face_sum += out[mobius ? cb : nb];
      if (classic) {
        edge_sum += fa + a0;
        edge_sum += a1 + fa;
        edge_sum += mobius ? at_nb : at_cb;
        edge_sum += mobius ? at_cb : at_nb;
      } else {
        edge_sum += out[out_ep + 2 * e];
        edge_sum += out[out_interior + ca];
        edge_sum += out[out_ep + 2 * e + 1];
        edge_sum += out[out_interior + cb];
      }
      result = smooth(here, edge_sum, face_sum, 4.0);
    }
  });

  // phase: G vertex by G vertex, the vertex points of P's vertex points: G's fan, quad c for corner c
  // (P corner 4c, between ep(edge of c) and ep(edge of prev c)), half 2e or 2e+1 for edge e; each half
  // keeps its parent's crease flag.
  parallel_for(g.num_vertices(), threads, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v) {
      const Vec3& here = in[vp + v];
      Vec3& result = out[out_vp + nf + ne + v];
      const auto edges = g.vertex_edges(v);
      Index sharp_count = 0;
      for (Index e : edges) sharp_count += g.is_crease(e) ? 1 : 0;
      if (rules.is_fixed(edges.size(), g.vertex_corners(v).size(), sharp_count)) {
        result = here;
      } else if (sharp_count == 2) {
        Vec3 sharp_sum(0.0);
        for (Index e : edges)
          if (g.is_crease(e)) sharp_sum += in[ep + e];
        result = (6.0 * here + sharp_sum) * 0.125;
      } else {
        Vec3 face_sum(0.0), edge_sum(0.0);
        for (Index c : g.vertex_corners(v)) {
          face_sum += out[c];
          if (classic) edge_sum += in[ep + g.corner_edge(c)] + in[ep + g.corner_edge(g.prev_corner(c))];
        }
        if (!classic)
          for (Index e : edges) edge_sum += out[out_ep + 2 * e + (g.edge_ends(e)[0] == v ? 0 : 1)];
        result = smooth(here, edge_sum, face_sum, double(edges.size()));
      }
    }
  });
}

template void refine_child_positions(const MeshLevelView&, std::span<const Vec3>, VertexRules,
                                     std::span<Vec3>, int);
template void refine_child_positions(const Refinement::Level&, std::span<const Vec3>, VertexRules,
                                     std::span<Vec3>, int);

}  // namespace nome
