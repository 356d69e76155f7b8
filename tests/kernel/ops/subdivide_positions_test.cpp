#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "nome/ops/subdivide.hpp"
#include "support/point_sets.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

Buffer<Vec3> subdivided(const PolygonSoup& soup, int levels,
                        SubdivisionRule rule = SubdivisionRule::classic) {
  return subdivide(build_mesh(soup), {levels, rule}).positions();
}

// Jitters every vertex so that no position is an accident of symmetry.
PolygonSoup jittered(PolygonSoup soup, double amount) {
  std::mt19937 rng{42};
  std::uniform_real_distribution<double> d(-amount, amount);
  for (Vec3& p : soup.positions) p += Vec3(d(rng), d(rng), d(rng));
  return soup;
}

// The Möbius band of test::mobius_band travelled twice: its orientation double cover, an annulus.
PolygonSoup mobius_double_cover(const PolygonSoup& band, Index segments, Index width) {
  PolygonSoup s;
  for (Index i = 0; i < 2 * segments; ++i)
    for (Index j = 0; j <= width; ++j) {
      const Index jj = i < segments ? j : width - j;
      s.add_vertex(band.positions[(i % segments) * (width + 1) + jj]);
    }
  auto id = [&](Index i, Index j) { return (i % (2 * segments)) * (width + 1) + j; };
  for (Index i = 0; i < 2 * segments; ++i)
    for (Index j = 0; j < width; ++j) s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return s;
}

Vec3 weighted(const PolygonSoup& s, std::initializer_list<std::pair<Index, double>> terms) {
  Vec3 sum(0.0);
  for (auto [v, w] : terms) sum += w * s.positions[v];
  return sum;
}

}  // namespace

TEST_CASE("positions do not depend on orientation, numbering or where a face's corner list starts",
          "[kernel]") {
  const std::pair<const char*, PolygonSoup> shapes[] = {
      {"torus", jittered(test::torus(7, 5), 0.05)},
      {"mobius band", jittered(test::mobius_band(8, 2), 0.05)},
      {"klein bottle", jittered(test::klein_bottle(8, 6), 0.05)},
      {"cube", jittered(test::cube(), 0.1)},
      {"projective plane", jittered(test::projective_plane(), 0.1)},
      {"grid with a crease",
       [] {
         PolygonSoup g = jittered(test::grid(4, 4), 0.1);
         g.sharp_edges = {{10, 11}, {11, 12}, {12, 13}, {12, 17}};
         return g;
       }()},
  };
  std::mt19937 rng{42};
  for (const auto& [name, soup] : shapes) {
    for (SubdivisionRule rule : {SubdivisionRule::classic, SubdivisionRule::report}) {
      for (int levels = 1; levels <= 3; ++levels) {
        INFO(name << ", " << levels << " levels, rule " << int(rule));
        const auto reference = subdivided(soup, levels, rule);
        CHECK(test::compare_point_sets(reference,
                                       subdivided(test::reverse_random_faces(soup, 0.5, rng), levels, rule),
                                       1e-12) == "");
        CHECK(test::compare_point_sets(
                  reference, subdivided(test::renumber_vertices(soup, rng), levels, rule), 1e-12) == "");
        CHECK(test::compare_point_sets(reference, subdivided(test::rotate_corners(soup, rng), levels, rule),
                                       1e-12) == "");
      }
    }
  }
}

TEST_CASE("a Möbius band subdivides as its orientation double cover does, each point twice", "[kernel]") {
  for (Index width : {1u, 3u}) {
    const Index segments = 9;
    const PolygonSoup band = test::mobius_band(segments, width);
    const PolygonSoup cover = mobius_double_cover(band, segments, width);
    for (int levels = 1; levels <= 3; ++levels) {
      INFO("width " << width << ", " << levels << " levels");
      CHECK(test::compare_point_sets(subdivided(band, levels), subdivided(cover, levels), 1e-12, 2) == "");
    }
  }
}

