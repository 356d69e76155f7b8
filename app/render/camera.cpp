#include "render/camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace nome::render {
namespace {

double radians(double degrees) {
  return degrees * (3.14159265358979323846 / 180.0);
}

// Shoemake: a point inside the unit circle lifts onto the sphere; outside it lands on the rim.
glm::dvec3 on_ball(const glm::dvec2& p) {
  const double r2 = glm::dot(p, p);
  if (r2 <= 1.0) return {p.x, p.y, std::sqrt(1.0 - r2)};
  const glm::dvec2 rim = p / std::sqrt(r2);
  return {rim.x, rim.y, 0.0};
}

}  // namespace

void Camera::set_view(double azimuth_degrees, double elevation_degrees) {
  const double az = radians(azimuth_degrees), el = radians(elevation_degrees);
  const glm::dvec3 back(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
  // Right stays horizontal and follows the azimuth, so straight up and down views are defined too.
  const glm::dvec3 right(std::cos(az), 0.0, -std::sin(az));
  const glm::dvec3 up = glm::cross(back, right);
  orientation = glm::normalize(glm::quat_cast(glm::dmat3(right, up, back)));
}

void Camera::fit(std::span<const glm::dvec3> points, double aspect, double margin) {
  const BoundingBox box = BoundingBox::of(points);
  if (box.is_empty()) return;
  scene_ = box;
  const glm::dmat3 axes = glm::mat3_cast(orientation);
  // Centre the target on the points' extent across the view, then back off until every point is in.
  BoundingBox across;
  for (const glm::dvec3& p : points) across.add(glm::transpose(axes) * (p - box.center()));
  target = box.center() + axes * glm::dvec3(across.center().x, across.center().y, 0.0);
  const double tan_y = std::tan(radians(lens.fov_y_degrees) / 2.0) * (1.0 - margin);
  const double tan_x = tan_y * aspect;
  double needed = 0.0;
  for (const glm::dvec3& point : points) {
    const glm::dvec3 p = glm::transpose(axes) * (point - target);
    // Orthographic, depth does not shrink a point: only its distance across the view counts.
    needed = std::max(
        needed, (lens.is_orthographic ? 0.0 : p.z) + std::max(std::abs(p.x) / tan_x, std::abs(p.y) / tan_y));
  }
  const double size = glm::length(box.max - box.min);
  distance = std::max(needed, 1e-6 * std::max(size, 1.0));
}

void Camera::arcball(const glm::dvec2& from, const glm::dvec2& to, double aspect) {
  const glm::dvec3 a = on_ball({from.x * aspect, from.y}), b = on_ball({to.x * aspect, to.y});
  const glm::dvec3 axis = glm::cross(a, b);
  if (glm::dot(axis, axis) < 1e-24) return;
  // The quaternion (a.b, a x b) turns by twice the angle between a and b (Shoemake's choice: a full
  // drag across the ball is a full turn). The scene turns one way, so the camera turns the other.
  const glm::dquat turn = glm::normalize(glm::dquat(glm::dot(a, b), axis.x, axis.y, axis.z));
  orientation = glm::normalize(orientation * glm::conjugate(turn));
}

void Camera::pan(const glm::dvec2& from, const glm::dvec2& to, double aspect) {
  const double half_height = distance * std::tan(radians(lens.fov_y_degrees) / 2.0);
  const glm::dvec2 delta = to - from;
  target -= orientation * glm::dvec3(delta.x * half_height * aspect, delta.y * half_height, 0.0);
}

void Camera::zoom(double factor) {
  distance = std::max(distance * factor, 1e-9);
}

void Camera::depth_range(double& near_plane, double& far_plane) const {
  double radius = 1.0;
  if (!scene_.is_empty())
    radius = 0.5 * glm::length(scene_.max - scene_.min) + glm::length(scene_.center() - target);
  radius = std::max(radius, 1e-9);
  const double depth = glm::length(eye() - (scene_.is_empty() ? target : scene_.center()));
  near_plane = std::max(depth - 1.05 * radius, 1e-3 * distance);
  far_plane = std::max(depth + 1.05 * radius, near_plane * 2.0);
  // Orthographic, the eye may sit inside the scene: the near plane may lie behind it.
  if (lens.is_orthographic) near_plane = depth - 1.05 * radius;
}

glm::mat4 Camera::view_matrix() const {
  const glm::dmat4 rotation = glm::mat4_cast(glm::conjugate(orientation));
  return glm::mat4(glm::translate(rotation, -eye()));
}

glm::mat4 Camera::projection_matrix(double aspect) const {
  double near_plane = 0.0, far_plane = 0.0;
  depth_range(near_plane, far_plane);
  if (lens.is_orthographic) {
    const double half_height = distance * std::tan(radians(lens.fov_y_degrees) / 2.0);
    return glm::mat4(glm::ortho(-half_height * aspect, half_height * aspect, -half_height, half_height,
                                near_plane, far_plane));
  }
  return glm::mat4(glm::perspective(radians(lens.fov_y_degrees), aspect, near_plane, far_plane));
}

ScreenProjection Camera::screen_projection(const glm::dvec2& viewport, const glm::dvec2& origin) const {
  return {glm::dmat4(view_matrix()), glm::dmat4(projection_matrix(viewport.x / viewport.y)), viewport,
          origin};
}

}  // namespace nome::render
