#include <catch2/catch.hpp>

#include "nome/error.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/ops/subdivide.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

// Every fan is a closed or open chain: consecutive corners share the fan edge between them.
void check_fans(const Mesh& m) {
  for (Index v = 0; v < m.num_vertices(); ++v) {
    const auto corners = m.vertex_corners(v);
    const auto edges = m.vertex_edges(v);
    if (corners.empty()) continue;
    REQUIRE(edges.size() == corners.size() + (m.is_boundary_vertex(v) ? 1 : 0));
    for (size_t i = 0; i < corners.size(); ++i) {
      const Index c = corners[i];
      REQUIRE(m.corner_vertex(c) == v);
      const Index before = edges[i];
      const Index after = edges[(i + 1) % edges.size()];
      const Index in = m.corner_edge(m.prev_corner(c)), out = m.corner_edge(c);
      CHECK(((before == in && after == out) || (before == out && after == in)));
      // The sign flips exactly across Möbius edges.
      if (i + 1 < corners.size()) {
        CHECK(m.corner_sign(corners[i + 1]) == (m.edge(after).is_mobius ? -1 : 1) * m.corner_sign(c));
      }
    }
    CHECK(m.corner_sign(corners.front()) == 1);
  }
}

}  // namespace

TEST_CASE("a tetrahedron builds 4 vertices, 6 edges, 4 faces, no border", "[kernel]") {
  const Mesh m = build_mesh(test::tetrahedron());
  CHECK(m.num_vertices() == 4);
  CHECK(m.num_edges() == 6);
  CHECK(m.num_faces() == 4);
  CHECK(m.num_boundary_loops() == 0);
  CHECK(m.num_components() == 1);
  for (const Edge& e : m.edges()) CHECK_FALSE(e.is_mobius);
  check_fans(m);
}

TEST_CASE("interior fans of a cube list three faces in cyclic order", "[kernel]") {
  const Mesh m = build_mesh(test::cube());
  CHECK(m.num_edges() == 12);
  for (Index v = 0; v < 8; ++v) {
    CHECK(m.vertex_corners(v).size() == 3);
    CHECK(m.vertex_edges(v).size() == 3);
    CHECK_FALSE(m.is_boundary_vertex(v));
  }
  check_fans(m);
}

TEST_CASE("boundary fans start and end at a border edge", "[kernel]") {
  const Mesh m = build_mesh(test::grid(3, 2));
  CHECK(m.num_boundary_loops() == 1);
  CHECK(m.loop_edges(0).size() == 10);
  const Index corner = 0, side = 1, interior = 5;  // (0,0), (1,0), (1,1)
  CHECK(m.vertex_corners(corner).size() == 1);
  CHECK(m.vertex_corners(side).size() == 2);
  CHECK(m.vertex_corners(interior).size() == 4);
  for (Index v : {corner, side}) {
    const auto edges = m.vertex_edges(v);
    CHECK(m.edge(edges.front()).is_boundary());
    CHECK(m.edge(edges.back()).is_boundary());
    for (size_t i = 1; i + 1 < edges.size(); ++i) CHECK_FALSE(m.edge(edges[i]).is_boundary());
  }
  check_fans(m);
}

TEST_CASE("boundary loops are closed chains of border edges", "[kernel]") {
  const Mesh m = build_mesh(test::mobius_band(8, 2));
  REQUIRE(m.num_boundary_loops() == 1);
  const auto edges = m.loop_edges(0);
  const auto verts = m.loop_vertices(0);
  CHECK(edges.size() == 16);  // the single border of a Möbius band runs around twice
  for (size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = m.edge(edges[i]);
    CHECK(e.is_boundary());
    CHECK(e.other_vertex(verts[i]) == verts[(i + 1) % verts.size()]);
  }
}

TEST_CASE("a Möbius band one quad wide has one Möbius edge and signed fans", "[kernel]") {
  const Mesh m = build_mesh(test::mobius_band(5, 1));
  Index mobius = 0;
  for (const Edge& e : m.edges()) mobius += e.is_mobius;
  CHECK(mobius == 1);
  check_fans(m);
  // The two ends of the Möbius edge: their fans cross it, so one of their corners has sign -1.
  for (const Edge& e : m.edges()) {
    if (!e.is_mobius) continue;
    for (Index v : e.vertices) {
      int negatives = 0;
      for (Index c : m.vertex_corners(v)) negatives += m.corner_sign(c) < 0;
      CHECK(negatives == 1);
    }
  }
}

TEST_CASE("a wider Möbius band has a Möbius edge at every seam edge", "[kernel]") {
  const Mesh m = build_mesh(test::mobius_band(12, 4));
  Index mobius = 0;
  for (const Edge& e : m.edges()) mobius += e.is_mobius;
  CHECK(mobius == 4);  // one per quad across the seam
  check_fans(m);
}

TEST_CASE("faces keep the orientation they were given", "[kernel]") {
  PolygonSoup s = test::cube();
  std::swap(s.face_vertices[1], s.face_vertices[3]);  // reverse face 0: 0 1 3 2
  const Mesh m = build_mesh(s);
  const auto vs = m.face_vertices(0);
  CHECK(std::vector<Index>(vs.begin(), vs.end()) == std::vector<Index>{0, 1, 3, 2});
  Index mobius = 0;
  for (const Edge& e : m.edges()) mobius += e.is_mobius;
  CHECK(mobius == 4);
  check_fans(m);
}

