#include "render/scene_camera.hpp"

#include <cmath>

namespace nome::render {

Lens scene_lens(const scene::RenderDefaults& defaults, Lens lens) {
  if (!defaults.camera_projection) return lens;
  const std::string& projection = *defaults.camera_projection;
  const std::vector<double>& f = defaults.camera_frustum;
  const auto usable = [](double degrees) {
    return std::isfinite(degrees) && degrees >= 1.0 && degrees <= 170.0;
  };
  if (projection == "NOME_ORTHOGRAPHIC" || projection == "NOME_ORTHOGONAL") {
    lens.is_orthographic = true;
  } else if (projection == "NOME_PERSPECTIVE") {
    lens.is_orthographic = false;
    if (!f.empty() && usable(f[0])) lens.fov_y_degrees = f[0];
  } else if (projection == "NOME_FRUSTUM" || projection == "NOME_FRUTUM") {
    lens.is_orthographic = false;
    // (left right bottom top near far): the angle the bottom and top planes make at the eye.
    if (f.size() >= 5 && f[4] > 0.0) {
      const double degrees = (std::atan2(std::abs(f[3]), f[4]) + std::atan2(std::abs(f[2]), f[4])) * 180.0 /
                             3.14159265358979323846;
      if (usable(degrees)) lens.fov_y_degrees = degrees;
    }
  }
  return lens;
}

}  // namespace nome::render
