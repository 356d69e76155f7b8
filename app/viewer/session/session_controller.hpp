#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "nome/edit/scene_drag.hpp"
#include "viewer/commands/actions.hpp"
#include "viewer/message_log.hpp"
#include "viewer/session/autosave.hpp"
#include "viewer/session/recent_files.hpp"
#include "viewer/session/session.hpp"
#include "viewer/session/stage_pipeline.hpp"
#include "viewer/session/undo_history.hpp"
#include "viewer/view/rim_picking.hpp"
#include "viewer/view/selection.hpp"

namespace nome::viewer {

// Where a viewer keeps its state between runs: the recent-files list, the recovery folder and the
// layout of its panels.
struct ViewerStores {
  std::filesystem::path recent_files;
  std::filesystem::path recovery_folder;
  std::filesystem::path layout_file;

  // The user's, from the environment (XDG folders).
  static ViewerStores from_environment();
};

// The open document and what comes with it: opening, saving, .anom files, slider moves, edits, the
// file watcher, the autosave and the crash-recovery offer. Errors go to the log. The one place that
// calls into the Session.
class SessionController {
 public:
  SessionController(MessageLog& log, const ViewerStores& stores);

  // The stage jobs read the session's polygons; the window reads only what follows.
  const Session* session() const { return session_ ? &*session_ : nullptr; }
  bool has_session() const { return session_.has_value(); }
  // The open file; empty without one.
  std::filesystem::path path() const { return session_ ? session_->path() : std::filesystem::path{}; }
  const Document* document() const { return session_ ? &session_->document() : nullptr; }
  const scene::Scene* scene() const { return session_ ? session_->scene() : nullptr; }
  bool has_scene() const { return scene() != nullptr; }
  bool is_modified() const { return session_ && session_->is_modified(); }
  const RecentFiles& recent() const { return recent_; }

  // Opens a file; on error logs it, keeps the current one and returns false.
  bool open(const std::filesystem::path& path);
  // Whether .sif files open with their triangles paired into quads (report 7.1; on unless `--triangles`).
  // Changing it reopens an open .sif file, unless it has unsaved edits (logged; returns false).
  bool set_sif_pairing(bool is_on);
  bool is_sif_pairing_on() const { return pair_sif_triangles_; }
  // An .anom file applies to the open scene instead of replacing it. Returns whether it applied.
  bool apply_anom(const std::filesystem::path& path);
  // Saves the scene to `target` (the session's file when none); throws Error on failure.
  void save(const std::optional<std::filesystem::path>& target);
  // save() with the error logged; returns whether it saved.
  bool save_logged(const std::optional<std::filesystem::path>& target);
  // Moves a slider (a step of the undo history); throws InvalidInputError for an unknown name, a value
  // out of range, or while the sliders are locked.
  void set_parameter(const std::string& name, double value);
  // The print preparation saved with the open scene (logged when refused).
  void set_print_setup(const PrintPlacementOptions& setup);
  // The report's lock, as an option: "lock generator parameters while editing". While it is on and the
  // document has edits, slider moves are refused (with a log line) so that no edit can lose its vertices.
  void set_parameter_lock(bool is_on) { is_parameter_lock_on_ = is_on; }
  bool is_parameter_lock_on() const { return is_parameter_lock_on_; }
  bool are_parameters_locked() const;
  // The panel's slider moves of one frame, one undo step (errors logged); `continues`: the same drag as
  // the last step's, which it merges into.
  void move_sliders(const std::vector<std::pair<scene::ParameterId, double>>& moves, bool continues);
  // A change the window makes (stage settings, colours) as a step of the same history.
  void push_step(UndoHistory::Step step, bool continues) { history_.push(std::move(step), continues); }
  bool can_undo() const { return history_.can_undo(); }
  bool can_redo() const { return history_.can_redo(); }

  // An edit action (undo, redo, accept, clear, and on the shown scene or merged stage with the selection
  // on it: add-polygon, delete, zip with two borders); needs a session. Undo and redo go through the
  // one history of edits and slider moves. The log says what happened. Returns whether it applied. Rim
  // vertices in the selection are named through `rims`; toggle-sharp gives the selected edges `sharpness`.
  // Gives the instances (placement paths) a colour as one step of the history (report 8.4); logs and
  // returns false when refused (nothing selected, flat geometry).
  bool color_instances(const std::vector<std::string>& paths, Color color);

  bool edit(Action action, const StageResult* shown, const Selection& selection, const ZipperOptions& zipper,
            const PickableRims& rims = {}, float sharpness = infinite_sharpness);

