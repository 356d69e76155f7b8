#pragma once

#include <optional>
#include <span>

#include <glm/vec2.hpp>

#include "nome/mesh/types.hpp"
#include "nome/query/screen_projection.hpp"
#include "render/camera.hpp"
#include "viewer/layout.hpp"
#include "viewer/platform.hpp"

namespace nome::viewer {

// What the mouse asked of the window beyond moving the camera.
struct MouseEvent {
  enum class Kind { click, right_click, double_click };
  Kind kind;
  glm::dvec2 pixel;
};

// The camera and the mouse (polyscope's feel): left drag turns (arcball), right or middle drag pans, the
// wheel zooms towards the point under the cursor; a press-release that moves less than click_pixels is a
// click, not a drag. All of it happens in the viewport, the window's rectangle between the panels.
class ViewController {
 public:
  static constexpr double default_azimuth = 30.0;
  static constexpr double default_elevation = 25.0;
  static constexpr double click_pixels = 4.0;

  ViewController();

  // Moves the camera by this frame's input; returns the click it ended, if any. Presses and the wheel
  // count inside the viewport only; a drag begun there goes on outside it.
  std::optional<MouseEvent> handle(const InputFrame& input, const ScreenRect& viewport);
  // A button is held (the window draws continuously meanwhile).
  bool is_pressed() const { return pressed_button_ >= 0; }

  const render::Camera& camera() const { return camera_; }
  ScreenProjection projection(const ScreenRect& viewport) const;
  void zoom(double factor) { camera_.zoom(factor); }
  // Zooms keeping the point under `pixel` (at the orbit centre's depth) where it is.
  void zoom_at(double factor, glm::dvec2 pixel, const ScreenRect& viewport);
  // Looks from these angles (degrees); frame() then fits the picture.
  void set_angles(double azimuth, double elevation) { camera_.set_view(azimuth, elevation); }
  // Perspective or orthographic, as the file's camera asks; frame() then fits the picture.
  void set_lens(const render::Lens& lens) { camera_.lens = lens; }
  // Turns the view about the world's vertical axis through the target (the turntable).
  void turn(double radians) {
    camera_.orientation = glm::angleAxis(radians, glm::dvec3(0.0, 1.0, 0.0)) * camera_.orientation;
  }
  // Fits the camera to the points (the mesh, then the rim lines' points) in the viewport.
  void frame(std::span<const Vec3> mesh, std::span<const Vec3> more, const ScreenRect& viewport);
  // The orbit centre moves to the point; the eye stays where it is.
  void orbit_around(const Vec3& point);

 private:
  render::Camera camera_;
  int pressed_button_ = -1;
  glm::dvec2 press_position_{0.0}, last_position_{0.0};
  bool is_dragging_ = false;
};

}  // namespace nome::viewer
