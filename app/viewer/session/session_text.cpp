#include "nome/atomic_file.hpp"
#include "nome/error.hpp"
#include "viewer/session/session_controller.hpp"

// The scene's text as the text pane edits it: applied and saved through the reload a change on disk makes.
namespace nome::viewer {

bool SessionController::reload(const std::string* text) {
  try {
    if (text)
      session_->reload_text(*text);
    else
      session_->reload();
    text_errors_.clear();
    report_scene_warnings();
    return true;
  } catch (const scene::SceneError& e) {
    // The last good geometry stays on screen; the text pane marks the places.
    text_errors_ = e.diagnostics();
    log_.error(e);
  } catch (const std::exception& e) {
    text_errors_.clear();
    log_.error(e);
  }
  return false;
}

bool SessionController::apply_text(const std::string& text) {
  if (!has_scene()) {
    log_.error("apply: the text pane evaluates scene files (.nome .nom .slf); open one first");
    return false;
  }
  if (!reload(&text)) return false;
  log_.info("applied the text of " + session_->path().filename().string() + " (" +
            std::to_string(session_->polygons().num_faces()) + " faces)");
  return true;
}

bool SessionController::save_text(const std::string& text) {
  if (!has_scene()) {
    log_.error("save text: the text pane saves scene files (.nome .nom .slf); open one first");
    return false;
  }
  const std::filesystem::path path = session_->path();
  try {
    write_file_atomically(path, [&](std::ostream& out) { out << text; });
  } catch (const std::exception& e) {
    log_.error(e);
    return false;
  }
  // The watcher would read the write back as another program's change.
  std::error_code ec;
  file_time_ = std::filesystem::last_write_time(path, ec);
  ++disk_version_;
  log_.info("saved the text of " + path.string());
  apply_text(text);
  return true;
}

}  // namespace nome::viewer
