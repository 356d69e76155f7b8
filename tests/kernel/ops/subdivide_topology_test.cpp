#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "nome/error.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/subdivide.hpp"
#include "support/face_colors.hpp"
#include "support/same_mesh.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

struct Named {
  const char* name;
  PolygonSoup soup;
};

std::vector<Named> surfaces() {
  std::mt19937 rng{42};
  PolygonSoup sharp_grid = test::grid(4, 3);
  sharp_grid.sharp_edges = {{6, 7}, {7, 8}, {7, 12}};
  return {
      {"tetrahedron", test::tetrahedron()},
      {"cube", test::cube()},
      {"grid", test::grid(3, 2)},
      {"grid with sharp edges", sharp_grid},
      {"torus", test::torus(6, 4)},
      {"torus with reversed faces", test::reverse_random_faces(test::torus(6, 4), 0.4, rng)},
      {"mobius band", test::mobius_band(7, 2)},
      {"mobius band, three twists", test::mobius_band(9, 1, 3)},
      {"klein bottle", test::klein_bottle(6, 4)},
      {"projective plane", test::projective_plane()},
      {"two parts", test::disjoint_union(test::mobius_band(6, 1), test::cube())},
  };
}

Index count_flags(const Mesh& m, bool Edge::*flag) {
  Index n = 0;
  for (const Edge& e : m.edges()) n += (e.*flag) ? 1 : 0;
  return n;
}

}  // namespace

TEST_CASE("every subdivision level is a valid mesh with the expected counts", "[kernel]") {
  for (const Named& s : surfaces()) {
    INFO(s.name);
    Mesh m = build_mesh(s.soup);
    REQUIRE(validate(m).empty());
    for (int level = 1; level <= 3; ++level) {
      INFO("level " << level);
      const Mesh child = subdivide(m, {1, SubdivisionRule::classic});
      const auto problems = validate(child);
      CHECK(problems.empty());
      if (!problems.empty()) FAIL(problems.front());
      CHECK(child.num_vertices() == m.num_faces() + m.num_edges() + m.num_vertices());
      CHECK(child.num_edges() == 2 * m.num_edges() + m.num_corners());
      CHECK(child.num_faces() == m.num_corners());
      for (Index f = 0; f < child.num_faces(); ++f) CHECK(child.face_degree(f) == 4);
      CHECK(count_flags(child, &Edge::is_mobius) == 2 * count_flags(m, &Edge::is_mobius));
      CHECK(count_flags(child, &Edge::is_sharp) == 2 * count_flags(m, &Edge::is_sharp));
      m = child;
    }
  }
}

TEST_CASE("subdivision preserves chi, orientability and borders of every part", "[kernel]") {
  for (const Named& s : surfaces()) {
    INFO(s.name);
    const Mesh base = build_mesh(s.soup);
    const TopologyReport before = topology_report(base);
    for (int level = 1; level <= 3; ++level) {
      INFO("level " << level);
      const TopologyReport after = topology_report(subdivide(base, {level, SubdivisionRule::classic}));
      REQUIRE(after.components.size() == before.components.size());
      CHECK(after.chi == before.chi);
      CHECK(after.orientable == before.orientable);
      CHECK(after.borders == before.borders);
      for (size_t i = 0; i < before.components.size(); ++i) {
        CHECK(after.components[i].chi == before.components[i].chi);
        CHECK(after.components[i].orientable == before.components[i].orientable);
        CHECK(after.components[i].borders == before.components[i].borders);
        CHECK(after.components[i].genus == before.components[i].genus);
      }
    }
  }
}

