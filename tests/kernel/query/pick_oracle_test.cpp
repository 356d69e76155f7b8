#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "nome/query/pick.hpp"
#include "nome/query/pick_edge.hpp"
#include "nome/query/rim_pick.hpp"
#include "support/shapes.hpp"

using namespace nome;

// Picking against oracles written here: Möller-Trumbore over each face's fan, a camera whose matrices are
// written out by hand, and pick tolerances measured in pixels by hand.
namespace {

// Möller and Trumbore 1997, two-sided: t along the ray, (u, v) the weights of b and c.
bool pick_oracle_moller_trumbore(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c, double& t,
                                 double& u, double& v) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = glm::cross(ray.direction, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-300) return false;
  const Vec3 s = ray.origin - a;
  u = glm::dot(s, p) / det;
  const Vec3 q = glm::cross(s, e1);
  v = glm::dot(ray.direction, q) / det;
  t = glm::dot(e2, q) / det;
  return u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t >= ray.t_min && t <= ray.t_max;
}

struct PickOracleHit {
  Index face;
  std::array<Index, 3> vertices;  // the fan triangle's
  std::array<double, 3> barycentric;
  double depth;
  Vec3 point;
  double margin;  // how far inside the triangle the hit is, in barycentric units
};

// Every hit of the ray on the fans from each face's first vertex (the faces here are convex), nearest first.
std::vector<PickOracleHit> pick_oracle_hits(const Mesh& mesh, const Ray& ray) {
  std::vector<PickOracleHit> hits;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto fv = mesh.face_vertices(f);
    for (std::size_t i = 1; i + 1 < fv.size(); ++i) {
      double t, u, v;
      const Vec3 &a = mesh.position(fv[0]), &b = mesh.position(fv[i]), &c = mesh.position(fv[i + 1]);
      if (!pick_oracle_moller_trumbore(ray, a, b, c, t, u, v)) continue;
      hits.push_back({f,
                      {fv[0], fv[i], fv[i + 1]},
                      {1.0 - u - v, u, v},
                      t,
                      ray.origin + t * ray.direction,
                      std::min({1.0 - u - v, u, v})});
    }
  }
  std::sort(hits.begin(), hits.end(),
            [](const PickOracleHit& x, const PickOracleHit& y) { return x.depth < y.depth; });
  return hits;
}

bool pick_oracle_close(const Vec3& a, const Vec3& b, double tolerance) {
  return glm::length(a - b) <= tolerance * (1.0 + glm::length(b));
}

// A camera at the origin looking down -z, written out: perspective with focal factor f, aspect `aspect`,
// near 1 and far 3 (OpenGL's matrix: NDC z = -1 at the near plane, +1 at the far plane).
glm::dmat4 pick_oracle_perspective(double f, double aspect) {
  const double near = 1.0, far = 3.0;
  glm::dmat4 m(0.0);  // m[column][row]
  m[0][0] = f / aspect;
  m[1][1] = f;
  m[2][2] = (far + near) / (near - far);      // -2
  m[3][2] = 2.0 * far * near / (near - far);  // -3
  m[2][3] = -1.0;
  return m;
}

// Orthographic over x, y in [-2, 2], z from -0.1 to -10, written out.
glm::dmat4 pick_oracle_ortho() {
  glm::dmat4 m(1.0);
  m[0][0] = 0.5;
  m[1][1] = 0.5;
  m[2][2] = -2.0 / 9.9;
  m[3][2] = -10.1 / 9.9;
  return m;
}

// 400 x 400 pixels over [-2, 2]^2: world (x, y) is pixel (100 (x + 2), 100 (2 - y)).
ScreenProjection pick_oracle_flat_camera() {
  ScreenProjection p;
  p.projection = pick_oracle_ortho();
  p.viewport = {400.0, 400.0};
  return p;
}

// The camera of pick_oracle_perspective(1, 1), not turned, over 400 x 400 pixels: camera point (x, y, z)
// is pixel (200 (1 - x / z), 200 (1 + y / z)).
glm::dvec2 pick_oracle_pixel(const Vec3& p) {
  return {200.0 * (1.0 - p.x / p.z), 200.0 * (1.0 + p.y / p.z)};
}

