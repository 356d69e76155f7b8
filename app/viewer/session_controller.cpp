#include "viewer/session_controller.hpp"

#include "nome/error.hpp"
#include "viewer/layout.hpp"
#include "viewer/picking.hpp"

namespace nome::viewer {

ViewerStores ViewerStores::from_environment() {
  return {RecentFiles::default_store(), Autosave::default_folder(), default_layout_file()};
}

SessionController::SessionController(MessageLog& log, const ViewerStores& stores)
    : log_(log), recent_(stores.recent_files), autosave_(stores.recovery_folder) {}

bool SessionController::open(const std::filesystem::path& path) {
  try {
    Session session = Session::open(path);
    session_.emplace(std::move(session));
    recovery_offer_ = autosave_.pending_recovery(path);
    std::error_code ec;
    file_time_ = std::filesystem::last_write_time(path, ec);
    recent_.add(path);
    const PolygonSoup& soup = session_->scene_soup();
    log_.info("opened " + path.string() + " (" + std::to_string(soup.num_vertices()) + " vertices, " +
              std::to_string(soup.num_faces()) + " faces)");
    return true;
  } catch (const std::exception& e) {
    log_.error(e.what());
    return false;
  }
}

bool SessionController::apply_anom(const std::filesystem::path& path) {
  if (!session_) {
    log_.error(path.string() + ": an .anom file applies to an open scene: open its .nome first");
    return false;
  }
  try {
    session_->apply_anom(path);
    recent_.add(path);
    log_.info("applied " + path.string() + " to " + session_->path().filename().string() + " (" +
              std::to_string(session_->scene_soup().num_faces()) + " faces)");
    return true;
  } catch (const std::exception& e) {
    log_.error(e.what());
    return false;
  }
}

void SessionController::save(const std::optional<std::filesystem::path>& target) {
  if (!has_scene()) throw InvalidInputError("save: only scene files (.nome) are saved");
  const std::filesystem::path previous = session_->path();
  const std::filesystem::path path = target ? *target : previous;
  const std::vector<std::string> left_out = session_->save(path);
  if (previous != path) autosave_.discard(previous);  // its changes went to the new file
  std::error_code ec;
  file_time_ = std::filesystem::last_write_time(path, ec);
  recent_.add(path);
  log_.info("saved " + path.string());
  if (!left_out.empty()) {
    std::string names;
    for (const std::string& name : left_out) names += (names.empty() ? "" : ", ") + name;
    log_.warning("not saved, kept in this session: " + std::to_string(left_out.size()) +
                 " edits whose vertices or faces are gone at the current slider values (" + names + ")");
  }
}

bool SessionController::save_logged(const std::optional<std::filesystem::path>& target) {
  if (!has_scene()) {
    log_.error("save: only scene files (.nome) are saved; File > Export writes .stl and .obj");
    return false;
  }
  try {
    save(target);
    return true;
  } catch (const std::exception& e) {
    log_.error(e.what());
    return false;
  }
}

void SessionController::set_parameter(const std::string& name, double value) {
  if (!session_) throw InvalidInputError("set: no file is open");
  session_->set_parameter(name, value);
}

void SessionController::set_parameter(Index parameter, double value) {
  try {
    session_->set_parameter(parameter, value);
  } catch (const std::exception& e) {
    log_.error(e.what());
  }
}

bool SessionController::edit(Action action, const StageResult* shown, const Selection& selection,
                             const ZipperOptions& zipper) {
  const std::string name = action_name(action);
  EditOutcome outcome{false, {}};
  if (action == Action::undo || action == Action::redo) {
    const bool is_undo = action == Action::undo;
    outcome.applied = is_undo ? session_->undo() : session_->redo();
    outcome.message = outcome.applied ? (is_undo ? "undone" : "redone") : "nothing to " + name;
  } else if (action == Action::accept) {
    outcome = session_->accept_temporary();
  } else if (action == Action::clear_temporary) {
    outcome = session_->clear_temporary();
  } else if (action == Action::add_polygon) {
    outcome = session_->add_polygon(*shown->mesh, selection.vertices());
  } else if (action == Action::delete_faces) {
    outcome = session_->delete_faces(*shown->mesh, selection.faces());
  } else if (action == Action::zip) {
    const auto& borders = selection.borders();
    outcome = session_->zipper(*shown->mesh, zipper_border(*shown->borders, borders[0]),
                               zipper_border(*shown->borders, borders[1]), zipper);
  }
  if (!outcome.applied) {
    log_.error(name + ": " + outcome.message);
    return false;
  }
  log_.info(name + ": " + (outcome.message.empty() ? std::string("done") : outcome.message));
  return true;
}

void SessionController::update(double now) {
  if (!session_) return;
  if (now - last_file_check_ >= 0.5 || last_file_check_ < 0.0) {
    last_file_check_ = now;
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(session_->path(), ec);
    if (!ec && time != file_time_) {
      file_time_ = time;
      try {
        session_->reload();
        log_.info("reloaded " + session_->path().filename().string());
      } catch (const std::exception& e) {
        // The last good geometry stays on screen.
        log_.error(e.what());
      }
    }
  }
  // Until the offer is answered the session holds the file as saved, and the recovery file must stay.
  if (recovery_offer_) return;
  try {
    autosave_.update(*session_, now);
  } catch (const std::exception& e) {
    log_.warning("autosave: " + std::string(e.what()));
  }
}

bool SessionController::answer_recovery(bool restore) {
  const std::filesystem::path recovery = *recovery_offer_;
  recovery_offer_.reset();
  const std::filesystem::path document = session_->path();
  if (!restore) {
    autosave_.discard(document);
    log_.info("discarded the recovered changes of " + document.filename().string());
    return false;
  }
  try {
    Session restored = Session::restore(document, recovery);
    session_.emplace(std::move(restored));
    log_.info("restored the unsaved changes of " + document.filename().string() + " (not saved yet)");
    return true;
  } catch (const std::exception& e) {
    // The recovery file stays for the user to look at.
    log_.error("cannot restore " + recovery.string() + ": " + e.what());
    return false;
  }
}

void SessionController::discard_recovery() {
  if (session_) autosave_.discard(session_->path());
}

}  // namespace nome::viewer
