#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "nome/mesh/face_orientation.hpp"
#include "support/shapes.hpp"

using namespace nome;

TEST_CASE("face signs undo random reversals of an orientable surface's faces", "[kernel]") {
  std::mt19937 rng{42};
  const PolygonSoup reversed = test::reverse_random_faces(test::torus(12, 8), 0.5, rng);
  const FaceOrientation o = face_orientation(build_mesh(reversed));
  REQUIRE(o.component_orientable == std::vector<char>{1});
  // Reverse again every face of sign -1: no Möbius edge is left.
  PolygonSoup fixed = reversed;
  for (Index f = 0; f < fixed.num_faces(); ++f)
    if (o.face_signs[f] < 0)
      std::reverse(fixed.face_vertices.begin() + fixed.face_offsets[f],
                   fixed.face_vertices.begin() + fixed.face_offsets[f + 1]);
  const Mesh m = build_mesh(fixed);
  CHECK(std::none_of(m.edges().begin(), m.edges().end(), [](const Edge& e) { return e.is_mobius; }));
}

TEST_CASE("each component is judged on its own", "[kernel]") {
  const Mesh m = build_mesh(test::disjoint_union(test::mobius_band(9, 3), test::cube()));
  const FaceOrientation o = face_orientation(m);
  REQUIRE(o.component_orientable.size() == 2);
  CHECK(o.component_orientable[m.face_component(0)] == 0);
  CHECK(o.component_orientable[m.face_component(m.num_faces() - 1)] == 1);
}

TEST_CASE("signs are relative to the first face of each component", "[kernel]") {
  std::mt19937 rng{7};
  const PolygonSoup soup = test::disjoint_union(test::reverse_random_faces(test::cube(), 0.5, rng),
                                                test::reverse_random_faces(test::torus(6, 4), 0.5, rng));
  const Mesh m = build_mesh(soup);
  const FaceOrientation o = face_orientation(m);
  std::vector<char> seen(m.num_components(), 0);
  for (Index f = 0; f < m.num_faces(); ++f) {
    if (seen[m.face_component(f)]) continue;
    seen[m.face_component(f)] = 1;
    CHECK(o.face_signs[f] == 1);
  }
  // Across every edge the signs agree exactly when the edge is not a Möbius edge.
  for (const Edge& e : m.edges())
    if (!e.is_boundary()) CHECK((o.face_signs[e.faces[0]] == o.face_signs[e.faces[1]]) == !e.is_mobius);
}
