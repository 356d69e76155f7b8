#include "ops/subdivision/tile_steps.hpp"

#include "nome/assert.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>

// Only these functions use AVX2, and the program picks them at run time (avx2_tile_steps). The target
// leaves out FMA on purpose: a fused multiply-add rounds once where the baseline steps round twice, so
// with it the compiler could contract a sum of products into different bits.
#define NOME_AVX2 __attribute__((target("avx2")))

namespace nome {
// Named as well as anonymous: a unity build puts other files' anonymous namespaces beside this one.
namespace avx2_steps {
namespace {

// A position in one register: x, y, z and a lane whose value no result reads.
using V = __m256d;

// x, y, z and the next position's x: reads 8 bytes past the position.
NOME_AVX2 inline V load(const Vec3& p) {
  return _mm256_loadu_pd(&p.x);
}
// A position of `out`, which another thread may be writing the next of: reads nothing past it.
NOME_AVX2 inline V load_alone(const Vec3& p) {
  return _mm256_maskload_pd(&p.x, _mm256_setr_epi64x(-1, -1, -1, 0));
}
// Writes the spare lane over the next position's x when `is_followed` (the same thread writes that
// position later, so it is correct in the end): one store instead of two.
NOME_AVX2 inline void store(Vec3& p, V v, bool is_followed = false) {
  if (is_followed) {
    _mm256_storeu_pd(&p.x, v);
    return;
  }
  _mm_storeu_pd(&p.x, _mm256_castpd256_pd128(v));
  _mm_store_sd(&p.z, _mm256_extractf128_pd(v, 1));
}

// The sums of ChildPass (child_pass.hpp) term by term in the same order.
NOME_AVX2 inline V face_point(V vertex, V leaving, V face, V arriving) {
  V sum = vertex;
  sum += leaving;
  sum += face;
  sum += arriving;
  return sum * 0.25;
}

// smooth_vertex_point with the classic rule's edge sum, which counts each neighbour twice.
NOME_AVX2 inline V smooth(V here, V edge_sum, V face_sum, double n) {
  const double inverse = 1.0 / n;
  return ((n - 2.0) * here + (edge_sum * 0.5 + face_sum) * inverse) * inverse;
}

// What the steps read of a pass, as plain pointers in a local: a vector store may alias anything, so each
// one would make the compiler load again what it reads through the pass.
struct Arrays {
  explicit Arrays(const LevelPass& p)
      : corner_edges(p.g.corner_edges.data()),
        corner_vertices(p.g.corner_vertices.data()),
        edge_corners(p.g.edge_corners.data()),
        edge_flags(p.g.edge_flags.data()),
        fan_corner_offsets(p.g.fan_corner_offsets.data()),
        fan_corners(p.g.fan_corners.data()),
        fan_edge_offsets(p.g.fan_edge_offsets.data()),
        fan_edges(p.g.fan_edges.data()),
        in(p.in.data()),
        edge_points(in + p.ep),
        vertex_points(in + p.vp),
        out(p.out.data()),
        out_edge_points(out + p.out_ep),
        out_interior(out + p.out_interior),
        out_vertex_points(out + p.out_vp),
        has_creases(p.has_creases) {}

  const Index *corner_edges, *corner_vertices;
  const std::array<Index, 2>* edge_corners;
  const std::uint8_t* edge_flags;
  const Index *fan_corner_offsets, *fan_corners, *fan_edge_offsets, *fan_edges;
  const Vec3 *in, *edge_points, *vertex_points;  // P's face points are `in` itself
  Vec3 *out, *out_edge_points, *out_interior, *out_vertex_points;
  bool has_creases;