// That camera's ray through a pixel: from the near plane (z = -1) at t = 0 to the far plane (z = -3), t = 1.
Ray pick_oracle_ray(glm::dvec2 pixel) {
  const Vec3 near(pixel.x / 200.0 - 1.0, 1.0 - pixel.y / 200.0, -1.0);
  return Ray{near, 2.0 * near, 0.0, 1.0};
}

Index pick_oracle_edge(const Mesh& mesh, Index u, Index w) {
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    const auto [a, b] = mesh.edge(e).vertices;
    if ((a == u && b == w) || (a == w && b == u)) return e;
  }
  return no_index;
}

}  // namespace

TEST_CASE("a single triangle's hit has the depth and barycentric weights computed by hand", "[kernel]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // Straight down through (0.2, 0.3): weights 0.5, 0.2, 0.3; the direction of length 2 halves the depth.
  TriangleHit hit;
  REQUIRE(intersect_triangle(ShearedRay(Ray{{0.2, 0.3, 5.0}, {0.0, 0.0, -2.0}}), a, b, c, hit));
  CHECK(hit.depth == Approx(2.5).epsilon(1e-14));
  CHECK(hit.barycentric[0] == Approx(0.5).epsilon(1e-14));
  CHECK(hit.barycentric[1] == Approx(0.2).epsilon(1e-14));
  CHECK(hit.barycentric[2] == Approx(0.3).epsilon(1e-14));
  // From below (the back side), along +z: the same point and weights.
  REQUIRE(intersect_triangle(ShearedRay(Ray{{0.2, 0.3, -1.0}, {0.0, 0.0, 4.0}}), a, b, c, hit));
  CHECK(hit.depth == Approx(0.25).epsilon(1e-14));
  CHECK(hit.barycentric[1] == Approx(0.2).epsilon(1e-14));
  CHECK(hit.barycentric[2] == Approx(0.3).epsilon(1e-14));
  // Outside the triangle, and beyond t_max or before t_min.
  CHECK_FALSE(intersect_triangle(ShearedRay(Ray{{0.6, 0.6, 5.0}, {0.0, 0.0, -1.0}}), a, b, c, hit));
  CHECK_FALSE(intersect_triangle(ShearedRay(Ray{{0.2, 0.3, 5.0}, {0.0, 0.0, -1.0}, 0.0, 4.9}), a, b, c, hit));
  CHECK_FALSE(intersect_triangle(ShearedRay(Ray{{0.2, 0.3, 5.0}, {0.0, 0.0, -1.0}, 5.1, 9.0}), a, b, c, hit));
  // Exactly at t_max and t_min: both ends belong to the ray.
  CHECK(intersect_triangle(ShearedRay(Ray{{0.2, 0.3, 5.0}, {0.0, 0.0, -1.0}, 0.0, 5.0}), a, b, c, hit));
  CHECK(intersect_triangle(ShearedRay(Ray{{0.2, 0.3, 5.0}, {0.0, 0.0, -1.0}, 5.0, 9.0}), a, b, c, hit));

  // Oblique rays whose dominant axis is x, y or z, either sign, against Möller-Trumbore.
  const Vec3 p(0.9, -0.4, 0.3), q(-0.5, 1.1, 0.2), r(0.1, 0.3, -1.2);
  const Vec3 target = 0.2 * p + 0.5 * q + 0.3 * r;
  for (const Vec3& d : {Vec3(3.0, 0.4, -0.7), Vec3(-3.0, 0.4, 0.7), Vec3(0.5, 2.5, -0.3),
                        Vec3(0.5, -2.5, 0.3), Vec3(0.2, -0.6, 1.9), Vec3(-0.2, 0.6, -1.9)}) {
    INFO("direction " << d.x << " " << d.y << " " << d.z);
    const Ray ray{target - 1.5 * d, d};
    double t, u, v;
    REQUIRE(pick_oracle_moller_trumbore(ray, p, q, r, t, u, v));
    REQUIRE(intersect_triangle(ShearedRay(ray), p, q, r, hit));
    CHECK(hit.depth == Approx(1.5).epsilon(1e-12));
    CHECK(t == Approx(1.5).epsilon(1e-12));
    CHECK(hit.barycentric[0] == Approx(0.2).epsilon(1e-12));
    CHECK(hit.barycentric[1] == Approx(0.5).epsilon(1e-12));
    CHECK(hit.barycentric[2] == Approx(0.3).epsilon(1e-12));
  }
}

