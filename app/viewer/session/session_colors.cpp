#include <cmath>
#include <cstdio>

#include "viewer/session/session_controller.hpp"

// Colours given to instances from the viewer (report 8.4), as steps of the one history.
namespace nome::viewer {

bool SessionController::color_instances(const std::vector<std::string>& paths, Color color) {
  if (!session_ || !session_->scene()) {
    log_.error("color: instances need a scene file (.nome)");
    return false;
  }
  if (paths.empty()) {
    log_.error("color: select instances first (instance mode: click a face)");
    return false;
  }
  InstanceSurfaces before, after;
  try {
    for (const std::string& path : paths) {
      before.emplace_back(path, session_->scene()->instance_surface(path));
      session_->set_instance_color(path, color);
      after.emplace_back(path, session_->scene()->instance_surface(path));
    }
  } catch (const std::exception& e) {
    log_.error(std::string("color: ") + e.what());
    set_instance_surfaces(before);
    return false;
  }
  history_.push({[this, before] { return set_instance_surfaces(before); },
                 [this, after] { return set_instance_surfaces(after); }, ""});
  char text[64];
  std::snprintf(text, sizeof text, "(%.3g, %.3g, %.3g)", color.r, color.g, color.b);
  log_.info("color: " + std::to_string(paths.size()) + (paths.size() == 1 ? " instance" : " instances") +
            " coloured " + text + " (surface " + after.front().second.value_or("") + ")");
  return true;
}

bool SessionController::set_instance_surfaces(const InstanceSurfaces& surfaces) {
  try {
    for (const auto& [path, surface] : surfaces) session_->set_instance_surface(path, surface);
    return true;
  } catch (const std::exception& e) {
    log_.error(std::string("color: ") + e.what());
    return false;
  }
}

}  // namespace nome::viewer
