#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "nome/query/pick.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

ScreenProjection camera_on_cube() {
  ScreenProjection p;
  p.view = glm::lookAt(Vec3(3.0, 2.5, 4.0), Vec3(0.0), Vec3(0.0, 1.0, 0.0));
  p.projection = glm::perspective(glm::radians(45.0), 800.0 / 600.0, 0.1, 100.0);
  p.viewport = {800.0, 600.0};
  return p;
}

}  // namespace

TEST_CASE("a pixel's ray passes through the points that project to that pixel", "[kernel]") {
  const ScreenProjection p = camera_on_cube();
  const Vec3 point(0.3, -0.2, 0.9);
  const auto pixel = project_to_pixel(p, point);
  REQUIRE(pixel);
  const Ray ray = ray_through_pixel(p, glm::dvec2(*pixel));
  const Vec3 to_point = point - ray.origin;
  const double t = glm::dot(to_point, ray.direction) / glm::dot(ray.direction, ray.direction);
  CHECK(glm::length(ray.origin + t * ray.direction - point) < 1e-9);
  CHECK(t > 0.0);
  CHECK(t < 1.0);
  CHECK_FALSE(project_to_pixel(p, Vec3(6.0, 5.0, 8.0)));  // behind the eye
}

TEST_CASE("clicking near a visible corner picks that vertex, farther away picks nothing", "[kernel]") {
  const Mesh mesh = build_mesh(test::cube());
  const TriangleBvh bvh(mesh);
  const ScreenProjection p = camera_on_cube();
  // Vertex 7 = (1, 1, 1) faces the camera.
  const auto corner = project_to_pixel(p, mesh.position(7));
  REQUIRE(corner);
  const glm::dvec2 centre(*corner);
  // Slightly inside the silhouette towards the cube's centre, so the ray hits a face.
  const auto middle = project_to_pixel(p, Vec3(0.0));
  const glm::dvec2 inward = glm::normalize(glm::dvec2(*middle) - centre);
  CHECK(pick_vertex(mesh, bvh, p, centre + 3.0 * inward, 6.0) == VertexId(7));
  CHECK_FALSE(pick_vertex(mesh, bvh, p, centre + 40.0 * inward, 6.0));
  // Far outside the cube there is no face and so no vertex.
  CHECK_FALSE(pick_vertex(mesh, bvh, p, {2.0, 2.0}, 6.0));
}

TEST_CASE("clicking a face picks the frontmost face under the cursor", "[kernel]") {
  const Mesh mesh = build_mesh(test::cube());
  const TriangleBvh bvh(mesh);
  const ScreenProjection p = camera_on_cube();
  // Centres of the three faces seen from (3, 2.5, 4): +z (face 1), +y (face 3), +x (face 5).
  const struct {
    Vec3 centre;
    Index face;
  } rows[] = {{{0, 0, 1}, 1}, {{0, 1, 0}, 3}, {{1, 0, 0}, 5}};
  for (const auto& row : rows) {
    const auto pixel = project_to_pixel(p, row.centre);
    REQUIRE(pixel);
    CHECK(pick_face(bvh, p, glm::dvec2(*pixel)) == FaceId(row.face));
    // The ray continues through the hidden far face behind it.
    const auto hits = bvh.cast_all(ray_through_pixel(p, glm::dvec2(*pixel)));
    REQUIRE(hits.size() == 2);
    CHECK(hits[0].face == row.face);
  }
}