TEST_CASE("every hit of random rays equals Möller-Trumbore over the face fans, self-intersections too",
          "[kernel]") {
  std::mt19937 rng{42};
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const PolygonSoup soups[] = {test::torus(20, 10), test::klein_bottle(16, 10),
                               test::disjoint_union(test::torus(12, 8), test::torus(10, 7, 1.2, 0.5))};
  int compared = 0, with_several = 0;
  for (const PolygonSoup& soup : soups) {
    const Mesh mesh = build_mesh(soup);
    const TriangleBvh bvh(mesh, {.max_leaf_size = 3});
    for (int i = 0; i < 150; ++i) {
      Ray ray;
      ray.origin = 4.0 * Vec3(unit(rng), unit(rng), unit(rng));
      ray.direction = 0.5 * Vec3(unit(rng), unit(rng), unit(rng)) - ray.origin;
      if (i % 3 == 0) ray.t_max = 0.9;  // a ray that ends inside the surface
      const std::vector<PickOracleHit> expected = pick_oracle_hits(mesh, ray);
      // Rays through an edge or near one: Möller-Trumbore is not watertight there.
      if (std::any_of(expected.begin(), expected.end(),
                      [](const PickOracleHit& h) { return h.margin < 1e-6; }))
        continue;
      const std::vector<RayHit> hits = bvh.cast_all(ray);
      INFO("ray " << i);
      REQUIRE(hits.size() == expected.size());
      ++compared;
      with_several += hits.size() > 2;
      for (std::size_t k = 0; k < hits.size(); ++k) {
        const RayHit& h = hits[k];
        const PickOracleHit& e = expected[k];
        CHECK(h.face == e.face);
        CHECK(h.kind == ElementKind::face);
        CHECK(h.element == e.face);
        CHECK(h.depth == Approx(e.depth).epsilon(1e-9));
        CHECK(pick_oracle_close(h.point, e.point, 1e-9));
        for (int c = 0; c < 3; ++c) {
          CHECK(bvh.triangle_vertex(h.triangle, c) == e.vertices[c]);
          CHECK(h.barycentric[c] == Approx(e.barycentric[c]).margin(1e-9));
        }
      }
      const auto nearest = bvh.cast_nearest(ray);
      REQUIRE(nearest.has_value() == !expected.empty());
      if (nearest) {
        CHECK(nearest->face == expected.front().face);
        CHECK(nearest->depth == Approx(expected.front().depth).epsilon(1e-9));
        CHECK(pick_oracle_close(nearest->point, expected.front().point, 1e-9));
      }
    }
  }
  CHECK(compared > 300);
  CHECK(with_several > 20);
}

