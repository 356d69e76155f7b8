#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "nome/mesh/normals.hpp"
#include "nome/query/fold_overs.hpp"
#include "nome/query/print_check.hpp"
#include "nome/query/triangle_proximity.hpp"
#include "nome/query/wall_thickness.hpp"
#include "support/shapes.hpp"

using namespace nome;

// The print check on shapes whose walls, gaps, crossings and fold-overs are known in closed form, with the
// pass/fail thresholds checked exactly at their limits from both sides.
namespace {

// The point of segment [a, b] nearest to p.
Vec3 print_oracle_segment_point(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return a + t * ab;
}

// The nearest point of a triangle, the other way round from Ericson's regions: p's foot on the plane when it
// lies inside (all three edge tests by the sign of the normal), else the nearest of the three sides.
Vec3 print_oracle_closest_point(const Vec3& p, const Triangle& t) {
  const Vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
  const Vec3 foot = p - n * (glm::dot(p - t[0], n) / glm::dot(n, n));
  bool inside = true;
  for (int i = 0; i < 3; ++i)
    inside = inside && glm::dot(glm::cross(t[(i + 1) % 3] - t[i], foot - t[i]), n) >= 0.0;
  if (inside) return foot;
  Vec3 best = print_oracle_segment_point(p, t[0], t[1]);
  for (int i = 1; i < 3; ++i) {
    const Vec3 q = print_oracle_segment_point(p, t[i], t[(i + 1) % 3]);
    if (glm::distance(p, q) < glm::distance(p, best)) best = q;
  }
  return best;
}

// The surface of the box [0, size.x] x [0, size.y] x [0, size.z], faces outward.
PolygonSoup print_oracle_box(const Vec3& size, const Vec3& corner = Vec3(0.0)) {
  PolygonSoup s = test::cube();
  for (Vec3& p : s.positions) p = corner + 0.5 * (p + Vec3(1.0)) * size;
  return s;
}

PolygonSoup print_oracle_reversed(PolygonSoup s) {
  for (Index f = 0; f < s.num_faces(); ++f)
    std::reverse(s.face_vertices.begin() + s.face_offsets[f],
                 s.face_vertices.begin() + s.face_offsets[f + 1]);
  return s;
}

// An open tube of radius r around the z axis: `around` x `along` quads, length 1, faces outward.
PolygonSoup print_oracle_tube(double r, Index around, Index along) {
  PolygonSoup s;
  for (Index j = 0; j <= along; ++j)
    for (Index i = 0; i < around; ++i) {
      const double a = 6.283185307179586 * double(i) / double(around);
      s.add_vertex(Vec3(r * std::cos(a), r * std::sin(a), double(j) / double(along)));
    }
  auto id = [&](Index i, Index j) { return j * around + i % around; };
  for (Index j = 0; j < along; ++j)
    for (Index i = 0; i < around; ++i) s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return s;
}

// A flat square plate of n x n squares of side h at height z.
PolygonSoup print_oracle_plate(Index n, double h, double z) {
  PolygonSoup s = test::grid(n, n);
  for (Vec3& p : s.positions) p = Vec3(h * p.x, h * p.y, z);
  return s;
}

PrintCheck print_oracle_check(const Mesh& surface, double distance, double wall) {
  PrintCheckOptions options;
  options.offset_distance = distance;
  options.min_wall = wall;
  return check_printability(surface, options);
}

bool print_oracle_same_pair(const CrossingSegment& s, const Vec3& p, const Vec3& q) {
  auto near = [](const Vec3& a, const Vec3& b) { return glm::distance(a, b) < 1e-14; };
  return (near(s.from, p) && near(s.to, q)) || (near(s.from, q) && near(s.to, p));
}

}  // namespace

