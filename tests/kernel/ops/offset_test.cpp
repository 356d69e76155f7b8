#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "nome/error.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/offset_surface.hpp"
#include "support/mesh_measures.hpp"
#include "support/same_mesh.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

struct Case {
  const char* name;
  PolygonSoup soup;
  long long chi;  // of the offset solid
  size_t parts;
};

}  // namespace

TEST_CASE("the offset is a closed, orientable, outward solid with chi = 2 chi(M)", "[kernel]") {
  std::mt19937 rng{42};
  const Case cases[] = {
      {"disk (grid) -> sphere", test::grid(3, 2), 2, 1},
      {"annulus -> torus", test::mobius_band(12, 2, 2), 0, 1},
      {"mobius band -> torus", test::mobius_band(12, 2), 0, 1},
      {"mobius band, 3 twists -> torus", test::mobius_band(15, 1, 3), 0, 1},
      {"klein bottle -> torus", test::klein_bottle(12, 8), 0, 1},
      {"torus -> two tori", test::torus(8, 6), 0, 2},
      {"cube and mobius band -> two spheres and a torus",
       test::disjoint_union(test::cube(), test::mobius_band(9, 1)), 4, 3},
      {"torus with reversed faces -> two tori", test::reverse_random_faces(test::torus(8, 6), 0.5, rng), 0,
       2},
      {"cube -> two spheres", test::cube(), 4, 2},
      {"projective plane -> sphere", test::projective_plane(), 2, 1},
      {"mobius band with reversed faces", test::reverse_random_faces(test::mobius_band(12, 3), 0.5, rng), 0,
       1},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const Mesh m = build_mesh(c.soup);
    const Mesh solid = offset(m, {0.02});
    const auto problems = validate(solid);
    CHECK(problems.empty());
    if (!problems.empty()) FAIL(problems.front());
    const TopologyReport r = topology_report(solid);
    CHECK(r.chi == 2 * topology_report(m).chi);
    CHECK(r.chi == c.chi);
    CHECK(r.components.size() == c.parts);
    CHECK(r.borders == 0);
    CHECK(r.orientable);
    CHECK(r.mobius_edges == 0);
    CHECK(test::signed_volume(solid) > 0.0);
    Index border_edges = 0;
    for (const Edge& e : m.edges()) border_edges += e.is_boundary() ? 1 : 0;
    CHECK(solid.num_faces() == 2 * m.num_faces() + border_edges);
  }
}

TEST_CASE("offset copies sit at distance d along the vertex normal, one on each side", "[kernel]") {
  const Mesh disk = build_mesh(test::grid(2, 2));
  const Mesh solid = offset(disk, {0.25});
  REQUIRE(solid.num_vertices() == 2 * disk.num_vertices());
  for (Index v = 0; v < disk.num_vertices(); ++v) {
    CHECK(solid.position(2 * v) == disk.position(v) + Vec3(0, 0, 0.25));
    CHECK(solid.position(2 * v + 1) == disk.position(v) - Vec3(0, 0, 0.25));
  }
  // 8 faces of two copies plus one quad per border edge.
  CHECK(solid.num_faces() == 8 + 8);
  // The slab of a flat unit-cell 2x2 grid: volume = area * thickness.
  CHECK(test::signed_volume(solid) == Approx(4.0 * 0.5));
}

TEST_CASE("a subdivided Möbius band offsets into a torus, rounded by subdivision after", "[kernel]") {
  const Mesh band = subdivide(build_mesh(test::mobius_band(16, 2)), {2, SubdivisionRule::classic});
  const Mesh solid = offset(band, {0.03, 1, SubdivisionRule::classic});
  CHECK(validate(solid).empty());
  const TopologyReport r = topology_report(solid);
  CHECK(r.components.size() == 1);
  CHECK(r.chi == 0);
  CHECK(r.orientable);
  CHECK(r.components[0].genus == 1);
  CHECK(r.borders == 0);
  CHECK(test::signed_volume(solid) > 0.0);
}

TEST_CASE("offset_positions moves the vertices of a kept offset topology", "[kernel]") {
  const Mesh band = build_mesh(test::mobius_band(10, 2));
  Mesh moved = band;
  for (Vec3& p : moved.positions()) p = Vec3(p.x * 1.5, p.y, p.z + 0.1 * p.x);
  Mesh solid = offset(band, {0.05});
  offset_positions(moved, 0.05, solid.positions());
  CHECK(solid.positions() == offset(moved, {0.05}).positions());
}

TEST_CASE("offset_positions on two threads writes the positions of one", "[kernel]") {
  // Large enough to split over two threads; a Möbius band, whose vertex normals follow each fan's sign.
  const Mesh band = build_mesh(test::mobius_band(700, 100));
  REQUIRE(band.num_vertices() > 2 * (1u << 15));
  const Normals normals = compute_normals(band);
  std::vector<Vec3> one(2 * std::size_t(band.num_vertices())), two(one.size());
  offset_positions(band, normals, 0.05, one);
  offset_positions(band, normals, 0.05, two, 2);
  CHECK(two == one);
  const Mesh solid = offset(band, {0.05});
  CHECK(one == std::vector<Vec3>(solid.positions().begin(), solid.positions().end()));
}

