#include "viewer/session/session_controller.hpp"

#include <algorithm>

#include "nome/error.hpp"
#include "viewer/layout.hpp"
#include "viewer/view/picking.hpp"

namespace nome::viewer {

ViewerStores ViewerStores::from_environment() {
  return {RecentFiles::default_store(), Autosave::default_folder(), default_layout_file()};
}

SessionController::SessionController(MessageLog& log, const ViewerStores& stores)
    : log_(log), recent_(stores.recent_files), autosave_(stores.recovery_folder) {}

bool SessionController::open(const std::filesystem::path& path) {
  try {
    Session session = Session::open(path, pair_sif_triangles_);
    session_.emplace(std::move(session));
    history_.clear();
    recovery_offer_ = autosave_.pending_recovery(path);
    std::error_code ec;
    file_time_ = std::filesystem::last_write_time(path, ec);
    ++disk_version_;
    text_errors_.clear();
    recent_.add(path);
    const PolygonSoup& soup = session_->polygons();
    log_.info("opened " + path.string() + " (" + std::to_string(soup.num_vertices()) + " vertices, " +
              std::to_string(soup.num_faces()) + " faces)");
    report_scene_warnings();
    return true;
  } catch (const std::exception& e) {
    log_.error(e.what());
    return false;
  }
}

bool SessionController::set_sif_pairing(bool is_on) {
  if (is_on == pair_sif_triangles_) return true;
  if (session_ && session_->is_sif() && session_->is_modified()) {
    log_.error("pair triangles: " + session_->path().filename().string() +
               " has unsaved edits, which name its faces: undo them first");
    return false;
  }
  pair_sif_triangles_ = is_on;
  log_.info(std::string(".sif triangles ") + (is_on ? "paired into quads" : "kept as triangles"));
  return !session_ || !session_->is_sif() || open(session_->path());
}

bool SessionController::apply_anom(const std::filesystem::path& path) {
  if (!session_) {
    log_.error(path.string() + ": an .anom file applies to an open scene: open its .nome first");
    return false;
  }
  try {
    session_->apply_anom(path);
    history_.clear();  // the working mesh replaced the edits and their history
    recent_.add(path);
    log_.info("applied " + path.string() + " to " + session_->path().filename().string() + " (" +
              std::to_string(session_->polygons().num_faces()) + " faces)");
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
  session_->save(path);
  if (previous != path) autosave_.discard(previous);  // its changes went to the new file
  std::error_code ec;
  file_time_ = std::filesystem::last_write_time(path, ec);
  ++disk_version_;
  recent_.add(path);
  log_.info("saved " + path.string());
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

namespace {

// The edits of `list` that `other` has not, named with what they miss.
std::string missing_from(const std::vector<UnresolvedEdit>& list, const std::vector<UnresolvedEdit>& other,
                         std::size_t& count) {
  std::string text;
  count = 0;
  for (const UnresolvedEdit& edit : list) {
    const auto is_same = [&](const UnresolvedEdit& o) { return o.face == edit.face; };
    if (std::any_of(other.begin(), other.end(), is_same)) continue;
    ++count;
    std::string missing;
    for (const std::string& v : edit.missing) missing += (missing.empty() ? "" : " ") + v;
    text += (text.empty() ? "" : ", ") + edit.face +
            (missing.empty() ? " (its face is gone)" : " (missing " + missing + ")");
  }
  return text;
}

}  // namespace

bool SessionController::are_parameters_locked() const {
  if (!is_parameter_lock_on_ || !session_) return false;
  const Document& d = session_->document();
  return !d.consolidated_faces().empty() || !d.temporary_faces().empty() || !d.deleted_faces().empty();
}

void SessionController::report_unresolved(const std::vector<UnresolvedEdit>& before) {
  const std::vector<UnresolvedEdit> after = session_->document().unresolved();
  std::size_t count = 0;
  if (const std::string lost = missing_from(after, before, count); count > 0)
    log_.warning(std::to_string(count) + " edits lost their vertices at these slider values; kept, hidden, " +
                 "until the sliders bring them back (save refuses until then): " + lost);
  if (const std::string back = missing_from(before, after, count); count > 0)
    log_.info(std::to_string(count) + " edits back with their vertices: " + back);
}

void SessionController::set_print_setup(const PrintPlacementOptions& setup) {
  if (!session_) return;
  try {
    session_->set_print_setup(setup);
  } catch (const Error& e) {
    log_.error(e.what());
  }
}

void SessionController::report_scene_warnings() {
  if (const scene::Scene* scene = session_->scene()) log_.diagnostics(scene->warnings());
}

void SessionController::set_parameter(const std::string& name, double value) {
  if (!session_) throw InvalidInputError("set: no file is open");
  if (are_parameters_locked())
    throw InvalidInputError("set " + name + ": the sliders are locked while editing (uncheck \"lock " +
                            "generator parameters while editing\" to move them)");
  const scene::Scene* scene = session_->scene();
  const std::optional<scene::ParameterId> id = scene ? scene->find_parameter(name) : std::nullopt;
  const double before = id ? scene->parameters()[*id].value : 0.0;
  const std::vector<UnresolvedEdit> unresolved = session_->document().unresolved();
  session_->set_parameter(name, value);
  report_unresolved(unresolved);
  if (id) history_.push(slider_step({{*id, before}}, {{*id, value}}));
}

bool SessionController::apply_moves(const std::vector<std::pair<scene::ParameterId, double>>& moves) {
  const std::vector<UnresolvedEdit> unresolved = session_->document().unresolved();
  try {
    for (const auto& [parameter, value] : moves) session_->set_parameter(parameter, value);
    report_unresolved(unresolved);
    return true;
  } catch (const std::exception& e) {
    log_.error(e.what());
    report_unresolved(unresolved);
    return false;
  }
}

UndoHistory::Step SessionController::slider_step(std::vector<std::pair<scene::ParameterId, double>> before,
                                                 std::vector<std::pair<scene::ParameterId, double>> after) {
  const std::string key = after.size() == 1 ? "slider " + std::to_string(after[0].first.index()) : "";
  // Undone in the reverse order, so that a batch returns exactly to where it started.
  std::reverse(before.begin(), before.end());
  return {[this, before] { return apply_moves(before); }, [this, after] { return apply_moves(after); }, key};
}

void SessionController::move_sliders(const std::vector<std::pair<scene::ParameterId, double>>& moves,
                                     bool continues) {
  if (!session_ || !session_->scene() || moves.empty()) return;
  if (are_parameters_locked()) {
    log_.warning(
        "the sliders are locked while editing (uncheck \"lock generator parameters while editing\" "
        "to move them)");
    return;
  }
  std::vector<std::pair<scene::ParameterId, double>> before, done;
  for (const auto& [parameter, value] : moves) {
    const double old = session_->scene()->parameters()[parameter].value;
    if (!apply_moves({{parameter, value}})) break;
    before.push_back({parameter, old});
    done.push_back({parameter, value});
  }
  if (!done.empty()) history_.push(slider_step(std::move(before), std::move(done)), continues);
}

bool SessionController::edit(Action action, const StageResult* shown, const Selection& selection,
                             const ZipperOptions& zipper, const PickableRims& rims, float sharpness) {
  const std::string name = action_name(action);
  EditOutcome outcome{false, {}};
  if (action == Action::undo || action == Action::redo) {
    const bool is_undo = action == Action::undo;
    outcome.applied = is_undo ? history_.undo() : history_.redo();
    outcome.message = outcome.applied ? (is_undo ? "undone" : "redone") : "nothing to " + name;
  } else if (action == Action::accept) {
    outcome = session_->accept_temporary();
  } else if (action == Action::clear_temporary) {
    outcome = session_->clear_temporary();
  } else if (action == Action::add_polygon) {
    std::vector<std::string> names;
    for (Index v : selection.vertices()) names.push_back(rims.name(*shown->mesh, v));
    outcome = session_->add_polygon(names);
  } else if (action == Action::toggle_sharp) {
    // Smooth when every selected edge has the weight already, that weight otherwise.
    const auto& edges = selection.edges();
    const float weight = std::min(sharpness, infinite_sharpness);
    const bool have_weight = std::all_of(edges.begin(), edges.end(),
                                         [&](Index e) { return shown->mesh->edge_sharpness(e) == weight; });
    outcome = session_->set_sharp(*shown->mesh, edges, have_weight ? 0.0f : weight);
  } else if (action == Action::delete_faces) {
    outcome = session_->delete_faces(*shown->mesh, selection.faces());
  } else if (action == Action::zip) {
    const auto& borders = selection.borders();
    if (touches_rim(rims, borders[0]) || touches_rim(rims, borders[1]))
      outcome = session_->zip_chains(chain_names(*shown->mesh, rims, borders[0]),
                                     chain_names(*shown->mesh, rims, borders[1]), zipper);
    else
      outcome = session_->zipper(*shown->mesh, zipper_border(*shown->borders, borders[0]),
                                 zipper_border(*shown->borders, borders[1]), zipper);
  }
  if (!outcome.applied) {
    log_.error(name + ": " + outcome.message);
    return false;
  }
  if (action != Action::undo && action != Action::redo)
    history_.push({[this] { return session_->undo(); }, [this] { return session_->redo(); }, ""});
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
      ++disk_version_;
      if (reload(nullptr)) log_.info("reloaded " + session_->path().filename().string());
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
    history_.clear();
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
