#include <catch2/catch.hpp>

#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "nome/query/triangle_bvh.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

// The reference: every display triangle tested, same ordering and de-duplication as the BVH.
std::vector<RayHit> brute_force(const TriangleBvh& bvh, const Ray& ray) {
  const ShearedRay sheared(ray);
  std::vector<RayHit> hits;
  for (Index t = 0; t < bvh.num_triangles(); ++t) {
    TriangleHit hit;
    if (bvh.intersect(sheared, t, hit)) hits.push_back(bvh.make_hit(ray, t, hit));
  }
  return sorted_unique_hits(std::move(hits));
}

void require_same_hits(const std::vector<RayHit>& a, const std::vector<RayHit>& b) {
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].face == b[i].face);
    CHECK(a[i].triangle == b[i].triangle);
    CHECK(a[i].depth == b[i].depth);
    CHECK(a[i].kind == b[i].kind);
    CHECK(a[i].element == b[i].element);
  }
}

Ray vertical_ray(double x, double y) {
  Ray ray;
  ray.origin = Vec3(x, y, 1.0);
  ray.direction = Vec3(0.0, 0.0, -1.0);
  return ray;
}

}  // namespace

TEST_CASE("rays exactly through shared grid vertices hit every incident face at that vertex", "[kernel]") {
  const Mesh mesh = build_mesh(test::grid(6, 5));
  const TriangleBvh bvh(mesh, {.max_leaf_size = 2});
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const Vec3 p = mesh.position(v);
    const Ray ray = vertical_ray(p.x, p.y);
    const auto hits = bvh.cast_all(ray);
    INFO("vertex " << v);
    require_same_hits(hits, brute_force(bvh, ray));
    REQUIRE(hits.size() == mesh.vertex_corners(v).size());
    for (const RayHit& h : hits) {
      CHECK(h.kind == ElementKind::vertex);
      CHECK(h.element == v);
      CHECK(h.depth == 1.0);
      CHECK(h.point == p);
    }
    const auto nearest = bvh.cast_nearest(ray);
    REQUIRE(nearest);
    CHECK(nearest->face == hits.front().face);
  }
}

TEST_CASE("rays exactly through shared grid edges report the edge on both faces", "[kernel]") {
  const Mesh mesh = build_mesh(test::grid(5, 4));
  const TriangleBvh bvh(mesh);
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    const Edge& edge = mesh.edge(e);
    const Vec3 mid = 0.5 * (mesh.position(edge.vertices[0]) + mesh.position(edge.vertices[1]));
    const Ray ray = vertical_ray(mid.x, mid.y);
    const auto hits = bvh.cast_all(ray);
    INFO("edge " << e);
    require_same_hits(hits, brute_force(bvh, ray));
    REQUIRE(hits.size() == (edge.is_boundary() ? 1u : 2u));
    for (const RayHit& h : hits) {
      CHECK(h.kind == ElementKind::edge);
      CHECK(h.element == e);
      CHECK((h.face == edge.faces[0] || h.face == edge.faces[1]));
    }
  }
}

TEST_CASE("a ray through a fan diagonal reports its face once, as the face interior", "[kernel]") {
  const Mesh mesh = build_mesh(test::grid(3, 3));
  const TriangleBvh bvh(mesh);
  // Each quad (i, j)-(i+1, j+1) is fanned from (i, j): its centre lies on the diagonal.
  const auto hits = bvh.cast_all(vertical_ray(1.5, 2.5));
  REQUIRE(hits.size() == 1);
  CHECK(hits[0].kind == ElementKind::face);
  CHECK(hits[0].element == hits[0].face);
  CHECK(hits[0].face == 7);
  CHECK(hits[0].barycentric[0] + hits[0].barycentric[1] + hits[0].barycentric[2] == Approx(1.0));
}