TEST_CASE("a ray exactly through a cube's corner or edge hits it on every face there, then the far face",
          "[kernel]") {
  const Mesh cube = build_mesh(test::cube());
  const TriangleBvh bvh(cube);
  // Direction (-1, -0.5, -2): the shears are exact, so the ray passes exactly through the corner (1, 1, 1)
  // (vertex 7, faces 1, 3, 5) at t = 1, then leaves through z = -1 (face 0, corners 0 2 3 1) at t = 2,
  // at (0, 0.5, -1): in the fan triangle of vertices 0, 2, 3 with weights 1/4, 1/4, 1/2.
  const Ray through_corner{{2.0, 1.5, 3.0}, {-1.0, -0.5, -2.0}};
  const auto hits = bvh.cast_all(through_corner);
  REQUIRE(hits.size() == 4);
  for (int k = 0; k < 3; ++k) {
    CHECK(hits[k].face == Index(2 * k + 1));
    CHECK(hits[k].kind == ElementKind::vertex);
    CHECK(hits[k].element == 7);
    CHECK(hits[k].depth == 1.0);
    CHECK(hits[k].point == Vec3(1.0, 1.0, 1.0));
  }
  CHECK(hits[3].face == 0);
  CHECK(hits[3].kind == ElementKind::face);
  CHECK(hits[3].depth == Approx(2.0).epsilon(1e-14));
  CHECK(pick_oracle_close(hits[3].point, Vec3(0.0, 0.5, -1.0), 1e-15));
  const std::array<Index, 3> far_triangle{0, 2, 3};
  const std::array<double, 3> far_weights{0.25, 0.25, 0.5};
  for (int c = 0; c < 3; ++c) {
    CHECK(bvh.triangle_vertex(hits[3].triangle, c) == far_triangle[c]);
    CHECK(hits[3].barycentric[c] == Approx(far_weights[c]).epsilon(1e-14));
  }
  const auto nearest = bvh.cast_nearest(through_corner);
  REQUIRE(nearest);
  CHECK(nearest->face == 1);  // equal depths: the lowest face first
  CHECK(nearest->kind == ElementKind::vertex);

  // Through the middle (1, 0, 1) of the edge from vertex 5 to 7 (faces 1 and 5), out at (0, -0.5, -1):
  // fan triangle 0, 3, 1 with weights 1/2, 1/4, 1/4.
  const auto edge_hits = bvh.cast_all(Ray{{2.0, 0.5, 3.0}, {-1.0, -0.5, -2.0}});
  REQUIRE(edge_hits.size() == 3);
  const Index edge = pick_oracle_edge(cube, 5, 7);
  for (int k = 0; k < 2; ++k) {
    CHECK(edge_hits[k].face == Index(4 * k + 1));
    CHECK(edge_hits[k].kind == ElementKind::edge);
    CHECK(edge_hits[k].element == edge);
    CHECK(edge_hits[k].point == Vec3(1.0, 0.0, 1.0));
  }
  CHECK(edge_hits[2].face == 0);
  CHECK(edge_hits[2].depth == Approx(2.0).epsilon(1e-14));
  const std::array<Index, 3> other_triangle{0, 3, 1};
  const std::array<double, 3> other_weights{0.5, 0.25, 0.25};
  for (int c = 0; c < 3; ++c) {
    CHECK(bvh.triangle_vertex(edge_hits[2].triangle, c) == other_triangle[c]);
    CHECK(edge_hits[2].barycentric[c] == Approx(other_weights[c]).epsilon(1e-14));
  }
}

TEST_CASE("a point projects to the pixel and depth computed by hand, and its pixel's ray runs near to far",
          "[kernel]") {
  ScreenProjection p;
  p.projection = pick_oracle_perspective(1.0, 2.0);
  // The eye at (5, 6, 7), not turned: a world point is its camera point plus the eye.
  p.view = glm::translate(glm::dmat4(1.0), Vec3(-5.0, -6.0, -7.0));
  p.viewport = {800.0, 400.0};
  p.origin = {10.0, 20.0};
  // Camera point (1, 0.5, -2): clip (0.5, 0.5, 1, 2), NDC (0.25, 0.25, 0.5); x = 10 + 1.25 / 2 * 800,
  // y = 20 + 0.75 / 2 * 400 (down the window).
  const auto pixel = project_to_pixel(p, Vec3(6.0, 6.5, 5.0));
  REQUIRE(pixel);
  CHECK(pixel->x == Approx(510.0).epsilon(1e-14));
  CHECK(pixel->y == Approx(170.0).epsilon(1e-14));
  CHECK(pixel->z == Approx(0.5).epsilon(1e-14));
  // The ray through that pixel: from camera (0.5, 0.25, -1) on the near plane to (1.5, 0.75, -3) on the far.
  const Ray ray = ray_through_pixel(p, {510.0, 170.0});
  CHECK(pick_oracle_close(ray.origin, Vec3(5.5, 6.25, 6.0), 1e-13));
  CHECK(pick_oracle_close(ray.direction, Vec3(1.0, 0.5, -2.0), 1e-13));
  CHECK(ray.t_min == 0.0);
  CHECK(ray.t_max == 1.0);
  // The window's corners are the frustum's: top left is NDC (-1, 1), bottom right (1, -1).
  const Ray corner = ray_through_pixel(p, {10.0, 20.0});
  CHECK(pick_oracle_close(corner.origin, Vec3(5.0 - 2.0, 6.0 + 1.0, 7.0 - 1.0), 1e-13));
  const Ray other_corner = ray_through_pixel(p, {810.0, 420.0});
  CHECK(pick_oracle_close(other_corner.origin + other_corner.direction, Vec3(5.0 + 6.0, 6.0 - 3.0, 7.0 - 3.0),
                          1e-13));
  // In the eye's plane or behind it there is no pixel.
  CHECK_FALSE(project_to_pixel(p, Vec3(6.0, 6.0, 7.0)));
  CHECK_FALSE(project_to_pixel(p, Vec3(6.0, 6.0, 8.0)));
}