  // The text pane's Apply (session_text.cpp): `text` evaluated as the file's content, the way a reload
  // after a save evaluates it (the edits and slider values kept). On an error the last good geometry
  // stays, and the errors are logged (each clickable) and kept in text_errors(). Returns whether it applied.
  bool apply_text(const std::string& text);
  // Writes `text` as the file (atomically) and applies it; the file watcher takes the write for its own
  // and does not read it back. Returns whether it was written (an error in the text is only marked).
  bool save_text(const std::string& text);
  // The errors of the last evaluation of the file's text (Apply, a reload after a change on disk); empty
  // after a good one.
  const std::vector<scene::Diagnostic>& text_errors() const { return text_errors_; }
  // Changes whenever the file on disk may hold another text: opened, changed by another program, saved.
  std::uint64_t disk_version() const { return disk_version_; }

  // Sculpting by hand (session_drag.cpp): a drag of vertices (full names) and instances (placement paths)
  // from the scene's current text (SceneDrag). Refused, logged, with false: flat geometry, a text pane
  // with changes not applied, a selection nothing moves, sliders to move while they are locked.
  bool begin_drag(const DragSelection& selection);
  // The selection `offset` away from where it was at the press: the text rewritten and read again and the
  // sliders solved for (the vertices alone move while the faces stay). False (logged) when refused.
  bool drag_to(const Vec3& offset);
  // Keeps the drag as one step of the undo history; cancel_drag returns to the press.
  void end_drag();
  void cancel_drag();
  const SceneDrag* drag() const { return drag_ ? &drag_->drag : nullptr; }
  const DragStep* drag_step() const { return drag_ ? &drag_->step : nullptr; }
  // The byte ranges of the current scene text that the drag in progress rewrote (the text pane marks them).
  std::vector<std::pair<std::size_t, std::size_t>> drag_marks() const;
  // The text the scene was read from (Session::text), and a number that grows whenever it changes other
  // than by the text pane's own Apply or Save (a drag, its undo): the text pane then shows it.
  const std::string& scene_text() const;
  std::uint64_t scene_text_version() const { return scene_text_version_; }
  // The text pane says whether it holds changes not applied (a drag would overwrite them).
  void set_unapplied_text(bool has_changes) { has_unapplied_text_ = has_changes; }

  // Once a frame: reloads the file when it changed on disk (every half second at most) and keeps the
  // recovery file of unsaved changes.
  void update(double now);
  // The recovery file a viewer that did not end cleanly left for this document.
  const std::optional<std::filesystem::path>& recovery_offer() const { return recovery_offer_; }
  // Restores (true) or discards the offered changes; returns whether the session was replaced.
  bool answer_recovery(bool restore);
  // The user gave the changes up, or the viewer ends cleanly: no recovery file should offer them back.
  void discard_recovery();

 private:
  MessageLog& log_;
  std::optional<Session> session_;
  std::filesystem::file_time_type file_time_{};
  double last_file_check_ = -1.0;
  RecentFiles recent_;
  Autosave autosave_;
  std::optional<std::filesystem::path> recovery_offer_;
  UndoHistory history_;
  std::vector<scene::Diagnostic> text_errors_;
  std::uint64_t disk_version_ = 0;

  struct DragInProgress {
    SceneDrag drag;
    DragStep step;
    std::vector<std::pair<scene::ParameterId, double>> sliders_before;
    std::vector<UnresolvedEdit> unresolved_before;
  };
  std::optional<DragInProgress> drag_;
  std::uint64_t scene_text_version_ = 0;
  bool has_unapplied_text_ = false;
  // Puts the scene to a text and slider values (a drag's step, its undo and redo); logged when refused.
  bool apply_drag_state(const std::string& text,
                        const std::vector<std::pair<scene::ParameterId, double>>& sliders);

  bool is_parameter_lock_on_ = false;
  bool pair_sif_triangles_ = true;

  // session_text.cpp: reloads the session from the file's text or `text`, keeping text_errors().
  bool reload(const std::string* text);
  bool apply_moves(const std::vector<std::pair<scene::ParameterId, double>>& moves);
  // session_colors.cpp: names the instances' surfaces (an undo or redo of colours).
  using InstanceSurfaces = std::vector<std::pair<std::string, std::optional<std::string>>>;
  bool set_instance_surfaces(const InstanceSurfaces& surfaces);
  // Logs the edits a slider move left without their vertices (kept, hidden) and those it brought back.
  void report_unresolved(const std::vector<UnresolvedEdit>& before);
  // The scene's warnings (a face left out, a name defined again), each with its place in the text.
  void report_scene_warnings();
  UndoHistory::Step slider_step(std::vector<std::pair<scene::ParameterId, double>> before,
                                std::vector<std::pair<scene::ParameterId, double>> after);
};

}  // namespace nome::viewer
