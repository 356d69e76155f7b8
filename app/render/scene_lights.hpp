#pragma once

#include <array>
#include <span>

#include <glm/vec3.hpp>

#include "nome/scene/scene.hpp"

namespace nome::render {

// The lights a scene places, as the mesh shader takes them: ambient colours summed, directional lights in
// world space (where the light travels). Unused, the renderer keeps its own lights fixed to the camera.
struct SceneLights {
  static constexpr int capacity = 8;
  bool is_used = false;
  glm::vec3 ambient{0.0f};
  int count = 0;
  std::array<glm::vec3, capacity> directions{};
  std::array<glm::vec3, capacity> colors{};
};

// The first `capacity` directional lights are drawn; a scene with no placed light uses none.
SceneLights scene_lights(std::span<const scene::SceneLight> lights);

}  // namespace nome::render