TEST_CASE("a vertex or an edge is picked within the pixel tolerance measured by hand, never beyond it",
          "[kernel]") {
  // Two unit squares at z = -1 (faces 0: x in [0, 1], 1: x in [1, 2]), and behind them at z = -3 a grid
  // shifted by half a square, whose vertical edge x = 0.5 lies right under the clicks below.
  const Mesh front =
      transformed(build_mesh(test::grid(2, 1)), glm::translate(glm::dmat4(1.0), Vec3(0, 0, -1)));
  PolygonSoup both = test::disjoint_union(
      to_soup(front),
      to_soup(transformed(build_mesh(test::grid(2, 1)), glm::translate(glm::dmat4(1.0), Vec3(-0.5, 0, -3)))));
  const Mesh mesh = build_mesh(std::move(both));
  const TriangleBvh bvh(mesh);
  const ScreenProjection p = pick_oracle_flat_camera();
  // Vertex 1 at (1, 0) is pixel (300, 200); the click (303, 196) is 5 pixels from it, over face 1.
  const auto pixel = project_to_pixel(p, mesh.position(1));
  REQUIRE(pixel);
  CHECK(pixel->x == 300.0);
  CHECK(pixel->y == 200.0);
  CHECK(pick_face(bvh, p, {303.0, 196.0}) == FaceId(1));
  CHECK(pick_vertex(mesh, bvh, p, {303.0, 196.0}, 5.0) == VertexId(1));
  CHECK_FALSE(pick_vertex(mesh, bvh, p, {303.0, 196.0}, 4.999));
  CHECK(nearest_corner_on_screen(mesh, FaceId(1), p, {303.0, 196.0}, 5.0) == VertexId(1));
  // Nearer to vertex 4 at (1, 1), pixel (300, 100): 6 pixels across, 8 down.
  CHECK(pick_vertex(mesh, bvh, p, {306.0, 108.0}, 10.0) == VertexId(4));
  CHECK_FALSE(pick_vertex(mesh, bvh, p, {306.0, 108.0}, 9.999));
  // Outside every face nothing is picked, whatever the tolerance.
  CHECK_FALSE(pick_vertex(mesh, bvh, p, {399.0, 10.0}, 1e6));

  // The click (250, 197) is over face 0 (x = 0.5, y = 0.03), 3 pixels from its bottom edge (vertices 0, 1),
  // 50 from its sides; the back grid's edge under it does not count.
  const Index bottom = pick_oracle_edge(mesh, 0, 1);
  CHECK(pick_face(bvh, p, {250.0, 197.0}) == FaceId(0));
  CHECK(pick_edge(mesh, bvh, p, {250.0, 197.0}, 3.0) == EdgeId(bottom));
  CHECK_FALSE(pick_edge(mesh, bvh, p, {250.0, 197.0}, 2.999));
  // Near the corner (1, 1) of face 0, pixel (300, 100): 2 pixels from the right edge, 4 from the top one.
  CHECK(pick_edge(mesh, bvh, p, {298.0, 104.0}, 10.0) == EdgeId(pick_oracle_edge(mesh, 1, 4)));
  CHECK(nearest_edge_on_screen(mesh, FaceId(0), p, {298.0, 104.0}, 10.0) ==
        EdgeId(pick_oracle_edge(mesh, 1, 4)));
  // Beyond the ends of sides the distance is to their ends: from (196, 203), just outside the corner
  // (200, 200), the left and bottom sides are 5 pixels away (to that corner), though their lines are 4 and 3.
  CHECK(nearest_edge_on_screen(mesh, FaceId(0), p, {196.0, 203.0}, 4.999) == std::nullopt);
  CHECK(nearest_edge_on_screen(mesh, FaceId(0), p, {196.0, 203.0}, 5.0).has_value());
}

