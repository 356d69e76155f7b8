#include "nome/query/screen_projection.hpp"

#include <glm/matrix.hpp>

namespace nome {

Ray ray_through_pixel(const ScreenProjection& p, glm::dvec2 pixel) {
  const glm::dmat4 inverse = glm::inverse(p.projection * p.view);
  const double x = 2.0 * (pixel.x - p.origin.x) / p.viewport.x - 1.0;
  const double y = 1.0 - 2.0 * (pixel.y - p.origin.y) / p.viewport.y;
  const glm::dvec4 near_h = inverse * glm::dvec4(x, y, -1.0, 1.0);
  const glm::dvec4 far_h = inverse * glm::dvec4(x, y, 1.0, 1.0);
  const Vec3 near_point = Vec3(near_h) / near_h.w;
  const Vec3 far_point = Vec3(far_h) / far_h.w;
  Ray ray;
  ray.origin = near_point;
  ray.direction = far_point - near_point;
  ray.t_min = 0.0;
  ray.t_max = 1.0;
  return ray;
}

std::optional<glm::dvec3> project_to_pixel(const ScreenProjection& p, const Vec3& point) {
  const glm::dvec4 clip = p.projection * p.view * glm::dvec4(point, 1.0);
  if (!(clip.w > 0.0)) return std::nullopt;
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  return glm::dvec3(p.origin.x + (ndc.x + 1.0) * 0.5 * p.viewport.x,
                    p.origin.y + (1.0 - ndc.y) * 0.5 * p.viewport.y, ndc.z);
}

}  // namespace nome