TEST_CASE("semi-sharp creases and corners across a Möbius seam subdivide as on the double cover",
          "[kernel]") {
  const Index segments = 9, width = 3;
  PolygonSoup band = test::mobius_band(segments, width);
  PolygonSoup cover = mobius_double_cover(band, segments, width);
  const auto band_vertex = [&](Index i, Index j) { return (i % segments) * (width + 1) + j; };
  const auto cover_vertex = [&](Index i, Index j) { return (i % (2 * segments)) * (width + 1) + j; };
  // A ring along the band's line j = 1, which comes back as j = 2 across the seam, weight 2.5; two
  // rungs across the band at the seam, 0.7; a corner of weight 1.3 on the band's first vertex.
  for (Index i = 0; i < segments; ++i) {
    const Index far = i + 1 == segments ? band_vertex(0, width - 1) : band_vertex(i + 1, 1);
    band.sharp_edges.emplace_back(band_vertex(i, 1), far);
    band.sharp_edge_weights.push_back(2.5f);
  }
  for (Index j = 1; j < 3; ++j) {
    band.sharp_edges.emplace_back(band_vertex(0, j - 1), band_vertex(0, j));
    band.sharp_edge_weights.push_back(0.7f);
  }
  band.sharp_vertices = {{band_vertex(0, 0), 1.3f}};
  // The cover carries each mark on both of its copies.
  for (Index i = 0; i < 2 * segments; ++i) {
    const Index jj = i < segments ? 1 : width - 1;
    cover.sharp_edges.emplace_back(cover_vertex(i, jj), cover_vertex(i + 1, jj));
    cover.sharp_edge_weights.push_back(2.5f);
  }
  for (Index half : {0u, segments})
    for (Index j = 1; j < 3; ++j) {
      const Index a = half == 0 ? j - 1 : width - (j - 1), b = half == 0 ? j : width - j;
      cover.sharp_edges.emplace_back(cover_vertex(half, a), cover_vertex(half, b));
      cover.sharp_edge_weights.push_back(0.7f);
    }
  cover.sharp_vertices = {{cover_vertex(0, 0), 1.3f}, {cover_vertex(segments, width), 1.3f}};
  for (CreaseMethod method : {CreaseMethod::uniform, CreaseMethod::chaikin})
    for (int levels = 1; levels <= 3; ++levels) {
      INFO(to_string(method) << ", " << levels << " levels");
      SubdivisionOptions options{levels};
      options.creases.method = method;
      const Buffer<Vec3> ours = subdivide(build_mesh(band), options).positions();
      CHECK(test::compare_point_sets(ours, subdivide(build_mesh(cover), options).positions(), 1e-12, 2) ==
            "");
      // The weights matter: without them the band refines elsewhere.
      PolygonSoup plain = band;
      plain.sharp_edges.clear(), plain.sharp_edge_weights.clear(), plain.sharp_vertices.clear();
      CHECK(test::compare_point_sets(ours, subdivide(build_mesh(plain), options).positions(), 1e-6) != "");
    }
}

TEST_CASE("cube, level 1: face points, edge points and both vertex rules by hand", "[kernel]") {
  const Mesh cube = build_mesh(test::cube());
  const std::vector<Vec3> face_points = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  for (SubdivisionRule rule : {SubdivisionRule::classic, SubdivisionRule::report}) {
    const Mesh m = subdivide(cube, {1, rule});
    REQUIRE(m.num_vertices() == 26);
    REQUIRE(m.num_faces() == 24);
    for (Index f = 0; f < 6; ++f) CHECK(m.position(f) == face_points[f]);
    // Edge points: (v0 + v1 + f1 + f2) / 4 puts them at 3/4 along both face directions.
    for (Index e = 0; e < 12; ++e) {
      const Vec3 p = m.position(6 + e);
      const Vec3 mid =
          0.5 * (cube.position(cube.edge(e).vertices[0]) + cube.position(cube.edge(e).vertices[1]));
      CHECK(p == 0.75 * mid);
    }
    // Vertex points: classic ((n-2) v + avg(neighbours) + avg(faces)) / n = 5/9 v; report
    // ((n-2) v + avg(edge points) + avg(faces)) / n = 11/18 v.
    const double scale = rule == SubdivisionRule::classic ? 5.0 / 9.0 : 11.0 / 18.0;
    for (Index v = 0; v < 8; ++v) {
      const Vec3 expected = scale * cube.position(v);
      for (int k = 0; k < 3; ++k) CHECK(m.position(18 + v)[k] == Approx(expected[k]).epsilon(1e-15));
    }
  }
}

