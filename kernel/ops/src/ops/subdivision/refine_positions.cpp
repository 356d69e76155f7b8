#include "ops/subdivision/refinement_level.hpp"
#include "support/parallel_for.hpp"

namespace nome {

// Report 004 section 4.1, written as gathers so that each child position is computed once, by one
// thread, from its parent's neighbourhood: face points, then edge points (which read face points),
// then vertex points (which read both).
template <class Parent>
void refine_positions(const Parent& p, std::span<const Vec3> in, VertexRules rules, std::span<Vec3> out,
                      int threads) {
  const SubdivisionRule rule = rules.rule;
  const Index nf = p.num_faces(), ne = p.num_edges();
  parallel_for(nf, threads, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f) {
      const Index b = p.face_begin(f), n = p.face_end(f) - b;
      Vec3 sum = in[p.corner_vertex(b)];
      for (Index i = 1; i < n; ++i) sum += in[p.corner_vertex(b + i)];
      out[f] = sum * (1.0 / n);
    }
  });
  parallel_for(ne, threads, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e) {
      const auto& ends = p.edge_ends(e);
      const Vec3 sum = in[ends[0]] + in[ends[1]];
      if (p.is_crease(e)) {
        out[nf + e] = sum * 0.5;
      } else {
        const Index fa = p.corner_face(p.edge_corner(e, 0)), fb = p.corner_face(p.edge_corner(e, 1));
        out[nf + e] = (sum + out[fa] + out[fb]) * 0.25;
      }
    }
  });
  parallel_for(p.num_vertices(), threads, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v) {
      const Vec3& here = in[v];
      Vec3& result = out[nf + ne + v];
      const auto edges = p.vertex_edges(v);
      Index sharp_count = 0;
      for (Index e : edges) sharp_count += p.is_crease(e) ? 1 : 0;
      if (rules.is_fixed(edges.size(), p.vertex_corners(v).size(), sharp_count)) {
        result = here;
      } else if (sharp_count == 2) {  // crease: (6v + a + b) / 8
        Vec3 sharp_sum(0.0);
        for (Index e : edges) {
          if (!p.is_crease(e)) continue;
          const auto ends = p.edge_ends(e);
          sharp_sum += in[ends[0] == v ? ends[1] : ends[0]];
        }
        result = (6.0 * here + sharp_sum) * 0.125;
      } else {
        // An interior vertex: each neighbour is next to two of its corners, one in each face of the
        // edge between them (whichever way the faces run), so the corners give twice the neighbour sum.
        Vec3 face_sum(0.0), edge_sum(0.0);
        for (Index c : p.vertex_corners(v)) {
          face_sum += out[p.corner_face(c)];
          if (rule == SubdivisionRule::classic)
            edge_sum += in[p.corner_vertex(p.next_corner(c))] + in[p.corner_vertex(p.prev_corner(c))];
        }
        if (rule == SubdivisionRule::classic) {
          edge_sum *= 0.5;
        } else {
          for (Index e : edges) edge_sum += out[nf + e];
        }
        result = smooth_vertex_point(here, edge_sum, face_sum, double(edges.size()));
      }
    }
  });
}

template void refine_positions(const MeshLevelView&, std::span<const Vec3>, VertexRules, std::span<Vec3>,
                               int);

}  // namespace nome
