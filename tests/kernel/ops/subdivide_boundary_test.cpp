// The boundary modes (OpenSubdiv's vertex boundary interpolation): what a vertex of one face does, and
// which faces are holes. The comparison with OpenSubdiv itself is subdivide_opensubdiv_test.cpp.
#include <catch2/catch.hpp>

#include "nome/ops/subdivide.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

Mesh refined(const PolygonSoup& soup, int levels, BoundaryMode boundary) {
  return subdivide(build_mesh(soup), {levels, SubdivisionRule::classic, boundary});
}

}  // namespace

TEST_CASE("a vertex of a single face follows its border with edge-only and stays put with edge-and-corner",
          "[kernel]") {
  const PolygonSoup quad = test::grid(1, 1);
  const Mesh base = build_mesh(quad);
  // Level 1 numbers the face point, the 4 edge points, then the vertex points.
  const Index vertex_point = 1 + base.num_edges();
  const Vec3 corner = base.position(0);
  const Mesh edge_only = refined(quad, 1, BoundaryMode::edge_only);
  const Mesh edge_and_corner = refined(quad, 1, BoundaryMode::edge_and_corner);
  Vec3 neighbours(0.0);
  for (Index e : base.vertex_edges(0)) neighbours += base.position(base.edge(e).other_vertex(0));
  CHECK(edge_only.position(vertex_point) == (6.0 * corner + neighbours) * 0.125);
  CHECK(edge_and_corner.position(vertex_point) == corner);
  // Only vertices of one face differ: everything else is the same.
  size_t differing = 0;
  for (Index v = 0; v < edge_only.num_vertices(); ++v)
    differing += edge_only.position(v) == edge_and_corner.position(v) ? 0 : 1;
  CHECK(differing == 4);
}

TEST_CASE("edge-and-corner changes nothing where no vertex has a single face, Möbius band included",
          "[kernel]") {
  for (const PolygonSoup& soup : {test::mobius_band(12, 2), test::torus(6, 4)})
    CHECK(refined(soup, 2, BoundaryMode::edge_and_corner).positions() ==
          refined(soup, 2, BoundaryMode::edge_only).positions());
}

TEST_CASE("with boundary none, faces with a border vertex shape their neighbours but are not output",
          "[kernel]") {
  const PolygonSoup grid = test::grid(3, 3);  // only the centre face has no border vertex
  const Mesh none = refined(grid, 2, BoundaryMode::none);
  const Mesh edge_only = refined(grid, 2, BoundaryMode::edge_only);
  CHECK(none.num_faces() == 16);
  CHECK(none.num_vertices() == 25);
  // Every kept vertex is where edge-only puts it: the holes shaped it.
  for (const Vec3& p : none.positions()) {
    bool is_found = false;
    for (const Vec3& q : edge_only.positions()) is_found = is_found || p == q;
    CHECK(is_found);
  }
  CHECK(refined(test::grid(1, 1), 1, BoundaryMode::none).num_faces() == 0);
  CHECK(refined(test::torus(6, 4), 1, BoundaryMode::none).num_faces() == 6 * 4 * 4);  // no border: no hole

  // The position pass into a mesh with holes gives what a full refine gives.
  Mesh base = build_mesh(grid), moved = base;
  for (Vec3& p : moved.positions()) p = Vec3(p.x, p.y, p.x * p.y);
  Refinement refinement(base, 2, BoundaryMode::none);
  const std::span<const Vec3> first = refinement.refine_positions(base, SubdivisionRule::classic);
  Mesh result = refinement.mesh(base, Buffer<Vec3>(first.begin(), first.end()));
  refinement.refine_positions(moved, SubdivisionRule::classic, result);
  CHECK(result.positions() ==
        subdivide(moved, {2, SubdivisionRule::classic, BoundaryMode::none}).positions());
}

TEST_CASE("boundary modes are named as on the command line and in the scene language", "[kernel]") {
  for (BoundaryMode mode : {BoundaryMode::none, BoundaryMode::edge_only, BoundaryMode::edge_and_corner})
    CHECK(parse_boundary_mode(to_string(mode)) == mode);
  CHECK(parse_boundary_mode("edge_and_corner") == BoundaryMode::edge_and_corner);
  CHECK_FALSE(parse_boundary_mode("corner"));
}