TEST_CASE("the nearest point of a triangle agrees with its definition in every region", "[kernel]") {
  const Triangle t{Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(1, 3, 0)};
  // By hand: the interior, each corner, each side.
  CHECK(glm::distance(closest_point_on_triangle(Vec3(1, 1, 2), t), Vec3(1, 1, 0)) < 1e-15);
  CHECK(closest_point_on_triangle(Vec3(-1, -1, 1), t) == Vec3(0, 0, 0));
  CHECK(closest_point_on_triangle(Vec3(5, -1, -1), t) == Vec3(4, 0, 0));
  CHECK(closest_point_on_triangle(Vec3(1, 4, 0.5), t) == Vec3(1, 3, 0));
  CHECK(glm::distance(closest_point_on_triangle(Vec3(2, -2, 1), t), Vec3(2, 0, 0)) < 1e-15);
  // Side from (4, 0) to (1, 3): the foot of (4, 3) is (2.5, 1.5); side from (1, 3) to (0, 0): of (-1, 2) it
  // is (0.5, 1.5) (direction (1, 3) / sqrt(10), projection length 5 / sqrt(10)).
  CHECK(glm::distance(closest_point_on_triangle(Vec3(4, 3, 0), t), Vec3(2.5, 1.5, 0)) < 1e-15);
  CHECK(glm::distance(closest_point_on_triangle(Vec3(-1, 2, 7), t), Vec3(0.5, 1.5, 0)) < 1e-15);
  std::mt19937 rng{42};
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const Triangle r{Vec3(unit(rng), unit(rng), unit(rng)), Vec3(unit(rng), unit(rng), unit(rng)),
                     Vec3(unit(rng), unit(rng), unit(rng))};
    const Vec3 p = 2.0 * Vec3(unit(rng), unit(rng), unit(rng));
    const Vec3 expected = print_oracle_closest_point(p, r);
    const Vec3 found = closest_point_on_triangle(p, r);
    INFO("case " << i);
    CHECK(glm::distance(found, expected) < 1e-9);
  }
}

