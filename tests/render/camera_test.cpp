#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "render/camera.hpp"
#include "render/scene_camera.hpp"
#include "support/shapes.hpp"

using namespace nome;
using render::Camera;

namespace {

glm::dvec3 project(const Camera& camera, const glm::dvec3& p, double aspect) {
  const glm::dvec4 clip =
      glm::dmat4(camera.projection_matrix(aspect)) * glm::dmat4(camera.view_matrix()) * glm::dvec4(p, 1.0);
  return glm::dvec3(clip) / clip.w;
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-6) {
  return glm::length(a - b) < eps;
}

}  // namespace

TEST_CASE("view angles: azimuth about +Y, elevation above the XZ plane", "[render]") {
  Camera camera;
  camera.distance = 2.0;
  camera.set_view(0, 0);
  CHECK(near(camera.eye(), {0, 0, 2}));
  camera.set_view(90, 0);
  CHECK(near(camera.eye(), {2, 0, 0}));
  camera.set_view(0, 90);
  CHECK(near(camera.eye(), {0, 2, 0}));
  camera.set_view(180, -30);
  CHECK(near(camera.eye(), {0, -1, -std::sqrt(3.0)}));
  // No roll: screen right stays horizontal.
  camera.set_view(37, 21);
  CHECK(std::abs((camera.orientation * glm::dvec3(1, 0, 0)).y) < 1e-12);
}

TEST_CASE("fit frames every point with the margin to spare", "[render]") {
  const Mesh torus = build_mesh(test::torus(24, 12, 3.0, 1.0));
  for (double aspect : {0.5, 4.0 / 3.0, 2.5}) {
    for (auto [az, el] : {std::pair{30.0, 25.0}, {0.0, 0.0}, {200.0, -60.0}, {90.0, 90.0}}) {
      Camera camera;
      camera.set_view(az, el);
      camera.fit(torus.positions(), aspect, 0.1);
      double extent = 0.0;
      for (const Vec3& p : torus.positions()) {
        const glm::dvec3 ndc = project(camera, p, aspect);
        REQUIRE(std::abs(ndc.x) <= 0.9 + 1e-6);
        REQUIRE(std::abs(ndc.y) <= 0.9 + 1e-6);
        REQUIRE(std::abs(ndc.z) < 1.0);  // inside the depth range too
        extent = std::max({extent, std::abs(ndc.x), std::abs(ndc.y)});
      }
      CHECK(extent > 0.85);  // tight, not merely inside
    }
  }
}

TEST_CASE("the kernel's pick ray through the picture's centre meets the target", "[render]") {
  Camera camera;
  camera.set_view(30, 25);
  camera.fit(build_mesh(test::cube()).positions(), 1.5);
  const ScreenProjection screen = camera.screen_projection({300, 200});
  const nome::Ray ray = ray_through_pixel(screen, {150, 100});
  const glm::dvec3 direction = glm::normalize(ray.direction);
  const double along = glm::dot(camera.target - ray.origin, direction);
  CHECK(near(ray.origin + along * direction, camera.target, 1e-6));
  const auto pixel = project_to_pixel(screen, camera.target + camera.orientation * glm::dvec3(0.2, 0, 0));
  REQUIRE(pixel);
  CHECK(pixel->x > 150.0);  // screen right is camera right
  CHECK(pixel->y == Approx(100.0));
}

