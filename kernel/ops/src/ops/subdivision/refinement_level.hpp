#pragma once

// Internal to subdivision: one refined level as flat arrays (every face a quad), a view giving a base
// Mesh the same accessors, and the topology and position passes written once for both.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "nome/buffer.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/ops/subdivide.hpp"

namespace nome {

inline constexpr std::uint8_t mobius_flag = 1;
inline constexpr std::uint8_t sharp_flag = 2;
inline constexpr std::uint8_t boundary_flag = 4;

// How much of a level refine_topology builds. The position pass into level k reads the full topology of
// level k-2 only (refine_child_positions), and the last level's quads come from the level two before it
// (refine_grandchild_quads): so the level before the last needs only its counts, and the two largest
// levels never get edges or fans.
enum class LevelDetail { counts, quads, full };

struct Refinement::Level {
  Index vertex_count = 0, edge_count = 0;
  Index num_vertices() const { return vertex_count; }
  Buffer<Index> corner_vertices;  // 4 per face; empty with LevelDetail::counts (no faces to read)
  Buffer<Index> corner_edges;     // with LevelDetail::full only
  // With LevelDetail::full only. An edge's end vertices are those of its first corner and the next one
  // (no array of their own, to bound the peak memory). Corner signs are left to Refinement::mesh().
  Buffer<std::array<Index, 2>> edge_corners;  // [1] is no_index on a border edge
  Buffer<std::uint8_t> edge_flags;
  Buffer<Index> fan_corner_offsets, fan_corners, fan_edge_offsets, fan_edges;
  Buffer<Vec3> positions;  // reused by each position pass (the last level's on request)

  Index num_faces() const { return Index(corner_vertices.size() / 4); }
  Index num_corners() const { return Index(corner_vertices.size()); }
  Index num_edges() const { return edge_count; }
  Index face_begin(Index f) const { return 4 * f; }
  Index face_end(Index f) const { return 4 * f + 4; }
  Index corner_face(Index c) const { return c >> 2; }
  Index next_corner(Index c) const { return (c & ~Index(3)) | ((c + 1) & 3); }
  Index prev_corner(Index c) const { return (c & ~Index(3)) | ((c + 3) & 3); }
  Index corner_vertex(Index c) const { return corner_vertices[c]; }
  Index corner_edge(Index c) const { return corner_edges[c]; }
  std::array<Index, 2> edge_ends(Index e) const {
    const Index c = edge_corners[e][0];
    return {corner_vertices[c], corner_vertices[next_corner(c)]};
  }
  Index edge_corner(Index e, int side) const { return edge_corners[e][side]; }
  // Whether corner c's vertex is the first end of the edge leaving it (edge_ends(corner_edge(c))[0]),
  // told by the numbering of a refined level's edges without reading the edge: corner 4p+k of a parent
  // corner p leaves along a half 2e (from the parent edge's first end: k = 0 on an even edge) or 2e+1 (from
  // its edge point: k = 3 on an odd one), or along an interior edge, which runs from its edge point (k = 1)
  // to the face point (k = 2). See refine_topology.cpp. Bit 2k + (edge odd) of a table: no branches.
  bool leaves_first_end(Index c) const {
    constexpr unsigned table = 0b10001101;  // k = 0: even; k = 1: any; k = 2: none; k = 3: odd
    return (table >> (2 * (c & 3) + (corner_edges[c] & 1))) & 1;
  }
  bool is_mobius(Index e) const { return edge_flags[e] & mobius_flag; }
  bool is_sharp(Index e) const { return edge_flags[e] & sharp_flag; }
  bool is_boundary(Index e) const { return edge_flags[e] & boundary_flag; }
  bool is_crease(Index e) const { return edge_flags[e] & (sharp_flag | boundary_flag); }
  std::span<const Index> vertex_corners(Index v) const {
    return {fan_corners.data() + fan_corner_offsets[v], fan_corner_offsets[v + 1] - fan_corner_offsets[v]};
  }
  std::span<const Index> vertex_edges(Index v) const {
    return {fan_edges.data() + fan_edge_offsets[v], fan_edge_offsets[v + 1] - fan_edge_offsets[v]};
  }
  // Where vertex v's fan starts (v = num_vertices(): the end of the last).
  Index fan_corner_offset(Index v) const { return fan_corner_offsets[v]; }
  Index fan_edge_offset(Index v) const { return fan_edge_offsets[v]; }
};

// A base Mesh seen through the accessors of a Level.
class MeshLevelView {
 public:
  explicit MeshLevelView(const Mesh& mesh) : m_(mesh) {}
  Index num_vertices() const { return m_.num_vertices(); }
  Index num_faces() const { return m_.num_faces(); }
  Index num_corners() const { return m_.num_corners(); }
  Index num_edges() const { return m_.num_edges(); }
  Index face_begin(Index f) const { return m_.face_offsets()[f]; }
  Index face_end(Index f) const { return m_.face_offsets()[f + 1]; }
  Index corner_face(Index c) const { return m_.corner_face(c); }
  Index next_corner(Index c) const { return m_.next_corner(c); }
  Index prev_corner(Index c) const { return m_.prev_corner(c); }
  Index corner_vertex(Index c) const { return m_.corner_vertex(c); }
  Index corner_edge(Index c) const { return m_.corner_edge(c); }
  std::array<Index, 2> edge_ends(Index e) const { return m_.edge(e).vertices; }
  Index edge_corner(Index e, int side) const { return m_.edge(e).corners[side]; }
  bool is_mobius(Index e) const { return m_.edge(e).is_mobius; }
  bool is_sharp(Index e) const { return m_.edge(e).is_sharp; }
  bool is_boundary(Index e) const { return m_.edge(e).is_boundary(); }
  bool is_crease(Index e) const { return m_.edge(e).is_sharp || m_.edge(e).is_boundary(); }
  std::span<const Index> vertex_corners(Index v) const { return m_.vertex_corners(v); }
  std::span<const Index> vertex_edges(Index v) const { return m_.vertex_edges(v); }
  Index fan_corner_offset(Index v) const { return m_.fan_corner_offsets()[v]; }
  Index fan_edge_offset(Index v) const { return m_.fan_edge_offsets()[v]; }

