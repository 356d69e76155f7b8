// Semi-sharp creases and corners after one Catmull-Clark level, against the crease rules computed here by
// hand on a jittered grid (OpenSubdiv's Catmark masks): an edge of weight w gets w times its midpoint and
// 1 - w times its smooth point (the midpoint from w = 1 up, while its halves stay sharp); a crease vertex
// whose weights decay to nothing blends (6v + a + b) / 8 with its smooth point by the mean decaying
// weight; a corner weight below 1 blends the vertex with its smooth point, from 1 up it stays.
#include <catch2/catch.hpp>

#include <random>

#include <glm/geometric.hpp>

#include "nome/mesh/mesh.hpp"
#include "nome/ops/subdivide.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

// A 4 x 4 grid of quads, every vertex jittered, with its vertices by column i and row j.
struct CreaseGrid {
  PolygonSoup soup;

  CreaseGrid() : soup(test::grid(4, 4)) {
    std::mt19937 rng{42};
    std::uniform_real_distribution<double> d(-0.2, 0.2);
    for (Vec3& p : soup.positions) p += Vec3(d(rng), d(rng), d(rng));
  }
  static Index id(int i, int j) { return Index(j * 5 + i); }
  Vec3 p(int i, int j) const { return soup.positions[id(i, j)]; }
  // The centroid of the quad whose lowest corner is (i, j).
  Vec3 face(int i, int j) const { return (p(i, j) + p(i + 1, j) + p(i + 1, j + 1) + p(i, j + 1)) / 4.0; }
  Vec3 midpoint_along_row(int i, int j) const { return (p(i, j) + p(i + 1, j)) / 2.0; }
  // The smooth edge point of (i, j)-(i+1, j): its ends and the two face points, a quarter each.
  Vec3 smooth_along_row(int i, int j) const {
    return (p(i, j) + p(i + 1, j) + face(i, j - 1) + face(i, j)) / 4.0;
  }
  // The smooth vertex point of an inner vertex of valence 4: 1/64 [1 6 1; 6 36 6; 1 6 1].
  Vec3 smooth_vertex(int i, int j) const {
    const Vec3 edges = p(i - 1, j) + p(i + 1, j) + p(i, j - 1) + p(i, j + 1);
    const Vec3 diagonals = p(i - 1, j - 1) + p(i + 1, j - 1) + p(i - 1, j + 1) + p(i + 1, j + 1);
    return (36.0 * p(i, j) + 6.0 * edges + diagonals) / 64.0;
  }
  // The crease vertex point between its row neighbours.
  Vec3 crease_vertex(int i, int j) const { return (6.0 * p(i, j) + p(i - 1, j) + p(i + 1, j)) / 8.0; }
};

struct CreaseLevel {
  Mesh base, child;
  Vec3 edge_point(Index a, Index b) const {
    for (Index e : base.vertex_edges(a))
      if (base.edge(e).other_vertex(a) == b) return child.position(base.num_faces() + e);
    FAIL("no edge");
    return {};
  }
  Vec3 vertex_point(Index v) const { return child.position(base.num_faces() + base.num_edges() + v); }
};

CreaseLevel crease_subdivided(const PolygonSoup& soup, CreaseMethod method) {
  CreaseLevel level{build_mesh(soup), {}};
  SubdivisionOptions options;
  options.creases.method = method;
  level.child = subdivide(level.base, options);
  return level;
}

// The smooth Catmull-Clark points of a level, for the level after it: face centroids, edge points (ends
// and face points a quarter each), vertex points (face average + neighbour average + (n - 2) v) / n.
Vec3 crease_centroid(const Mesh& m, Index f) {
  Vec3 sum(0.0);
  for (Index v : m.face_vertices(f)) sum += m.position(v);
  return sum / double(m.face_degree(f));
}
Vec3 crease_smooth_edge(const Mesh& m, Index e) {
  const Edge& edge = m.edge(e);
  return (m.position(edge.vertices[0]) + m.position(edge.vertices[1]) + crease_centroid(m, edge.faces[0]) +
          crease_centroid(m, edge.faces[1])) /
         4.0;
}
Vec3 crease_smooth_vertex(const Mesh& m, Index v) {
  Vec3 faces(0.0), neighbours(0.0);
  for (Index c : m.vertex_corners(v)) faces += crease_centroid(m, m.corner_face(c));
  for (Index e : m.vertex_edges(v)) neighbours += m.position(m.edge(e).other_vertex(v));
  const double n = double(m.vertex_edges(v).size());
  return (faces / double(m.vertex_corners(v).size()) + neighbours / n + (n - 2) * m.position(v)) / n;
}
Index crease_edge_between(const Mesh& m, Index a, Index b) {
  for (Index e : m.vertex_edges(a))
    if (m.edge(e).other_vertex(a) == b) return e;
  FAIL("no edge");
  return no_index;
}

