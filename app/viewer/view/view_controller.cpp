#include "viewer/view/view_controller.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace nome::viewer {

ViewController::ViewController() {
  camera_.set_view(default_azimuth, default_elevation);
}

namespace {

glm::dvec2 to_ndc(glm::dvec2 p, const ScreenRect& viewport) {
  const glm::dvec2 q = (p - viewport.origin) / glm::max(viewport.size, glm::dvec2(1.0));
  return {2.0 * q.x - 1.0, 1.0 - 2.0 * q.y};
}

double aspect_of(const ScreenRect& viewport) {
  return std::max(viewport.size.x, 1.0) / std::max(viewport.size.y, 1.0);
}

}  // namespace

std::optional<MouseEvent> ViewController::handle(const InputFrame& input, const ScreenRect& viewport) {
  const glm::dvec2 position = input.cursor;
  const double aspect = aspect_of(viewport);
  std::optional<MouseEvent> event;
  if (pressed_button_ < 0 && !input.is_over_panel && viewport.contains(position)) {
    for (int button = 0; button < 3; ++button) {
      if (!input.is_pressed[button]) continue;
      pressed_button_ = button;
      press_position_ = last_position_ = position;
      is_dragging_ = false;
      if (button == 0 && input.is_double_click) event = MouseEvent{MouseEvent::Kind::double_click, position};
      break;
    }
    if (input.wheel != 0.0) zoom_at(std::pow(0.88, input.wheel), position, viewport);
  }
  if (pressed_button_ < 0) return event;
  if (glm::length(position - press_position_) >= click_pixels) is_dragging_ = true;
  if (is_dragging_ && position != last_position_) {
    if (pressed_button_ == 0)
      camera_.arcball(to_ndc(last_position_, viewport), to_ndc(position, viewport), aspect);
    else
      camera_.pan(to_ndc(last_position_, viewport), to_ndc(position, viewport), aspect);
  }
  last_position_ = position;
  if (input.is_down[std::size_t(pressed_button_)]) return event;
  if (!is_dragging_ && pressed_button_ == 0) event = MouseEvent{MouseEvent::Kind::click, press_position_};
  if (!is_dragging_ && pressed_button_ == 1)
    event = MouseEvent{MouseEvent::Kind::right_click, press_position_};
  pressed_button_ = -1;
  return event;
}

ScreenProjection ViewController::projection(const ScreenRect& viewport) const {
  return camera_.screen_projection(glm::max(viewport.size, glm::dvec2(1.0)), viewport.origin);
}

void ViewController::zoom_at(double factor, glm::dvec2 pixel, const ScreenRect& viewport) {
  // The point under the cursor at the orbit centre's depth lies `c` (NDC) from the centre; after the
  // zoom it would lie factor * c from it, so the centre moves by (1 - factor) of that offset.
  const glm::dvec2 c = to_ndc(pixel, viewport);
  camera_.pan(c, factor * c, aspect_of(viewport));
  camera_.zoom(factor);
}

void ViewController::frame(std::span<const Vec3> mesh, std::span<const Vec3> more,
                           const ScreenRect& viewport) {
  const double aspect = aspect_of(viewport);
  if (more.empty()) {
    camera_.fit(mesh, aspect);
    return;
  }
  std::vector<Vec3> points(mesh.begin(), mesh.end());
  points.insert(points.end(), more.begin(), more.end());
  camera_.fit(points, aspect);
}

void ViewController::orbit_around(const Vec3& point) {
  const glm::dvec3 eye = camera_.eye();
  camera_.target = point;
  camera_.distance = std::max(glm::length(eye - point), 1e-9);
  const glm::dvec3 back = glm::normalize(eye - point);
  // Keep the up direction as close as possible to the current one while looking at the new centre.
  const glm::dvec3 up_now = camera_.orientation * glm::dvec3(0.0, 1.0, 0.0);
  glm::dvec3 right = glm::cross(up_now, back);
  if (glm::dot(right, right) < 1e-18) return;
  right = glm::normalize(right);
  camera_.orientation = glm::normalize(glm::quat_cast(glm::dmat3(right, glm::cross(back, right), back)));
}

}  // namespace nome::viewer