  // P's edge point on the edge leaving `corner`, and its vertex point at the corner's vertex.
  NOME_AVX2 V edge_point(Index corner) const { return load(edge_points[corner_edges[corner]]); }
  NOME_AVX2 V vertex_point(Index corner) const { return load(vertex_points[corner_vertices[corner]]); }
};

// The corners after and before `c` in its quad.
inline Index next(Index c) {
  return (c & ~Index(3)) | ((c + 1) & 3);
}
inline Index prev(Index c) {
  return (c & ~Index(3)) | ((c + 3) & 3);
}

// ChildPass::quad_face on faces [first, last), whose points are written in increasing order.
NOME_AVX2 void faces(const LevelPass& pass, Index first, Index last) {
  const Arrays a(pass);
  for (Index f = first; f < last; ++f) {
    const Index b = 4 * f;
    const bool is_followed = f + 1 < last;
    const V centre = load(a.in[f]);
    const V e0 = a.edge_point(b), e1 = a.edge_point(b + 1), e2 = a.edge_point(b + 2),
            e3 = a.edge_point(b + 3);
    const V p0 = face_point(a.vertex_point(b), e0, centre, e3);
    const V p1 = face_point(a.vertex_point(b + 1), e1, centre, e0);
    const V p2 = face_point(a.vertex_point(b + 2), e2, centre, e1);
    const V p3 = face_point(a.vertex_point(b + 3), e3, centre, e2);
    store(a.out[b], p0, true);
    store(a.out[b + 1], p1, true);
    store(a.out[b + 2], p2, true);
    store(a.out[b + 3], p3, is_followed);
    store(a.out_interior[b], (e0 + centre + p0 + p1) * 0.25, true);
    store(a.out_interior[b + 1], (e1 + centre + p1 + p2) * 0.25, true);
    store(a.out_interior[b + 2], (e2 + centre + p2 + p3) * 0.25, true);
    store(a.out_interior[b + 3], (e3 + centre + p3 + p0) * 0.25, is_followed);
    V face_sum = _mm256_setzero_pd() + p0, edge_sum = _mm256_setzero_pd() + (e3 + e0);
    face_sum += p1;
    face_sum += p2;
    face_sum += p3;
    edge_sum += e0 + e1;
    edge_sum += e1 + e2;
    edge_sum += e2 + e3;
    store(a.out_vertex_points[f], smooth(centre, edge_sum, face_sum, 4.0), is_followed);
  }
}

// ReadyCorners, or every corner when `is_all_ready`: the tiles of the thread that starts at the first base
// face, where each face point an edge or a vertex reads was written by an earlier or the same tile (an edge
// or vertex goes with the last tile around it). The checks cost a tenth of the steps.
template <bool is_all_ready>
struct Ready {
  ReadyCorners corners;
  bool has(Index c) const {
    NOME_ASSERT(!is_all_ready || corners.has(c));
    return is_all_ready || corners.has(c);
  }
};

// ChildPass::edge on an edge that is not a crease; `out` is where its vertex point goes.
template <bool is_all_ready>
NOME_AVX2 inline void smooth_edge(const Arrays& a, Index e, Ready<is_all_ready> ready, Vec3& out,
                                  bool is_followed) {
  const Index ca = a.edge_corners[e][0], cb = a.edge_corners[e][1];
  const Index na = next(ca), nb = next(cb);
  const V here = load(a.edge_points[e]), a0 = a.vertex_point(ca), a1 = a.vertex_point(na);
  const V b0 = a.vertex_point(cb), b1 = a.vertex_point(nb), fa = load(a.in[ca >> 2]),
          fb = load(a.in[cb >> 2]);
  const V fp_ca = ready.has(ca) ? load_alone(a.out[ca]) : face_point(a0, here, fa, a.edge_point(prev(ca)));
  const V fp_na = ready.has(na) ? load_alone(a.out[na]) : face_point(a1, a.edge_point(na), fa, here);
  const V fp_cb = ready.has(cb) ? load_alone(a.out[cb]) : face_point(b0, here, fb, a.edge_point(prev(cb)));
  const V fp_nb = ready.has(nb) ? load_alone(a.out[nb]) : face_point(b1, a.edge_point(nb), fb, here);
  const bool mobius = a.edge_flags[e] & mobius_flag;
  const V far0 = mobius ? fp_cb : fp_nb, far1 = mobius ? fp_nb : fp_cb;
  store(a.out_edge_points[2 * e], (a0 + here + fp_ca + far0) * 0.25, true);
  store(a.out_edge_points[2 * e + 1], (here + a1 + fp_na + far1) * 0.25, is_followed);
  const V at_cb = fb + b0, at_nb = b1 + fb;
  V face_sum = _mm256_setzero_pd() + fp_ca, edge_sum = _mm256_setzero_pd() + (fa + a0);
  face_sum += fp_na;
  face_sum += far1;
  face_sum += far0;
  edge_sum += a1 + fa;
  edge_sum += mobius ? at_nb : at_cb;
  edge_sum += mobius ? at_cb : at_nb;
  store(out, smooth(here, edge_sum, face_sum, 4.0), is_followed);
}

// Crease edges take the baseline step.
template <bool is_all_ready>
NOME_AVX2 void edge_range(const LevelPass& pass, Index first, Index last, ReadyCorners ready) {
  const Arrays a(pass);
  Vec3* out = a.out_vertex_points + pass.nf;
  for (Index e = first; e < last; ++e) {
    if (a.has_creases && (a.edge_flags[e] & (sharp_flag | boundary_flag)))
      pass.edge(e, ready);
    else
      smooth_edge(a, e, Ready<is_all_ready>{ready}, out[e], e + 1 < last);
  }
}

NOME_AVX2 void edges(const LevelPass& pass, Index first, Index last, ReadyCorners ready) {
  if (ready.begin == 0)
    edge_range<true>(pass, first, last, ready);
  else
    edge_range<false>(pass, first, last, ready);
}

// ChildPass::vertex_point at a vertex of fan corners [begin, end) and `n` edges that is neither fixed nor on
// a crease.
template <bool is_all_ready>
NOME_AVX2 inline V smooth_vertex(const Arrays& a, Index v, Index begin, Index end, Index n,
                                 Ready<is_all_ready> ready) {
  const V here = load(a.vertex_points[v]);
  V face_sum = _mm256_setzero_pd(), edge_sum = _mm256_setzero_pd();
  for (Index i = begin; i < end; ++i) {
    const Index c = a.fan_corners[i];
    const V leaving = a.edge_point(c), arriving = a.edge_point(prev(c));
    face_sum += ready.has(c) ? load_alone(a.out[c]) : face_point(here, leaving, load(a.in[c >> 2]), arriving);
    edge_sum += leaving + arriving;
  }
  return smooth(here, edge_sum, face_sum, double(n));
}

// Fixed and crease vertices take the baseline step.
template <bool is_all_ready>
NOME_AVX2 void vertex_range(const LevelPass& pass, Index first, Index last, VertexRules rules,
                            ReadyCorners ready) {
  const Arrays a(pass);
  Vec3* out = a.out_vertex_points + pass.nf + pass.ne;
  for (Index v = first; v < last; ++v) {
    const Index edges_begin = a.fan_edge_offsets[v], edges = a.fan_edge_offsets[v + 1] - edges_begin;
    const Index corners_begin = a.fan_corner_offsets[v], corners_end = a.fan_corner_offsets[v + 1];
    Index sharp_count = 0;
    if (a.has_creases)
      for (Index i = edges_begin; i < edges_begin + edges; ++i)
        sharp_count += a.edge_flags[a.fan_edges[i]] & (sharp_flag | boundary_flag) ? 1 : 0;
    if (sharp_count == 2 || rules.is_fixed(edges, corners_end - corners_begin, sharp_count))
      out[v] = pass.vertex_point(v, rules, ready);
    else
      store(out[v], smooth_vertex(a, v, corners_begin, corners_end, edges, Ready<is_all_ready>{ready}),
            v + 1 < last);
  }
}

NOME_AVX2 void vertices(const LevelPass& pass, Index first, Index last, VertexRules rules,
                        ReadyCorners ready) {
  if (ready.begin == 0)
    vertex_range<true>(pass, first, last, rules, ready);
  else
    vertex_range<false>(pass, first, last, rules, ready);
}

}  // namespace
}  // namespace avx2_steps

const TileSteps* avx2_tile_steps() {
  static constexpr TileSteps steps{avx2_steps::faces, avx2_steps::edges, avx2_steps::vertices};
  return __builtin_cpu_supports("avx2") ? &steps : nullptr;
}

}  // namespace nome

#undef NOME_AVX2

#else

namespace nome {

const TileSteps* avx2_tile_steps() {
  return nullptr;
}

}  // namespace nome

#endif