TEST_CASE("fans of the Klein bottle and the projective plane are single disks", "[kernel]") {
  check_fans(build_mesh(test::klein_bottle(8, 6)));
  const Mesh rp2 = build_mesh(test::projective_plane());
  CHECK(rp2.num_vertices() == 4);
  CHECK(rp2.num_edges() == 6);
  CHECK(rp2.num_faces() == 3);
  check_fans(rp2);
}

TEST_CASE("build_mesh refuses what is not a 2-manifold, naming the elements", "[kernel]") {
  SECTION("a third face on an edge") {
    PolygonSoup s = test::grid(1, 1);
    const Index v = s.add_vertex({0, 0, 1});
    s.add_face({0, 1, v});
    const Index w = s.add_vertex({0, 0, -1});
    s.add_face({1, 0, w});
    CHECK_THROWS_WITH(build_mesh(s), Catch::Contains("edge (v0, v1) has a third face f2"));
  }
  SECTION("a repeated vertex") {
    PolygonSoup s = test::grid(1, 1);
    s.face_vertices[2] = 0;
    CHECK_THROWS_WITH(build_mesh(s), Catch::Contains("face f0 repeats vertex v0"));
  }
  SECTION("a face with two vertices") {
    PolygonSoup s = test::tetrahedron();
    s.add_face({0, 1});
    CHECK_THROWS_WITH(build_mesh(s), Catch::Contains("face f4 has 2 vertices"));
  }
  SECTION("an index out of range") {
    PolygonSoup s = test::tetrahedron();
    s.face_vertices[0] = 9;
    CHECK_THROWS_WITH(build_mesh(s), Catch::Contains("refers to vertex 9"));
  }
  SECTION("two cones touching at their tips") {
    PolygonSoup s;
    const Index tip = s.add_vertex({0, 0, 0});
    for (int k = 0; k < 2; ++k) {
      const double z = k ? 1 : -1;
      const Index a = s.add_vertex({1, 0, z}), b = s.add_vertex({0, 1, z}), c = s.add_vertex({-1, -1, z});
      s.add_face({tip, a, b});
      s.add_face({tip, b, c});
      s.add_face({tip, c, a});
    }
    CHECK_THROWS_WITH(build_mesh(s), Catch::Contains("vertex v0") && Catch::Contains("do not form one fan"));
  }
  SECTION("names are used when given") {
    PolygonSoup s = test::grid(1, 1);
    s.vertex_names = {"a", "b", "c", "d"};
    s.face_names = {"quad"};
    s.face_vertices[2] = 0;
    CHECK_THROWS_WITH(build_mesh(s), Catch::Contains("face quad repeats vertex a"));
  }
  SECTION("the error is a TopologyError") {
    CHECK_THROWS_AS(build_mesh([] {
                      PolygonSoup s = test::tetrahedron();
                      s.add_face({0, 1});
                      return s;
                    }()),
                    TopologyError);
  }
}

TEST_CASE("sharp edges are marked by vertex pairs", "[kernel]") {
  PolygonSoup s = test::cube();
  s.sharp_edges = {{0, 2}, {2, 3}};
  const Mesh m = build_mesh(s);
  Index sharp = 0;
  for (const Edge& e : m.edges()) sharp += e.is_sharp;
  CHECK(sharp == 2);
  s.sharp_edges = {{0, 7}};
  CHECK_THROWS_AS(build_mesh(s), TopologyError);
}

TEST_CASE("copy, soup round trip and transform", "[kernel]") {
  const Mesh m = build_mesh(test::torus(6, 4));
  const Mesh copy = m;
  CHECK(copy.num_edges() == m.num_edges());
  const Mesh again = build_mesh(to_soup(m));
  CHECK(again.corner_edges() == m.corner_edges());
  CHECK(again.positions() == m.positions());
  glm::dmat4 shift(1.0);
  shift[3] = glm::dvec4(1, 2, 3, 1);
  const Mesh moved = transformed(m, shift);
  CHECK(moved.position(0) == m.position(0) + Vec3(1, 2, 3));
  CHECK(moved.corner_vertices() == m.corner_vertices());
}

TEST_CASE("a mesh of quads only finds a corner's face without a table, any other mesh with one", "[kernel]") {
  auto check_corner_faces = [](const Mesh& m) {
    Index c = 0;
    for (Index f = 0; f < m.num_faces(); ++f)
      for (Index i = 0; i < m.face_degree(f); ++i, ++c) REQUIRE(m.corner_face(c) == f);
    CHECK(validate(m).empty());
    check_fans(m);
  };
  const Mesh quads = subdivide(build_mesh(test::mobius_band(6, 2)), {.levels = 1});
  CHECK(quads.corner_faces().empty());
  check_corner_faces(quads);
  // The band and a triangle apart from it.
  PolygonSoup mixed = test::mobius_band(6, 2);
  const Index a = mixed.add_vertex({0.0, 0.0, 5.0}), b = mixed.add_vertex({1.0, 0.0, 5.0}),
              c = mixed.add_vertex({0.0, 1.0, 5.0});
  mixed.add_face({a, b, c});
  const Mesh with_triangle = build_mesh(mixed);
  CHECK(with_triangle.corner_faces().size() == with_triangle.num_corners());
  check_corner_faces(with_triangle);
}
