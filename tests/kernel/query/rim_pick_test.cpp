#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "nome/query/border_lookup.hpp"
#include "nome/query/rim_pick.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

// An open line along x: points at x = 0, 1, 4 (edges 1 and 3 long).
RimLines open_line() {
  RimLines rims;
  const std::vector<Vec3> points{{0, 0, 0}, {1, 0, 0}, {4, 0, 0}};
  const std::vector<std::string> names{"l_a", "l_b", "l_c"};
  rims.add_line(points, names, false);
  return rims;
}

Ray down_from(double x, double y) {
  return Ray{{x, y, 10.0}, {0.0, 0.0, -1.0}};
}

}  // namespace

TEST_CASE("a rim vertex's cube is proportional to the mean length of its rim edges", "[kernel]") {
  const RimLines rims = open_line();
  const auto half = rim_cube_half_sizes(rims, 0.5);
  REQUIRE(half.size() == 3);
  CHECK(half[0] == Approx(0.5));
  CHECK(half[1] == Approx(1.0));  // (1 + 3) / 2
  CHECK(half[2] == Approx(1.5));
  RimLines square;
  const std::vector<Vec3> corners{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  square.add_line(corners, std::vector<std::string>{"a", "b", "c", "d"}, true);
  for (double h : rim_cube_half_sizes(square, 0.25)) CHECK(h == Approx(0.5));  // the closing edge counts
}

TEST_CASE("a ray picks the rim vertex whose cube it enters first, and misses between cubes", "[kernel]") {
  const RimLines rims = open_line();
  const auto half = rim_cube_half_sizes(rims);  // 0.2, 0.4, 0.6
  const auto hit = pick_rim_vertex(rims, half, down_from(1.3, 0.0));
  REQUIRE(hit);
  CHECK(hit->vertex == RimVertexId(1));
  CHECK(hit->depth == Approx(10.0 - 0.4));
  CHECK_FALSE(pick_rim_vertex(rims, half, down_from(2.5, 0.0)));
  CHECK_FALSE(pick_rim_vertex(rims, half, down_from(1.0, 0.5)));
  // Along the line: the nearest cube wins.
  const auto along = pick_rim_vertex(rims, half, Ray{{10.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}});
  REQUIRE(along);
  CHECK(along->vertex == RimVertexId(2));
  // Only the part of the ray between t_min and t_max picks: a cube beyond its end or behind its start
  // is missed, one it starts inside is hit where it starts.
  CHECK_FALSE(pick_rim_vertex(rims, half, Ray{{1.0, 0.0, 10.0}, {0.0, 0.0, -1.0}, 0.0, 9.5}));
  CHECK_FALSE(pick_rim_vertex(rims, half, Ray{{1.0, 0.0, 10.0}, {0.0, 0.0, -1.0}, 10.5, 20.0}));
  const auto inside = pick_rim_vertex(rims, half, Ray{{1.0, 0.0, 10.0}, {0.0, 0.0, -1.0}, 10.0, 20.0});
  REQUIRE(inside);
  CHECK(inside->depth == Approx(10.0));
}

TEST_CASE("a click picks a rim vertex in front of the surface, never one behind it", "[kernel]") {
  // The grid's square [0, 2] x [0, 1] at z = 0, seen from +z; rim vertices above it and below it.
  const Mesh grid = build_mesh(test::grid(2, 1));
  const TriangleBvh bvh(grid);
  RimLines rims;
  const std::vector<Vec3> points{{0.5, 0.5, 1.0}, {1.5, 0.5, -1.0}};
  rims.add_line(points, std::vector<std::string>{"above", "below"}, false);
  const auto half = rim_cube_half_sizes(rims, 0.1);
  ScreenProjection projection;
  projection.view = glm::lookAt(glm::dvec3(1.0, 0.5, 5.0), glm::dvec3(1.0, 0.5, 0.0), glm::dvec3(0, 1, 0));
  projection.projection = glm::ortho(-2.0, 2.0, -2.0, 2.0, 0.1, 10.0);
  projection.viewport = {400.0, 400.0};
  auto pixel_of = [&](const Vec3& p) { return glm::dvec2(*project_to_pixel(projection, p)); };
  CHECK(pick_rim_vertex(rims, half, bvh, projection, pixel_of(points[0])) == RimVertexId(0));
  CHECK_FALSE(pick_rim_vertex(rims, half, bvh, projection, pixel_of(points[1])));
  CHECK_FALSE(pick_rim_vertex(rims, half, bvh, projection, pixel_of({1.0, 0.9, 0.0})));
}

TEST_CASE("rim lines join the border lookup after the mesh's vertices, open ones as segments", "[kernel]") {
  const Mesh mesh = build_mesh(test::grid(1, 1));  // one quad: a border of four vertices
  BorderLookup borders(mesh);
  RimLines rims = open_line();
  const std::vector<Vec3> triangle{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  rims.add_line(triangle, std::vector<std::string>{"t_a", "t_b", "t_c"}, true);
  borders.add_rim_lines(rims, mesh.num_vertices());
  const Index first = mesh.num_vertices();
  REQUIRE(borders.is_on_border(first));
  CHECK(borders.is_closed(borders.loop_of(0)));
  CHECK_FALSE(borders.is_closed(borders.loop_of(first)));
  CHECK(borders.is_closed(borders.loop_of(first + 3)));
  // An open line is whole from its first vertex whichever is clicked; any two of its vertices bound one
  // segment.
  CHECK(borders.whole_loop_from(first + 2) == std::vector<Index>{first, first + 1, first + 2});
  CHECK(borders.are_adjacent(first, first + 2));
  CHECK(*borders.segment(first + 2, first, no_index) == std::vector<Index>{first + 2, first + 1, first});
  CHECK(borders.whole_loop_from(first + 4) == std::vector<Index>{first + 4, first + 5, first + 3});
  CHECK_FALSE(borders.segment(first, first + 3, first + 1));
}