TEST_CASE("child faces keep their parent's orientation and colour", "[kernel]") {
  PolygonSoup soup = test::mobius_band(5, 2);
  for (Index f = 0; f < soup.num_faces(); ++f)
    add_colors(soup.face_attributes).values().push_back(Color(float(f), 0.f, 1.f));
  const Mesh base = build_mesh(soup);
  const Mesh child = subdivide(base, {2, SubdivisionRule::classic});
  REQUIRE(test::face_colors(child).size() == child.num_faces());
  for (Index f = 0; f < child.num_faces(); ++f)
    CHECK(test::face_colors(child)[f] == test::face_colors(base)[base.corner_face(f >> 2)]);
  // Children of a face are consecutive and run the same way round: the quad at parent corner c starts at
  // c's vertex point and goes on to the edge point of the edge leaving c.
  const Mesh level1 = subdivide(base, {1, SubdivisionRule::classic});
  const Index nf = base.num_faces(), ne = base.num_edges();
  for (Index c = 0; c < base.num_corners(); ++c) {
    const auto q = level1.face_vertices(c);
    CHECK(q[0] == nf + ne + base.corner_vertex(c));
    CHECK(q[1] == nf + base.corner_edge(c));
    CHECK(q[2] == base.corner_face(c));
  }
}

TEST_CASE("a refinement rejects levels below 1 and a base of another topology", "[kernel]") {
  const Mesh cube = build_mesh(test::cube());
  CHECK_THROWS_AS(Refinement(cube, 0), InvalidInputError);
  Refinement refinement(cube, 2);
  CHECK(refinement.fits(cube));
  const Mesh tetra = build_mesh(test::tetrahedron());
  CHECK_FALSE(refinement.fits(tetra));
  std::vector<Vec3> out(refinement.num_vertices());
  CHECK_THROWS_AS(refinement.refine_positions(tetra, SubdivisionRule::classic, out), InvalidInputError);
  Mesh sharper = cube;
  sharper.set_sharp(0, true);
  CHECK_FALSE(refinement.fits(sharper));
}

TEST_CASE("a refinement rebuilt for another base gives what a new one gives", "[kernel]") {
  // Bases in turn, each after a different one, with levels up and down: nothing of the last build may
  // leak into the next (weights, holes, kept vertices, the roles of the levels).
  Mesh weighted = build_mesh(test::torus(6, 4));
  weighted.set_edge_sharpness(0, 1.5f);
  weighted.set_vertex_sharpness(3, 2.0f);
  Mesh holed = build_mesh(test::grid(4, 3));
  holed.set_hole(5, true);
  std::vector<std::pair<Mesh, int>> bases = {{weighted, 3},
                                             {build_mesh(test::mobius_band(7, 2)), 4},
                                             {holed, 2},
                                             {build_mesh(test::cube()), 1},
                                             {build_mesh(test::klein_bottle(6, 4)), 3},
                                             {weighted, 2}};
  for (BoundaryMode boundary : {BoundaryMode::edge_only, BoundaryMode::none}) {
    Refinement kept(build_mesh(test::tetrahedron()), 3, boundary);
    for (const auto& [base, levels] : bases) {
      kept.rebuild(base, levels, boundary);
      Refinement fresh(base, levels, boundary);
      CHECK(kept.num_vertices() == fresh.num_vertices());
      CHECK(std::ranges::equal(kept.quad_vertices(), fresh.quad_vertices()));
      const auto kept_positions = kept.refine_positions(base, SubdivisionRule::classic);
      CHECK(std::ranges::equal(kept_positions, fresh.refine_positions(base, SubdivisionRule::classic)));
      const Mesh a = kept.mesh(base, {kept_positions.begin(), kept_positions.end()});
      const Mesh b = fresh.mesh(base, {kept_positions.begin(), kept_positions.end()});
      CHECK(a.num_vertices() == b.num_vertices());
      CHECK(a.corner_vertices() == b.corner_vertices());
    }
  }
}

TEST_CASE("two threads refine a large mesh with borders as one does", "[kernel]") {
  // Over 2^16 parent edges the fan offsets are counted in one part a thread, each part with border edges
  // before it: a part that did not start after the earlier parts' borders would shift every fan.
  const Mesh base = build_mesh(test::grid(200, 200));
  REQUIRE(base.num_edges() >= Index(1) << 16);
  Refinement one(base, 1, BoundaryMode::edge_only, 1);
  Refinement two(base, 1, BoundaryMode::edge_only, 2);
  const auto positions = one.refine_positions(base, SubdivisionRule::classic);
  test::check_same_mesh(one.mesh(base, {positions.begin(), positions.end()}, 1),
                        two.mesh(base, {positions.begin(), positions.end()}, 2));
}