TEST_CASE("back faces are hit too and all hits come nearest first", "[kernel]") {
  const Mesh mesh = build_mesh(test::cube());
  const TriangleBvh bvh(mesh);
  Ray from_below;
  from_below.origin = Vec3(0.25, 0.3, -5.0);
  from_below.direction = Vec3(0.0, 0.0, 1.0);
  const auto hits = bvh.cast_all(from_below);
  REQUIRE(hits.size() == 2);
  CHECK(hits[0].face == 0);  // z = -1, whose corners wind away from this ray
  CHECK(hits[1].face == 1);
  CHECK(hits[0].depth == Approx(4.0));
  CHECK(hits[1].depth == Approx(6.0));
  CHECK(hits[0].point.z == Approx(-1.0));

  Ray inside = from_below;
  inside.origin = Vec3(0.25, 0.3, 0.0);
  CHECK(bvh.cast_all(inside).size() == 1);
  inside.t_max = 0.5;
  CHECK(bvh.cast_all(inside).empty());
  CHECK_FALSE(bvh.cast_nearest(inside));
}

TEST_CASE("the BVH agrees with brute force on random rays through random surfaces", "[kernel]") {
  std::mt19937 rng{42};
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  struct Case {
    const char* name;
    PolygonSoup soup;
  };
  const Case cases[] = {
      {"torus", test::torus(24, 12)},
      {"Möbius band", test::mobius_band(40, 3)},
      {"Klein bottle (self-intersecting)", test::klein_bottle(24, 12)},
      {"two overlapping tori", test::disjoint_union(test::torus(16, 8), test::torus(12, 9))}};
  for (const Case& c : cases) {
    INFO(c.name);
    const Mesh mesh = build_mesh(c.soup);
    // The two-thread build (normally for large meshes only) must give a tree just as correct.
    for (const Index threshold : {Index{0}, Index{1} << 30}) {
      const TriangleBvh bvh(mesh, {.parallel_build_threshold = threshold});
      std::uniform_int_distribution<Index> pick_vertex(0, mesh.num_vertices() - 1);
      for (int i = 0; i < 200; ++i) {
        Ray ray;
        ray.origin = 4.0 * Vec3(unit(rng), unit(rng), unit(rng));
        // Half the rays aim at a vertex (shared by several faces), half at a random point. A ray at a
        // silhouette or border vertex may pass just beside the surface, so only agreement is required.
        const Vec3 target = i % 2 ? mesh.position(pick_vertex(rng)) : Vec3(unit(rng), unit(rng), unit(rng));
        ray.direction = target - ray.origin;
        const auto hits = bvh.cast_all(ray);
        require_same_hits(hits, brute_force(bvh, ray));
        const auto nearest = bvh.cast_nearest(ray);
        REQUIRE(nearest.has_value() == !hits.empty());
        if (nearest) {
          CHECK(nearest->face == hits.front().face);
          CHECK(nearest->depth == hits.front().depth);
        }
      }
    }
  }
}

TEST_CASE("oblique rays through interior vertices and edges of a rotated grid never slip through",
          "[kernel]") {
  const glm::dmat4 rotation = glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(Vec3(1.0, 2.0, 3.0)));
  const Mesh mesh = transformed(build_mesh(test::grid(8, 8)), rotation);
  const TriangleBvh bvh(mesh);
  const Vec3 normal = Vec3(rotation * glm::dvec4(0.0, 0.0, 1.0, 0.0));
  auto check_ray_at = [&](const Vec3& target) {
    Ray ray;
    ray.origin = target + 2.0 * normal + Vec3(0.01, -0.02, 0.005);
    ray.direction = target - ray.origin;
    const auto hits = bvh.cast_all(ray);
    require_same_hits(hits, brute_force(bvh, ray));
    CHECK_FALSE(hits.empty());
  };
  // Interior targets only: a ray at a border vertex or edge may pass just outside the surface.
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    INFO("vertex " << v);
    if (!mesh.is_boundary_vertex(v)) check_ray_at(mesh.position(v));
  }
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    INFO("edge " << e);
    const Edge& edge = mesh.edge(e);
    if (!edge.is_boundary())
      check_ray_at(0.5 * (mesh.position(edge.vertices[0]) + mesh.position(edge.vertices[1])));
  }
}

TEST_CASE("an empty mesh has nothing to hit", "[kernel]") {
  const TriangleBvh bvh(build_mesh(PolygonSoup{}));
  CHECK(bvh.num_triangles() == 0);
  CHECK(bvh.cast_all(vertical_ray(0, 0)).empty());
  CHECK_FALSE(bvh.cast_nearest(vertical_ray(0, 0)));
}