TEST_CASE("on a regular grid the points follow the bicubic B-spline stencils", "[kernel]") {
  const PolygonSoup g = jittered(test::grid(6, 6), 0.3);
  const Mesh base = build_mesh(g);
  auto id = [](Index i, Index j) { return j * 7 + i; };
  const Index nf = base.num_faces(), ne = base.num_edges();
  // Vertex (3,3): 1/64 [1 6 1; 6 36 6; 1 6 1] for classic, and the report's rule works out to
  // 1/128 (84 v + 8 per edge neighbour + 3 per diagonal one). (Report 004 section 4.1.3 prints 92, 6, 3,
  // which does not follow from its own formula.)
  const Index v = id(3, 3);
  const Vec3 edge_nbrs = weighted(g, {{id(2, 3), 1}, {id(4, 3), 1}, {id(3, 2), 1}, {id(3, 4), 1}});
  const Vec3 diag_nbrs = weighted(g, {{id(2, 2), 1}, {id(4, 2), 1}, {id(2, 4), 1}, {id(4, 4), 1}});
  const Vec3 classic = (36.0 * g.positions[v] + 6.0 * edge_nbrs + diag_nbrs) / 64.0;
  const Vec3 report = (84.0 * g.positions[v] + 8.0 * edge_nbrs + 3.0 * diag_nbrs) / 128.0;
  const Mesh c = subdivide(base, {1, SubdivisionRule::classic});
  const Mesh r = subdivide(base, {1, SubdivisionRule::report});
  for (int k = 0; k < 3; ++k) {
    CHECK(c.position(nf + ne + v)[k] == Approx(classic[k]).margin(1e-14));
    CHECK(r.position(nf + ne + v)[k] == Approx(report[k]).margin(1e-14));
  }
  // Edge (3,3)-(4,3): 1/16 [1 6 1] on both columns; face (3,3): the bilinear average.
  Index edge = no_index;
  for (Index e : base.vertex_edges(v))
    if (base.edge(e).other_vertex(v) == id(4, 3)) edge = e;
  REQUIRE(edge != no_index);
  const Vec3 edge_point = weighted(g, {{id(3, 3), 6. / 16},
                                       {id(4, 3), 6. / 16},
                                       {id(3, 2), 1. / 16},
                                       {id(4, 2), 1. / 16},
                                       {id(3, 4), 1. / 16},
                                       {id(4, 4), 1. / 16}});
  const Index face = 3 * 6 + 3;
  const Vec3 face_point = weighted(g, {{id(3, 3), .25}, {id(4, 3), .25}, {id(4, 4), .25}, {id(3, 4), .25}});
  for (int k = 0; k < 3; ++k) {
    CHECK(c.position(nf + edge)[k] == Approx(edge_point[k]).margin(1e-14));
    CHECK(c.position(face)[k] == Approx(face_point[k]).margin(1e-14));
  }
}