TEST_CASE("an OffsetSurface reads as offset()'s positions and polygons, bit for bit", "[kernel]") {
  PolygonSoup with_lone_vertex = test::grid(3, 2);
  with_lone_vertex.add_vertex({5.0, 5.0, 5.0});  // no faces: no vertices in the solid
  const PolygonSoup shapes[] = {test::mobius_band(10, 2), test::klein_bottle(8, 6), with_lone_vertex};
  for (const PolygonSoup& shape : shapes) {
    const Mesh m = build_mesh(shape);
    const Mesh solid = offset(m, {0.05});
    const OffsetSurface streamed(m, compute_normals(m).vertices, 0.05);
    REQUIRE(streamed.num_vertices() == solid.num_vertices());
    REQUIRE(streamed.num_faces() == solid.num_faces());
    CHECK(streamed.num_corners() == solid.num_corners());
    for (Index v = 0; v < solid.num_vertices(); ++v) REQUIRE(streamed.position(v) == solid.position(v));
    for (Index f = 0; f < solid.num_faces(); ++f) {
      const auto expected = solid.face_vertices(f);
      const auto corners = streamed.face_vertices(f);
      REQUIRE(streamed.face_degree(f) == expected.size());
      REQUIRE(std::vector<Index>(corners.begin(), corners.end()) ==
              std::vector<Index>(expected.begin(), expected.end()));
    }
  }
  const Mesh band = build_mesh(test::mobius_band(10, 2));
  CHECK_THROWS_AS(OffsetSurface(band, compute_normals(band).vertices, 0.0), InvalidInputError);
  CHECK_THROWS_AS(OffsetSurface(band, Buffer<Vec3>(3), 0.05), InvalidInputError);
}

TEST_CASE("offset_into rebuilds in the blocks of the solid it replaces what offset() builds", "[kernel]") {
  PolygonSoup band = test::mobius_band(12, 3);
  for (Index f = 0; f < band.num_faces(); ++f)
    add_colors(band.face_attributes).values().push_back(Color(0.1f * float(f % 7), 0.5f, 1.0f));
  std::mt19937 rng{7};
  // Larger, smaller, then larger again; with and without borders, Möbius edges and colours.
  const PolygonSoup shapes[] = {
      test::torus(16, 8),       band,
      test::klein_bottle(8, 6), test::reverse_random_faces(test::torus(8, 6), 0.5, rng),
      test::grid(3, 2),         test::disjoint_union(test::cube(), test::mobius_band(9, 1)),
      test::torus(16, 8)};
  Mesh solid;
  Normals normals;
  for (const PolygonSoup& shape : shapes) {
    const Mesh m = build_mesh(shape);
    compute_normals(m, normals);
    offset_into(m, normals, 0.04, solid);
    test::check_same_mesh(solid, offset(m, {0.04}));
    CHECK(normals.vertices == compute_normals(m).vertices);
  }
  // Rebuilt with the same counts, the solid keeps its blocks: no fresh memory.
  const Mesh torus = build_mesh(test::torus(16, 8));
  const Vec3* positions = solid.positions().data();
  const Edge* edges = solid.edges().data();
  const Index* fans = solid.fan_corners().data();
  offset_into(torus, compute_normals(torus), 0.05, solid);
  CHECK(solid.positions().data() == positions);
  CHECK(solid.edges().data() == edges);
  CHECK(solid.fan_corners().data() == fans);
  test::check_same_mesh(solid, offset(torus, {0.05}));
  // Two threads build the same arrays (the meshes are large enough to be split: 2^15 faces and more).
  for (const PolygonSoup& shape : {test::torus(256, 128), test::mobius_band(512, 64)}) {
    const Mesh m = build_mesh(shape);
    offset_into(m, compute_normals(m), 0.01, solid, 2);
    test::check_same_mesh(solid, offset(m, {0.01}));
  }
  // A refused distance leaves the solid as it was.
  CHECK_THROWS_AS(offset_into(torus, compute_normals(torus), -1.0, solid), InvalidInputError);
  CHECK(solid.num_faces() == 2 * 512 * 64 + 2 * 512);
}

TEST_CASE("offset refuses a distance that is not positive and finite", "[kernel]") {
  const Mesh cube = build_mesh(test::cube());
  for (double d : {0.0, -0.1, std::numeric_limits<double>::infinity(), std::nan("")}) {
    CHECK_THROWS_WITH(offset(cube, {d}), Catch::StartsWith("offset: the offset distance must be positive"));
  }
  std::vector<Vec3> out(3);
  CHECK_THROWS_AS(offset_positions(cube, 0.1, out), InvalidInputError);
}
