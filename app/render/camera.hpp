#pragma once

#include <span>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "nome/query/screen_projection.hpp"
#include "render/bounding_box.hpp"

namespace nome::render {

// How a camera projects: in perspective with a vertical field of view, or orthographically (the field of
// view then only sets how much the distance shows: a half height of distance * tan(fov / 2)).
struct Lens {
  double fov_y_degrees = 30.0;
  bool is_orthographic = false;
};

// An orbit camera shared by `nome render` and the viewer: the eye looks at `target` from `distance`
// away along the camera's +z axis; `orientation` turns camera axes into world axes. The world is
// Y-up, as the report's viewer. Screen positions are normalized device coordinates in [-1, 1]^2.
class Camera {
 public:
  glm::dvec3 target{0.0};
  double distance = 4.0;
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
  Lens lens;

  // Looks from azimuth AZ (degrees about +Y, 0 = from +Z, 90 = from +X) and elevation EL (degrees
  // above the XZ plane), with no roll.
  void set_view(double azimuth_degrees, double elevation_degrees);
  // Keeps the orientation and moves target and distance so that the points fill the picture with
  // `margin` (a fraction of the half-size) to spare; remembers their box for the depth range.
  void fit(std::span<const glm::dvec3> points, double aspect, double margin = 0.06);
  // Shoemake's arcball: the drag from `from` to `to` rolls the scene like a ball under the mouse.
  void arcball(const glm::dvec2& from, const glm::dvec2& to, double aspect);
  // Moves the target so that the point under `from` ends up under `to` (at the target's depth).
  void pan(const glm::dvec2& from, const glm::dvec2& to, double aspect);
  // Multiplies the distance to the target (factor < 1 comes closer).
  void zoom(double factor);

  glm::dvec3 eye() const { return target + orientation * glm::dvec3(0.0, 0.0, distance); }
  glm::mat4 view_matrix() const;
  glm::mat4 projection_matrix(double aspect) const;
  // The matrices and viewport (size and top-left corner in window pixels) the kernel's picking casts
  // rays with.
  ScreenProjection screen_projection(const glm::dvec2& viewport, const glm::dvec2& origin = {0.0, 0.0}) const;

 private:
  void depth_range(double& near_plane, double& far_plane) const;

  BoundingBox scene_{};
};

}  // namespace nome::render