TEST_CASE("crease, corner and border rules on an open grid", "[kernel]") {
  PolygonSoup g = jittered(test::grid(4, 4), 0.3);
  auto id = [](Index i, Index j) { return j * 5 + i; };
  // A crease along row j = 2 that reaches the border at (0,2) and (4,2), and a spur (2,2)-(2,3).
  g.sharp_edges = {{id(0, 2), id(1, 2)},
                   {id(1, 2), id(2, 2)},
                   {id(2, 2), id(3, 2)},
                   {id(3, 2), id(4, 2)},
                   {id(2, 2), id(2, 3)}};
  const Mesh base = build_mesh(g);
  const Mesh m = subdivide(base, {1, SubdivisionRule::classic});
  const Index vp = base.num_faces() + base.num_edges();
  auto p = [&](Index i, Index j) { return g.positions[id(i, j)]; };
  auto near = [](const Vec3& a, const Vec3& b) { return glm::length(a - b) < 1e-14; };
  // Crease vertex (1,2): (6v + a + b) / 8 along the crease.
  CHECK(near(m.position(vp + id(1, 2)), (6.0 * p(1, 2) + p(0, 2) + p(2, 2)) / 8.0));
  // Three sharp edges: a corner, unchanged. Border meets crease at (0,2): two border edges + one sharp.
  CHECK(m.position(vp + id(2, 2)) == p(2, 2));
  CHECK(m.position(vp + id(0, 2)) == p(0, 2));
  // A border vertex follows its border; so does the grid's own corner (2 sharp edges, not 3).
  CHECK(near(m.position(vp + id(2, 0)), (6.0 * p(2, 0) + p(1, 0) + p(3, 0)) / 8.0));
  CHECK(near(m.position(vp + id(0, 0)), (6.0 * p(0, 0) + p(1, 0) + p(0, 1)) / 8.0));
  // The spur's far end (2,3) has one sharp edge: the smooth rule, as on a regular grid.
  const Vec3 smooth = (36.0 * p(2, 3) + 6.0 * (p(1, 3) + p(3, 3) + p(2, 2) + p(2, 4)) + p(1, 2) + p(3, 2) +
                       p(1, 4) + p(3, 4)) /
                      64.0;
  CHECK(near(m.position(vp + id(2, 3)), smooth));
  // Sharp and border edges get their midpoints.
  for (Index e = 0; e < base.num_edges(); ++e) {
    const Edge& edge = base.edge(e);
    if (!edge.is_sharp && !edge.is_boundary()) continue;
    CHECK(near(m.position(base.num_faces() + e),
               0.5 * (base.position(edge.vertices[0]) + base.position(edge.vertices[1]))));
  }
}

TEST_CASE("the position pass alone reproduces a full refinement after the base moves", "[kernel]") {
  const Mesh base = build_mesh(test::mobius_band(64, 8));
  Refinement refinement(base, 3);
  Buffer<Vec3> out(refinement.num_vertices());
  refinement.refine_positions(base, SubdivisionRule::classic, out);
  CHECK(out == subdivide(base, {3, SubdivisionRule::classic}).positions());
  Mesh moved = base;
  for (Vec3& p : moved.positions()) p = Vec3(2.0 * p.x, p.y + p.z * p.z, p.z - 1.0);
  refinement.refine_positions(moved, SubdivisionRule::report, out);
  CHECK(out == subdivide(moved, {3, SubdivisionRule::report}).positions());
  // Two threads split the work, not the arithmetic: bit for bit the same.
  const Mesh torus = build_mesh(test::torus(64, 32));
  Refinement big(torus, 4);
  Buffer<Vec3> one(big.num_vertices()), two(big.num_vertices());
  big.refine_positions(torus, SubdivisionRule::classic, one, 1);
  big.refine_positions(torus, SubdivisionRule::classic, two, 2);
  CHECK(one == two);
  const std::span<const Vec3> own = big.refine_positions(torus, SubdivisionRule::classic, 2);
  CHECK(std::equal(own.begin(), own.end(), one.begin(), one.end()));
  const auto quads = big.quad_vertices();
  const Mesh full = big.mesh(torus, two);
  CHECK(std::equal(quads.begin(), quads.end(), full.corner_vertices().begin(), full.corner_vertices().end()));
}

