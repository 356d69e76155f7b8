#include <catch2/catch.hpp>

#include <algorithm>

#include "nome/query/border_lookup.hpp"
#include "support/shapes.hpp"

using namespace nome;

TEST_CASE("each border vertex knows its loop, interior vertices none", "[kernel]") {
  const Mesh mesh = build_mesh(test::grid(3, 2));
  const BorderLookup borders(mesh);
  CHECK_FALSE(borders.is_on_border(5));  // (1, 1) and (2, 1) are interior
  CHECK_FALSE(borders.is_on_border(6));
  const auto loop = borders.whole_loop_from(4);
  REQUIRE(loop.size() == 10);
  CHECK(loop.front() == 4);
  for (Index v : loop) CHECK(borders.loop_of(v) == borders.loop_of(4));
  CHECK(borders.whole_loop_from(5).empty());
}

TEST_CASE("a partial border runs between its two ends on the side of the third vertex", "[kernel]") {
  const Mesh mesh = build_mesh(test::grid(3, 2));
  const BorderLookup borders(mesh);
  const auto loop = borders.whole_loop_from(0);
  // Ends loop[0] and loop[3]; the short way passes loop[1], loop[2], the long way loop[4..9].
  const auto short_way = borders.segment(loop[0], loop[3], loop[2]);
  REQUIRE(short_way);
  CHECK(*short_way == std::vector<Index>{loop[0], loop[1], loop[2], loop[3]});
  const auto long_way = borders.segment(loop[0], loop[3], loop[7]);
  REQUIRE(long_way);
  CHECK(long_way->size() == 8);
  CHECK(long_way->front() == loop[0]);
  CHECK(long_way->back() == loop[3]);
  CHECK((*long_way)[1] == loop[9]);
  CHECK(borders.are_adjacent(loop[4], loop[5]));
  CHECK(borders.are_adjacent(loop[0], loop[9]));
  CHECK_FALSE(borders.are_adjacent(loop[0], loop[2]));
  CHECK_FALSE(borders.segment(loop[0], loop[3], loop[3]));
  CHECK_FALSE(borders.segment(loop[0], loop[3], 5));  // interior vertex
}

TEST_CASE("the Möbius band has one border loop through both edges of the strip", "[kernel]") {
  const Mesh mesh = build_mesh(test::mobius_band(12, 2));
  const BorderLookup borders(mesh);
  Index border_vertices = 0;
  for (Index v = 0; v < mesh.num_vertices(); ++v) border_vertices += borders.is_on_border(v);
  CHECK(border_vertices == 24);
  const auto loop = borders.whole_loop_from(mesh.loop_vertices(0)[5]);
  CHECK(loop.size() == 24);
  CHECK(std::adjacent_find(loop.begin(), loop.end()) == loop.end());
}

TEST_CASE("two separate borders are told apart", "[kernel]") {
  const Mesh mesh = build_mesh(test::disjoint_union(test::grid(2, 2), test::grid(1, 1)));
  const BorderLookup borders(mesh);
  CHECK(borders.loop_of(0) != borders.loop_of(9));
  CHECK_FALSE(borders.segment(0, 2, 9));
  CHECK(borders.whole_loop_from(9).size() == 4);
}