void check_crease_point(const Vec3& got, const Vec3& expected) {
  INFO("got " << got.x << " " << got.y << " " << got.z << ", expected " << expected.x << " " << expected.y
              << " " << expected.z);
  CHECK(glm::length(got - expected) < 1e-12);
}

}  // namespace

TEST_CASE("semi-sharp edges below 1 blend their midpoints and smooth points by their weights", "[kernel]") {
  CreaseGrid g;
  const auto id = CreaseGrid::id;
  // A crease along row 2 from (1,2) to (3,2), weights 0.25 and 0.75; (3,1)-(3,2) of weight 1 and
  // (1,3)-(2,3) of weight 2.5, alone at their ends.
  g.soup.sharp_edges = {
      {id(1, 2), id(2, 2)}, {id(2, 2), id(3, 2)}, {id(3, 1), id(3, 2)}, {id(1, 3), id(2, 3)}};
  g.soup.sharp_edge_weights = {0.25f, 0.75f, 1.0f, 2.5f};
  for (const CreaseMethod method : {CreaseMethod::uniform, CreaseMethod::chaikin}) {
    INFO(to_string(method));
    const CreaseLevel m = crease_subdivided(g.soup, method);
    check_crease_point(m.edge_point(id(1, 2), id(2, 2)),
                       0.25 * g.midpoint_along_row(1, 2) + 0.75 * g.smooth_along_row(1, 2));
    check_crease_point(m.edge_point(id(2, 2), id(3, 2)),
                       0.75 * g.midpoint_along_row(2, 2) + 0.25 * g.smooth_along_row(2, 2));
    check_crease_point(m.edge_point(id(3, 1), id(3, 2)), (g.p(3, 1) + g.p(3, 2)) / 2.0);
    check_crease_point(m.edge_point(id(1, 3), id(2, 3)), g.midpoint_along_row(1, 3));
    // A smooth edge beside them keeps its smooth point.
    check_crease_point(m.edge_point(id(1, 1), id(2, 1)), g.smooth_along_row(1, 1));
    // (2,2): a crease whose weights both decay to nothing: blended by their mean, 0.5.
    check_crease_point(m.vertex_point(id(2, 2)), 0.5 * g.crease_vertex(2, 2) + 0.5 * g.smooth_vertex(2, 2));
    // (3,2): a crease turning down to (3,1), weights 0.75 and 1 that both decay: their mean, 0.875.
    check_crease_point(
        m.vertex_point(id(3, 2)),
        0.875 * (0.75 * g.p(3, 2) + 0.125 * (g.p(2, 2) + g.p(3, 1))) + 0.125 * g.smooth_vertex(3, 2));
    // (1,2): one semi-sharp edge, a dart: the smooth rule.
    check_crease_point(m.vertex_point(id(1, 2)), g.smooth_vertex(1, 2));
  }
}