TEST_CASE("two triangles cross along the segment computed by hand", "[kernel]") {
  const Triangle flat{Vec3(-1, -1, 0), Vec3(3, -1, 0), Vec3(-1, 3, 0)};
  // The standing triangle's two rising sides cut z = 0 at their middles: (0.5, 0, 0) and (0, 0.5, 0).
  const Triangle standing{Vec3(0, 0, -1), Vec3(1, 0, 1), Vec3(0, 1, 1)};
  CrossingSegment segment;
  REQUIRE(triangles_cross(flat, standing, segment));
  CHECK(print_oracle_same_pair(segment, Vec3(0.5, 0, 0), Vec3(0, 0.5, 0)));
  REQUIRE(triangles_cross(standing, flat, segment));
  CHECK(print_oracle_same_pair(segment, Vec3(0.5, 0, 0), Vec3(0, 0.5, 0)));
  // A large triangle in the plane x = 0.25 cuts a small one between its sides: from (0.25, 0) to (0.25,
  // 0.75).
  const Triangle small{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const Triangle wall{Vec3(0.25, -5, -5), Vec3(0.25, 5, -5), Vec3(0.25, 0, 5)};
  REQUIRE(triangles_cross(small, wall, segment));
  CHECK(print_oracle_same_pair(segment, Vec3(0.25, 0, 0), Vec3(0.25, 0.75, 0)));
  // One end from each: a wall whose section at z = 0 runs from y = 0.5 (on its side) to y = 3 (its corner).
  const Triangle half_wall{Vec3(0.25, 0.5, -1), Vec3(0.25, 0.5, 1), Vec3(0.25, 3, 0)};
  REQUIRE(triangles_cross(small, half_wall, segment));
  CHECK(print_oracle_same_pair(segment, Vec3(0.25, 0.5, 0), Vec3(0.25, 0.75, 0)));
  // A corner touching the other's inside is a one-point crossing; a triangle just above is none, and
  // coplanar overlapping ones are touching sheets, not a crossing.
  const Triangle touching{Vec3(0.2, 0.2, 0), Vec3(0.5, 0.5, 1), Vec3(0.2, 0.6, 1)};
  REQUIRE(triangles_cross(small, touching, segment));
  CHECK(glm::distance(segment.from, Vec3(0.2, 0.2, 0)) < 1e-15);
  CHECK(glm::distance(segment.to, Vec3(0.2, 0.2, 0)) < 1e-15);
  const Triangle above{Vec3(0.2, 0.2, 1e-9), Vec3(0.5, 0.5, 1), Vec3(0.2, 0.6, 1)};
  CHECK_FALSE(triangles_cross(small, above, segment));
  const Triangle coplanar{Vec3(0.1, 0.1, 0), Vec3(2, 0.1, 0), Vec3(0.1, 2, 0)};
  CHECK_FALSE(triangles_cross(small, coplanar, segment));
}

TEST_CASE("a box's and a shell's walls measure their sizes exactly", "[kernel]") {
  const Mesh box = build_mesh(print_oracle_box(Vec3(3.0, 2.0, 0.5)));
  const TriangleBvh bvh(box);
  // Face 0 is z = 0, face 4 is x = 0, face 3 is y = 2 (the cube's order).
  const auto floor = wall_thickness(box, bvh, 0, Vec3(1.0, 0.7, 0.0));
  REQUIRE(floor);
  CHECK(floor->thickness == Approx(0.5).epsilon(1e-12));
  CHECK(glm::distance(floor->to, Vec3(1.0, 0.7, 0.5)) < 1e-12);
  CHECK(floor->from == Vec3(1.0, 0.7, 0.0));
  const auto side = wall_thickness(box, bvh, 4, Vec3(0.0, 0.3, 0.2));
  REQUIRE(side);
  CHECK(side->thickness == Approx(3.0).epsilon(1e-12));
  CHECK(glm::distance(side->to, Vec3(3.0, 0.3, 0.2)) < 1e-12);
  const auto top = wall_thickness(box, bvh, 3, Vec3(2.5, 2.0, 0.1));
  REQUIRE(top);
  CHECK(top->thickness == Approx(2.0).epsilon(1e-12));

  // A hollow cube: outer [-1, 1]^3, inner [-0.8, 0.8]^3 facing the hollow. From either sheet the wall is
  // 0.2 thick, though the ray into the solid crosses the hollow and the far wall too.
  const Mesh shell =
      build_mesh(test::disjoint_union(print_oracle_box(Vec3(2.0), Vec3(-1.0)),
                                      print_oracle_reversed(print_oracle_box(Vec3(1.6), Vec3(-0.8)))));
  const TriangleBvh shell_bvh(shell);
  const auto outer = wall_thickness(shell, shell_bvh, 5, Vec3(1.0, 0.3, 0.2));
  REQUIRE(outer);
  CHECK(outer->thickness == Approx(0.2).epsilon(1e-12));
  CHECK(glm::distance(outer->to, Vec3(0.8, 0.3, 0.2)) < 1e-12);
  const auto inner = wall_thickness(shell, shell_bvh, 6 + 5, Vec3(0.8, -0.1, 0.4));
  REQUIRE(inner);
  CHECK(inner->thickness == Approx(0.2).epsilon(1e-12));
  CHECK(glm::distance(inner->to, Vec3(1.0, -0.1, 0.4)) < 1e-12);
  // A face that does not exist has no wall.
  CHECK_FALSE(wall_thickness(shell, shell_bvh, shell.num_faces(), Vec3(0.0)));
}

TEST_CASE("two parallel plates a gap apart are near misses exactly when the wall exceeds the gap",
          "[kernel]") {
  const double gap = 0.2;
  const Index n = 6;
  const Mesh plates =
      build_mesh(test::disjoint_union(print_oracle_plate(n, 0.1, 0.0), print_oracle_plate(n, 0.1, gap)));
  const Index per_plate = (n + 1) * (n + 1);
  REQUIRE(plates.num_vertices() == 2 * per_plate);
  const double above = gap * (1.0 + 1e-9);
  // Every vertex's nearest point on the other plate is the vertex across the gap.
  const PrintCheck thin = print_oracle_check(plates, 0.0, above);
  CHECK(thin.min_wall == above);
  REQUIRE(thin.near_misses.size() == 2 * per_plate);
  for (Index v = 0; v < plates.num_vertices(); ++v) {
    const NearMiss& m = thin.near_misses[v];
    CHECK(m.vertex == v);
    CHECK(m.distance == gap);
    const Vec3 across = plates.position(v) + Vec3(0.0, 0.0, v < per_plate ? gap : -gap);
    CHECK(glm::distance(m.point, across) < 1e-15);
    CHECK(plates.face_component(m.face) != plates.vertex_component(v));
  }
  CHECK(thin.crossings.pairs.empty());
  CHECK(thin.fold_over_faces.empty());
  CHECK_FALSE(thin.is_printable());
  // One place per plate, each the size of the plate, at the gap.
  REQUIRE(thin.places.size() == 2);
  for (const PrintPlace& place : thin.places) {
    CHECK(place.kind == FindingKind::near_miss);
    CHECK(place.size == per_plate);
    CHECK(place.distance == gap);
    CHECK(place.face != no_index);
    CHECK(plates.face_component(place.face) != plates.face_component(place.other_face));
  }
  // A wall of exactly the gap is no near miss: the gap is the wall.
  CHECK(print_oracle_check(plates, 0.0, gap).is_printable());
  CHECK(print_oracle_check(plates, 0.0, gap).near_misses.empty());
  // Without a wall given it is twice the offset distance: exactly half the gap passes, a little more fails.
  const PrintCheck half = print_oracle_check(plates, 0.5 * gap, 0.0);
  CHECK(half.min_wall == gap);
  CHECK(half.is_printable());
  const PrintCheck more = print_oracle_check(plates, 0.5 * above, 0.0);
  CHECK(more.min_wall == above);
  CHECK(more.near_misses.size() == 2 * per_plate);
  CHECK_FALSE(more.is_printable());
}

TEST_CASE("squares passing through each other cross along the segments computed by hand", "[kernel]") {
  // Two far apart pairs: a floor square [c - 1, c + 1] x [-1, 1] at z = 0 (face 2k) and a standing square
  // x = c + 0.25, y in [-0.5, 0.5], z in [-1, 1] (face 2k + 1), c = -2 and 2: two crossing curves, each the
  // segment y in [-0.5, 0.5] of x = c + 0.25 on the floor.
  PolygonSoup soup;
  const double centres[] = {-2.0, 2.0};
  for (const double c : centres) {
    Index first = soup.num_vertices();
    for (const Vec3& p : {Vec3(c - 1, -1, 0), Vec3(c + 1, -1, 0), Vec3(c + 1, 1, 0), Vec3(c - 1, 1, 0)})
      soup.add_vertex(p);
    soup.add_face({first, first + 1, first + 2, first + 3});
    first = soup.num_vertices();
    const double x = c + 0.25;
    for (const Vec3& p : {Vec3(x, -0.5, -1), Vec3(x, 0.5, -1), Vec3(x, 0.5, 1), Vec3(x, -0.5, 1)})
      soup.add_vertex(p);
    soup.add_face({first, first + 1, first + 2, first + 3});
  }
  const Mesh mesh = build_mesh(std::move(soup));
  const PrintCheck check = print_oracle_check(mesh, 0.01, 0.0);
  CHECK(check.crossings.curves == 2);
  CHECK(check.crossings.faces == std::vector<Index>{0, 1, 2, 3});
  REQUIRE(check.crossings.curve_of_pair.size() == check.crossings.pairs.size());
  // Each curve's pieces lie on its segment and together cover it.
  std::vector<Index> curve_of[2];
  for (Index k = 0; k < 2; ++k) {
    const double x = centres[k] + 0.25;
    std::vector<std::pair<double, double>> pieces;
    for (Index i = 0; i < check.crossings.pairs.size(); ++i) {
      const Crossing& c = check.crossings.pairs[i];
      if (c.face != 2 * k) continue;
      CHECK(c.other_face == 2 * k + 1);
      curve_of[k].push_back(check.crossings.curve_of_pair[i]);
      for (const Vec3& p : {c.segment.from, c.segment.to}) {
        CHECK(std::abs(p.x - x) < 1e-15);
        CHECK(std::abs(p.z) < 1e-15);
        CHECK(std::abs(p.y) <= 0.5 + 1e-15);
      }
      pieces.emplace_back(std::min(c.segment.from.y, c.segment.to.y),
                          std::max(c.segment.from.y, c.segment.to.y));
    }
    REQUIRE_FALSE(pieces.empty());
    std::sort(pieces.begin(), pieces.end());
    double covered = -0.5;
    for (const auto& [low, high] : pieces) {
      CHECK(low <= covered + 1e-12);
      covered = std::max(covered, high);
    }
    CHECK(covered == Approx(0.5).epsilon(1e-12));
  }
  // One curve per pair of squares.
  for (const auto& curves : curve_of)
    CHECK(std::all_of(curves.begin(), curves.end(), [&](Index c) { return c == curves.front(); }));
  CHECK(curve_of[0].front() != curve_of[1].front());
  // Crossings fuse the slab by design: printable, one place per curve on its segment.
  CHECK(check.is_printable());
  REQUIRE(check.places.size() == 2);
  for (const PrintPlace& place : check.places) {
    CHECK(place.kind == FindingKind::crossing);
    const Index k = place.position.x < 0.0 ? 0 : 1;
    CHECK(std::abs(place.position.x - (centres[k] + 0.25)) < 1e-15);
    CHECK(std::abs(place.position.y) <= 0.5);
    CHECK(std::abs(place.position.z) < 1e-15);
    CHECK(place.face == 2 * k);
    CHECK(place.other_face == 2 * k + 1);
  }
}

TEST_CASE("a tube's offset folds over exactly when the distance passes its radius, on its inner side",
          "[kernel]") {
  // Vertex normals of a regular tube are radial: the inner copy is the tube of radius r - d, turned inside
  // out once d > r. The inner side is -d for outward faces and +d for inward ones.
  const double r = 0.5;
  for (const bool outward : {true, false}) {
    INFO("outward " << outward);
    PolygonSoup soup = print_oracle_tube(r, 12, 3);
    if (!outward) soup = print_oracle_reversed(std::move(soup));
    const Mesh tube = build_mesh(std::move(soup));
    const PrintCheck safe = print_oracle_check(tube, r * (1.0 - 1e-6), 0.0);
    CHECK(safe.fold_over_faces.empty());
    const PrintCheck folded = print_oracle_check(tube, r * (1.0 + 1e-6), 0.0);
    CHECK(folded.fold_over_faces.size() == tube.num_faces());
    CHECK_FALSE(folded.is_printable());
    REQUIRE_FALSE(folded.places.empty());
    CHECK(folded.places[0].kind == FindingKind::fold_over);
    CHECK(folded.places[0].size == tube.num_faces());
    CHECK(find_fold_overs(tube, compute_normals(tube), r * (1.0 - 1e-6)).empty());
    CHECK(find_fold_overs(tube, compute_normals(tube), r * (1.0 + 1e-6)).size() == tube.num_faces());
  }
}

TEST_CASE("near-miss places are listed thinnest first, each at its thinnest vertex", "[kernel]") {
  // Three unit cubes, tipped a little, over a wide slab whose top is z = 0: each cube's lowest corner is
  // the given gap above it, its other bottom corners a little higher (all within the wall), so each cube
  // is one place of 4 vertices whose gaps are their heights. Written in vertex order 0.05, 0.02, 0.07.
  const double wall = 0.1;
  PolygonSoup soup = print_oracle_box(Vec3(10.0, 10.0, 1.0), Vec3(-5.0, -5.0, -1.0));
  const struct {
    double x, gap, tip_x, tip_y;
  } cubes[] = {{-3.5, 0.05, 0.012, 0.009}, {-0.5, 0.02, 0.008, -0.014}, {2.5, 0.07, 0.01, -0.011}};
  for (const auto& c : cubes) {
    PolygonSoup cube = print_oracle_box(Vec3(1.0), Vec3(c.x, -0.5, 0.0));
    const Vec3 centre(c.x + 0.5, 0.0, 0.5);
    const glm::dmat4 tip =
        glm::rotate(glm::rotate(glm::dmat4(1.0), c.tip_x, Vec3(1, 0, 0)), c.tip_y, Vec3(0, 1, 0));
    double lowest = 1e300;
    for (Vec3& p : cube.positions) {
      p = centre + Vec3(tip * glm::dvec4(p - centre, 0.0));
      lowest = std::min(lowest, p.z);
    }
    for (Vec3& p : cube.positions) p.z += c.gap - lowest;
    soup = test::disjoint_union(soup, cube);
  }
  const Mesh solid = build_mesh(std::move(soup));
  // The oracle: each cube's bottom corners, their gaps the heights above the slab.
  struct Expected {
    double gap;
    Index thinnest;
  };
  std::vector<Expected> expected;
  std::vector<Index> near_vertices;
  for (Index k = 0; k < 3; ++k) {
    Expected e{1e300, no_index};
    for (Index v = 8 * (k + 1); v < 8 * (k + 2); ++v) {
      const double gap = solid.position(v).z;
      if (gap >= wall) continue;
      near_vertices.push_back(v);
      if (gap < e.gap) e = {gap, v};
    }
    expected.push_back(e);
  }
  REQUIRE(near_vertices.size() == 12);
  // The thinnest corner of a cube is its first near vertex for one cube and not for another.
  CHECK(expected[0].thinnest != near_vertices[0]);
  CHECK(expected[1].thinnest == near_vertices[4]);
  std::sort(expected.begin(), expected.end(),
            [](const Expected& a, const Expected& b) { return a.gap < b.gap; });
  for (const int threads : {1, 2}) {
    INFO(threads << " threads");
    PrintCheckOptions options;
    options.min_wall = wall;
    options.threads = threads;
    const PrintCheck check = check_printability(solid, options);
    REQUIRE(check.near_misses.size() == near_vertices.size());
    for (std::size_t i = 0; i < near_vertices.size(); ++i) {
      CHECK(check.near_misses[i].vertex == near_vertices[i]);
      CHECK(check.near_misses[i].distance == Approx(solid.position(near_vertices[i]).z).margin(1e-12));
    }
    REQUIRE(check.places.size() == 3);
    for (std::size_t i = 0; i < 3; ++i) {
      INFO("place " << i);
      const PrintPlace& place = check.places[i];
      CHECK(place.kind == FindingKind::near_miss);
      CHECK(place.size == 4);
      CHECK(place.distance == Approx(expected[i].gap).margin(1e-12));
      CHECK(place.position == solid.position(expected[i].thinnest));
      REQUIRE(place.face != no_index);
      CHECK(solid.face_component(place.face) == solid.vertex_component(expected[i].thinnest));
      CHECK(solid.face_component(place.other_face) == solid.vertex_component(0));
    }
  }
}