TEST_CASE("arcball drags cancel when reversed and pan keeps the grabbed point under the mouse", "[render]") {
  Camera camera;
  camera.set_view(30, 25);
  const glm::dquat start = camera.orientation;
  camera.arcball({0.1, 0.2}, {0.4, -0.1}, 1.0);
  CHECK(std::abs(glm::dot(camera.orientation, start)) < 0.999);
  camera.arcball({0.4, -0.1}, {0.1, 0.2}, 1.0);
  CHECK(std::abs(glm::dot(camera.orientation, start)) == Approx(1.0));
  // Dragging right turns the scene right: the point nearest the eye moves right on screen.
  Camera turning;
  turning.distance = 5.0;
  const glm::dvec3 front(0, 0, 1);
  turning.arcball({0, 0}, {0.2, 0}, 1.0);
  CHECK(project(turning, front, 1.0).x > 0.01);

  Camera panning;
  panning.distance = 5.0;
  const glm::dvec3 grabbed = panning.target + glm::dvec3(0.3, 0.1, 0);
  const glm::dvec3 before = project(panning, grabbed, 1.0);
  panning.pan({before.x, before.y}, {before.x + 0.2, before.y - 0.1}, 1.0);
  const glm::dvec3 after = project(panning, grabbed, 1.0);
  CHECK(after.x == Approx(before.x + 0.2));
  CHECK(after.y == Approx(before.y - 0.1));
}

TEST_CASE("an orthographic lens: depth does not shrink, fit still frames every point", "[render]") {
  Camera camera;
  camera.lens.is_orthographic = true;
  camera.set_view(0, 0);
  const std::vector<glm::dvec3> points = {{-1, -1, -3}, {1, 1, -3}, {-1, -1, 3}, {1, 1, 3}};
  camera.fit(points, 1.0);
  // The near and far squares land on the same pixels: no perspective.
  CHECK(near(glm::dvec3(glm::dvec2(project(camera, {1, 1, -3}, 1.0)), 0.0),
             glm::dvec3(glm::dvec2(project(camera, {1, 1, 3}, 1.0)), 0.0)));
  for (const glm::dvec3& p : points) {
    const glm::dvec3 ndc = project(camera, p, 1.0);
    CHECK(std::abs(ndc.x) <= 1.0);
    CHECK(std::abs(ndc.y) <= 1.0);
    CHECK(std::abs(ndc.z) <= 1.0);
  }
  CHECK(std::abs(project(camera, {1, 1, 0}, 1.0).x) > 0.9);  // and fills the picture to the margin
  camera.lens.is_orthographic = false;
  CHECK(project(camera, {1, 1, 3}, 1.0).x > project(camera, {1, 1, -3}, 1.0).x);
}

TEST_CASE("a scene's camera chooses the lens: projection and field of view", "[render]") {
  scene::RenderDefaults d;
  CHECK_FALSE(render::scene_lens(d).is_orthographic);
  CHECK(render::scene_lens(d).fov_y_degrees == 30.0);
  d.camera_projection = "NOME_ORTHOGONAL";
  CHECK(render::scene_lens(d).is_orthographic);
  d.camera_projection = "NOME_ORTHOGRAPHIC";
  CHECK(render::scene_lens(d).is_orthographic);
  d.camera_projection = "NOME_PERSPECTIVE";
  d.camera_frustum = {45, 1.5, 0.1, 100};
  CHECK_FALSE(render::scene_lens(d).is_orthographic);
  CHECK(render::scene_lens(d).fov_y_degrees == 45.0);
  d.camera_frustum = {0, 1.5, 0.1, 100};  // no usable angle: the default stays
  CHECK(render::scene_lens(d).fov_y_degrees == 30.0);
  d.camera_projection = "NOME_FRUSTUM";
  d.camera_frustum = {-1, 1, -1, 1, 1, 10};  // bottom and top at 45 degrees each side of the near plane
  CHECK(render::scene_lens(d).fov_y_degrees == Approx(90.0));
  d.camera_frustum = {-10, 10, -10, 10, -1, 10};  // light_test's negative near plane: no angle
  CHECK(render::scene_lens(d).fov_y_degrees == 30.0);
  // A perspective camera turns the lens it is given back into a perspective one, orthographic or not.
  render::Lens orthographic;
  orthographic.is_orthographic = true;
  for (const char* perspective : {"NOME_FRUSTUM", "NOME_FRUTUM", "NOME_PERSPECTIVE"}) {
    INFO(perspective);
    d.camera_projection = perspective;
    CHECK_FALSE(render::scene_lens(d, orthographic).is_orthographic);
  }
}