TEST_CASE("a crease vertex whose weights do not all decay: uniform and Chaikin decay differ by hand",
          "[kernel]") {
  CreaseGrid g;
  const auto id = CreaseGrid::id;
  g.soup.sharp_edges = {{id(1, 2), id(2, 2)}, {id(2, 2), id(3, 2)}};
  g.soup.sharp_edge_weights = {0.125f, 1.25f};
  // Uniform: the 1.25 edge stays sharp below (0.25), so its point is the midpoint; at (2,2) the child is a
  // dart and only the 0.125 weight decays, so the crease counts for 0.125.
  const CreaseLevel uniform = crease_subdivided(g.soup, CreaseMethod::uniform);
  check_crease_point(uniform.edge_point(id(1, 2), id(2, 2)),
                     0.125 * g.midpoint_along_row(1, 2) + 0.875 * g.smooth_along_row(1, 2));
  check_crease_point(uniform.edge_point(id(2, 2), id(3, 2)), g.midpoint_along_row(2, 2));
  check_crease_point(uniform.vertex_point(id(2, 2)),
                     0.125 * g.crease_vertex(2, 2) + 0.875 * g.smooth_vertex(2, 2));
  // Chaikin: at (2,2) the 1.25 edge's child is 3/4 1.25 + 1/4 0.125 - 1 < 0, so its point blends by 1.25
  // (beyond the midpoint); both weights decay at (2,2), their mean 0.6875 weighs the crease.
  const CreaseLevel chaikin = crease_subdivided(g.soup, CreaseMethod::chaikin);
  check_crease_point(chaikin.edge_point(id(1, 2), id(2, 2)),
                     0.125 * g.midpoint_along_row(1, 2) + 0.875 * g.smooth_along_row(1, 2));
  check_crease_point(chaikin.edge_point(id(2, 2), id(3, 2)),
                     1.25 * g.midpoint_along_row(2, 2) - 0.25 * g.smooth_along_row(2, 2));
  check_crease_point(chaikin.vertex_point(id(2, 2)),
                     0.6875 * g.crease_vertex(2, 2) + 0.3125 * g.smooth_vertex(2, 2));
  // With weights that stay above 1 at both ends the crease rule holds whole, either way.
  g.soup.sharp_edge_weights = {2.5f, 3.0f};
  for (const CreaseMethod method : {CreaseMethod::uniform, CreaseMethod::chaikin}) {
    INFO(to_string(method));
    const CreaseLevel m = crease_subdivided(g.soup, method);
    check_crease_point(m.edge_point(id(1, 2), id(2, 2)), g.midpoint_along_row(1, 2));
    check_crease_point(m.vertex_point(id(2, 2)), g.crease_vertex(2, 2));
  }
}

TEST_CASE("corner weights: below 1 the vertex blends with its smooth point, from 1 up it stays", "[kernel]") {
  CreaseGrid g;
  const auto id = CreaseGrid::id;
  g.soup.sharp_vertices = {{id(1, 1), 0.25f}, {id(3, 3), 1.5f}, {id(2, 2), 1.0f}};
  for (const CreaseMethod method : {CreaseMethod::uniform, CreaseMethod::chaikin}) {
    INFO(to_string(method));
    const CreaseLevel m = crease_subdivided(g.soup, method);
    check_crease_point(m.vertex_point(id(1, 1)), 0.25 * g.p(1, 1) + 0.75 * g.smooth_vertex(1, 1));
    check_crease_point(m.vertex_point(id(3, 3)), g.p(3, 3));
    check_crease_point(m.vertex_point(id(2, 2)), g.p(2, 2));
    check_crease_point(m.vertex_point(id(1, 3)), g.smooth_vertex(1, 3));
    // A corner weighs on its vertex only: the edges around it stay smooth.
    check_crease_point(m.edge_point(id(1, 1), id(2, 1)), g.smooth_along_row(1, 1));
  }
}

TEST_CASE("a weight of 1.5 is a crease for one level and half a crease the next", "[kernel]") {
  CreaseGrid g;
  const auto id = CreaseGrid::id;
  g.soup.sharp_edges = {{id(1, 2), id(2, 2)}, {id(2, 2), id(3, 2)}};
  g.soup.sharp_edge_weights = {1.5f, 1.5f};
  for (const CreaseMethod method : {CreaseMethod::uniform, CreaseMethod::chaikin}) {
    INFO(to_string(method));
    const Mesh base = build_mesh(g.soup);
    SubdivisionOptions options;
    options.creases.method = method;
    const Mesh one = subdivide(base, options);
    options.levels = 2;
    const Mesh two = subdivide(base, options);
    const Index nf = base.num_faces(), ne = base.num_edges();
    // Level 1: the crease rules whole.
    const Index e = crease_edge_between(base, id(2, 2), id(3, 2));
    check_crease_point(one.position(nf + e), g.midpoint_along_row(2, 2));
    check_crease_point(one.position(nf + ne + id(2, 2)), g.crease_vertex(2, 2));
    // Level 2: the halves at (2,2) weigh 0.5.
    const Index v1 = nf + ne + id(2, 2), left = nf + crease_edge_between(base, id(1, 2), id(2, 2));
    const Index half = crease_edge_between(one, nf + e, v1);
    const Vec3 mid = (one.position(nf + e) + one.position(v1)) / 2.0;
    check_crease_point(two.position(one.num_faces() + half), 0.5 * mid + 0.5 * crease_smooth_edge(one, half));
    const Vec3 crease = (6.0 * one.position(v1) + one.position(left) + one.position(nf + e)) / 8.0;
    check_crease_point(two.position(one.num_faces() + one.num_edges() + v1),
                       0.5 * crease + 0.5 * crease_smooth_vertex(one, v1));
  }
}