 private:
  const Mesh& m_;
};

// The quads of the level after P (P = the child of `grandparent`) straight from the grandparent's topology.
template <class Grandparent>
void refine_grandchild_quads(const Grandparent& grandparent, Refinement::Level& grandchild, int threads);

// The smooth vertex rule on a fan of n faces from the sums of its neighbours (or, for the report rule, of
// its new edge points) and of its face points: classic ((n-3) v + 2 avg(midpoints) + avg(faces)) / n =
// ((n-2) v + avg(neighbours) + avg(faces)) / n. One reciprocal instead of six divisions.
inline Vec3 smooth_vertex_point(const Vec3& here, const Vec3& edge_sum, const Vec3& face_sum, double n) {
  const double inverse = 1.0 / n;
  return ((n - 2.0) * here + (edge_sum + face_sum) * inverse) * inverse;
}

// The vertex rules a position pass applies beyond the crease count.
struct VertexRules {
  SubdivisionRule rule = SubdivisionRule::classic;
  bool is_lone_corner_fixed = false;  // a vertex of one face and two border edges stays put (edge and corner)

  // A vertex with this fan keeps its position: a corner (>= 3 creases), an isolated vertex, or a lone corner.
  bool is_fixed(size_t edges, size_t corners, Index creases) const {
    return creases >= 3 || edges == 0 || (is_lone_corner_fixed && edges == 2 && corners == 1);
  }
};

// The topology pass from `parent` (a Level or a MeshLevelView) into `child`, with the arrays `detail`
// asks for. Runs on `threads` threads.
template <class Parent>
void refine_topology(const Parent& parent, Refinement::Level& child, LevelDetail detail, int threads);

// The position pass into the level after `parent`: its face points, edge points and vertex points from
// the parent's positions. Used from the base mesh into level 1.
template <class Parent>
void refine_positions(const Parent& parent, std::span<const Vec3> in, VertexRules rules, std::span<Vec3> out,
                      int threads);

// The same pass from a child level P (positions `in`) into the level after it, reading only the topology
// of P's parent `grandparent`: the same results bit for bit, from arrays four times smaller.
template <class Grandparent>
void refine_child_positions(const Grandparent& grandparent, std::span<const Vec3> in, VertexRules rules,
                            std::span<Vec3> out, int threads);

struct BaseTiles;
struct LevelCounts;

// The classic rule's pass of refine_child_positions from a refined level G (level k >= 1; counts of levels
// 0 .. k), base face by base face: the same results bit for bit, in an order that keeps them in cache. With
// `is_vector_allowed`, in AVX2 instructions where the CPU has them (tile_steps.hpp): one more Vec3 after
// `in` must then be readable.
void refine_child_positions_by_tile(const Refinement::Level& grandparent, const BaseTiles& tiles,
                                    std::span<const LevelCounts> counts, std::span<const Vec3> in,
                                    VertexRules rules, std::span<Vec3> out, int threads,
                                    bool is_vector_allowed);

}  // namespace nome