TEST_CASE("rim cubes and their entry depths computed by hand", "[kernel]") {
  RimLines rims;
  // A closed line of two vertices is one segment (length 2); a line of one vertex takes the mean of all.
  const std::vector<Vec3> pair{{0, 0, 0}, {2, 0, 0}};
  rims.add_line(pair, std::vector<std::string>{"a", "b"}, true);
  const std::vector<Vec3> single{{0, 5, 0}};
  rims.add_line(single, std::vector<std::string>{"c"}, false);
  const std::vector<Vec3> open{{0, 10, 0}, {0, 11, 0}, {0, 11, 3}, {0, 15, 3}};
  rims.add_line(open, std::vector<std::string>{"d", "e", "f", "g"}, false);
  const auto half = rim_cube_half_sizes(rims, 0.25);
  REQUIRE(half.size() == 7);
  CHECK(half[0] == Approx(0.5).epsilon(1e-14));
  CHECK(half[1] == Approx(0.5).epsilon(1e-14));
  CHECK(half[2] == Approx(0.25 * (2.0 + 1.0 + 3.0 + 4.0) / 4.0).epsilon(1e-14));
  CHECK(half[3] == Approx(0.25).epsilon(1e-14));
  CHECK(half[4] == Approx(0.5).epsilon(1e-14));
  CHECK(half[5] == Approx(0.875).epsilon(1e-14));
  CHECK(half[6] == Approx(1.0).epsilon(1e-14));
  RimLines lone;
  lone.add_line(single, std::vector<std::string>{"c"}, true);
  CHECK(rim_cube_half_sizes(lone, 0.3) == std::vector<double>{0.3});

  // An oblique ray: direction (1, 2, -4) from (-1, -1, 6) is in vertex 1's cube [1.5, 2.5] x [-0.5, 0.5] x
  // [-0.5, 0.5] for x at t in [2.5, 3.5] but for y at [0.25, 0.75]: a miss. From (0.8, -2.4, 4.8) instead:
  // x at [0.7, 1.7], y at [0.95, 1.45], z at [1.075, 1.325]: it enters at 1.075.
  CHECK_FALSE(pick_rim_vertex(rims, half, Ray{{-1.0, -1.0, 6.0}, {1.0, 2.0, -4.0}}));
  const auto hit = pick_rim_vertex(rims, half, Ray{{0.8, -2.4, 4.8}, {1.0, 2.0, -4.0}});
  REQUIRE(hit);
  CHECK(hit->vertex == RimVertexId(1));
  CHECK(hit->depth == Approx(1.075).epsilon(1e-14));
  // A ray along a cube's face (x = 2.5, direction in y) touches it: the slabs meet at one t.
  const auto grazing = pick_rim_vertex(rims, half, Ray{{2.5, -3.0, 0.0}, {0.0, 1.0, 0.0}});
  REQUIRE(grazing);
  CHECK(grazing->vertex == RimVertexId(1));
  CHECK(grazing->depth == Approx(2.5).epsilon(1e-14));
  // Two cubes on the ray: the nearer one (vertex 0, entered at t = 1.5) wins over vertex 1's.
  const auto first = pick_rim_vertex(rims, half, Ray{{-2.0, 0.1, 0.0}, {1.0, 0.0, 0.0}});
  REQUIRE(first);
  CHECK(first->vertex == RimVertexId(0));
  CHECK(first->depth == Approx(1.5).epsilon(1e-14));
  const auto back = pick_rim_vertex(rims, half, Ray{{4.0, 0.1, 0.0}, {-1.0, 0.0, 0.0}});
  REQUIRE(back);
  CHECK(back->vertex == RimVertexId(1));
  CHECK(back->depth == Approx(1.5).epsilon(1e-14));
}

