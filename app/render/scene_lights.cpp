#include "render/scene_lights.hpp"

namespace nome::render {

SceneLights scene_lights(std::span<const scene::SceneLight> lights) {
  SceneLights out;
  out.is_used = !lights.empty();
  for (const scene::SceneLight& light : lights) {
    if (light.kind == scene::SceneLight::Kind::ambient) {
      out.ambient += light.color;
    } else if (out.count < SceneLights::capacity) {
      out.directions[std::size_t(out.count)] = glm::vec3(light.direction);
      out.colors[std::size_t(out.count)] = light.color;
      ++out.count;
    }
  }
  return out;
}

}  // namespace nome::render
