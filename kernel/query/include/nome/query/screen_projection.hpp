#pragma once

#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "nome/query/ray.hpp"

namespace nome {

// What a pick needs of the camera: the matrices the frame was drawn with and the viewport (its top-left
// corner and size) in window pixels, as a window with panels around its picture has it. Pixel
// coordinates have their origin at the window's top-left corner, y down (as GLFW reports the cursor);
// they are continuous (pixel (i, j) covers [i, i+1) x [j, j+1)).
struct ScreenProjection {
  glm::dmat4 view{1.0};
  glm::dmat4 projection{1.0};
  glm::dvec2 viewport{1.0, 1.0};
  glm::dvec2 origin{0.0, 0.0};
};

// The ray from the near plane to the far plane through a window pixel position: t = 0 at the near
// plane, t = 1 at the far plane.
Ray ray_through_pixel(const ScreenProjection& projection, glm::dvec2 pixel);

// Window pixel position and NDC depth of a world point; none when it lies behind the eye.
std::optional<glm::dvec3> project_to_pixel(const ScreenProjection& projection, const Vec3& point);

}  // namespace nome