TEST_CASE("of several corners in reach the one nearest on screen wins, on the frontmost of stacked faces",
          "[kernel]") {
  // Tilted hexagons stacked in front of the camera, added in random order with their corners starting
  // anywhere: the frontmost face is often neither the first face hit by index nor the BVH's first
  // triangle, and several of its corners at different depths lie within the reach.
  ScreenProjection p;
  p.projection = pick_oracle_perspective(1.0, 1.0);
  p.viewport = {400.0, 400.0};
  const double reach = 40.0;
  std::mt19937 rng{42};
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tested = 0, not_first_in_reach = 0, not_last_in_reach = 0, not_first_face = 0, deeper_wins = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::vector<Vec3>> layers;
    for (int k = 0; k < 5; ++k) {
      const double depth = -1.3 - 1.3 * unit(rng), radius = 0.25 + 0.2 * unit(rng);
      const Vec3 centre(0.1 * depth * (unit(rng) - 0.5), 0.1 * depth * (unit(rng) - 0.5), depth);
      const glm::dmat4 tilt =
          glm::rotate(glm::rotate(glm::dmat4(1.0), 1.4 * (unit(rng) - 0.5), Vec3(1, 0, 0)),
                      1.4 * (unit(rng) - 0.5), Vec3(0, 1, 0));
      const double start = 6.283185307179586 * unit(rng);
      std::vector<Vec3> corners;
      for (int i = 0; i < 6; ++i) {
        const double a = start + 6.283185307179586 * i / 6.0;
        corners.push_back(centre +
                          Vec3(tilt * glm::dvec4(radius * std::cos(a), radius * std::sin(a), 0.0, 0.0)));
      }
      layers.push_back(std::move(corners));
    }
    PolygonSoup soup;
    for (const auto& corners : layers) {
      std::vector<Index> face;
      for (const Vec3& c : corners) face.push_back(soup.add_vertex(c));
      soup.add_face(face);
    }
    const Mesh mesh = build_mesh(std::move(soup));
    const TriangleBvh bvh(mesh);
    const glm::dvec2 cursor = pick_oracle_pixel(Vec3(0.0, 0.0, -2.0)) +
                              glm::dvec2(60.0 * (unit(rng) - 0.5), 60.0 * (unit(rng) - 0.5));
    // The oracle: the nearest hit by Möller-Trumbore, then the face's corner nearest the cursor by hand.
    const auto hits = pick_oracle_hits(mesh, pick_oracle_ray(cursor));
    if (hits.empty()) {
      CHECK_FALSE(pick_vertex(mesh, bvh, p, cursor, reach));
      continue;
    }
    if (hits[0].margin < 1e-9 || (hits.size() > 1 && hits[1].depth - hits[0].depth < 1e-9)) continue;
    const Index front = hits[0].face;
    std::vector<Index> in_reach;
    Index nearest = no_index;
    double nearest_distance = reach;
    for (const Index v : mesh.face_vertices(front)) {
      const double d = glm::length(pick_oracle_pixel(mesh.position(v)) - cursor);
      if (d > reach) continue;
      in_reach.push_back(v);
      if (d < nearest_distance) nearest_distance = d, nearest = v;
    }
    INFO("trial " << trial);
    CHECK(pick_face(bvh, p, cursor) == FaceId(front));
    if (nearest == no_index) {
      CHECK_FALSE(pick_vertex(mesh, bvh, p, cursor, reach));
      continue;
    }
    CHECK(pick_vertex(mesh, bvh, p, cursor, reach) == VertexId(nearest));
    ++tested;
    not_first_in_reach += nearest != in_reach.front();
    not_last_in_reach += nearest != in_reach.back();
    not_first_face += front != std::min_element(hits.begin(), hits.end(), [](const auto& a, const auto& b) {
                                 return a.face < b.face;
                               })->face;
    for (const Index v : in_reach) deeper_wins += mesh.position(v).z > mesh.position(nearest).z;
  }
  // Each case named above occurred: the checks compared real choices.
  CHECK(tested > 100);
  CHECK(not_first_in_reach > 10);
  CHECK(not_last_in_reach > 10);
  CHECK(not_first_face > 10);
  CHECK(deeper_wins > 10);
}