TEST_CASE("refining several levels at once gives the bits of refining one level at a time", "[kernel]") {
  // From level 2 on, the position pass reads the topology two levels up (refine_child_positions); one
  // level at a time always runs the plain pass over the parent's own fans and builds every level in full.
  PolygonSoup creased = jittered(test::grid(3, 3), 0.2);
  creased.sharp_edges = {{5, 6}, {6, 7}, {6, 10}};
  const std::vector<PolygonSoup> soups = {
      jittered(test::mobius_band(12, 3), 0.05), creased,
      jittered(test::disjoint_union(test::tetrahedron(), test::cube()), 0.1), test::klein_bottle(8, 6),
      test::projective_plane()};
  for (const PolygonSoup& soup : soups)
    for (SubdivisionRule rule : {SubdivisionRule::classic, SubdivisionRule::report}) {
      Mesh stepwise = build_mesh(soup);
      for (int level = 1; level <= 3; ++level) {
        stepwise = subdivide(stepwise, {1, rule});
        const Mesh at_once = subdivide(build_mesh(soup), {level, rule});
        CHECK(at_once.positions() == stepwise.positions());
        CHECK(at_once.corner_vertices() == stepwise.corner_vertices());
        // The last level's quads alone come from the level two before it (refine_grandchild_quads).
        const Refinement refinement(build_mesh(soup), level);
        const auto quads = refinement.quad_vertices();
        CHECK(std::equal(quads.begin(), quads.end(), stepwise.corner_vertices().begin(),
                         stepwise.corner_vertices().end()));
      }
      Refinement refinement(build_mesh(soup), 3);
      Buffer<Vec3> two_threads(refinement.num_vertices());
      refinement.refine_positions(build_mesh(soup), rule, two_threads, 2);
      CHECK(two_threads == stepwise.positions());
    }
}

TEST_CASE("the classic pass by base-face tiles gives the bits of one level at a time", "[kernel]") {
  // From level 3 on, the classic rule's position pass runs tile by tile over the base faces (base_tiles.hpp):
  // every element of a level must be made once, by the same sums, whatever the tile. Unwritten outputs
  // would stay NaN.
  PolygonSoup with_lone_vertex = jittered(test::disjoint_union(test::tetrahedron(), test::grid(3, 2)), 0.1);
  with_lone_vertex.add_vertex(Vec3(5.0, 5.0, 5.0));
  std::vector<Index> pentagon;
  for (int k = 0; k < 5; ++k)
    pentagon.push_back(
        with_lone_vertex.add_vertex(Vec3(std::cos(1.3 * k), std::sin(1.3 * k), 0.1 * k - 3.0)));
  with_lone_vertex.add_face(pentagon);
  PolygonSoup creased = jittered(test::torus(6, 5), 0.05);
  creased.sharp_edges = {{0, 1}, {1, 2}, {2, 3}, {0, 5}};
  // No crease anywhere (the pass then reads no edge flags), and a vertex of no face.
  PolygonSoup closed_with_lone_vertex = jittered(test::torus(7, 4), 0.05);
  closed_with_lone_vertex.add_vertex(Vec3(0.0, 0.0, 4.0));
  const std::vector<PolygonSoup> soups = {
      jittered(test::klein_bottle(8, 6), 0.05),
      test::projective_plane(),
      jittered(test::mobius_band(9, 2), 0.05),
      with_lone_vertex,
      creased,
      jittered(test::disjoint_union(test::cube(), test::torus(5, 4)), 0.1),
      closed_with_lone_vertex};
  for (size_t i = 0; i < soups.size(); ++i) {
    INFO("shape " << i);
    const Mesh base = build_mesh(soups[i]);
    Mesh stepwise = base;
    for (int level = 1; level <= 4; ++level) {
      stepwise = subdivide(stepwise, {1, SubdivisionRule::classic});
      for (int threads : {1, 2}) {
        Refinement refinement(base, level, BoundaryMode::edge_only, threads);
        Buffer<Vec3> out(refinement.num_vertices(), Vec3(std::nan("")));
        refinement.refine_positions(base, SubdivisionRule::classic, out, threads);
        CHECK(out == stepwise.positions());
        // The quads too: a refined level's edge ends and the last level's quads are told arithmetically.
        CHECK(std::ranges::equal(refinement.quad_vertices(), stepwise.corner_vertices()));
      }
    }
  }
  // Enough tiles that two threads split them: each thread reads back only the face points it wrote.
  const Mesh torus = build_mesh(jittered(test::torus(32, 32), 0.01));
  Refinement refinement(torus, 5);
  Buffer<Vec3> one(refinement.num_vertices()), two(refinement.num_vertices(), Vec3(std::nan("")));
  refinement.refine_positions(torus, SubdivisionRule::classic, one, 1);
  refinement.refine_positions(torus, SubdivisionRule::classic, two, 2);
  CHECK(one == two);
}
