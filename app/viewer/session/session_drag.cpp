#include <algorithm>
#include <cstdio>

#include "nome/error.hpp"
#include "viewer/session/session_controller.hpp"

// Sculpting by hand: a drag of the selection rewrites the scene's text or moves its sliders, one step of
// the undo history however many frames it lasts.
namespace nome::viewer {

const std::string& SessionController::scene_text() const {
  static const std::string none;
  return session_ ? session_->text() : none;
}

bool SessionController::begin_drag(const DragSelection& selection) {
  drag_.reset();
  if (!session_ || !session_->scene()) {
    log_.error("drag: only a scene's vertices and instances move (a flat file has no text to change)");
    return false;
  }
  if (has_unapplied_text_) {
    log_.error(
        "drag: the text pane holds changes not applied: apply them (Ctrl+Enter) or load the file again");
    return false;
  }
  try {
    SceneDrag drag(*session_->scene(), session_->text(), selection);
    if (!drag.sliders().empty() && are_parameters_locked()) {
      log_.warning("drag: it would move sliders (" + drag.description() +
                   "), and the sliders are locked while editing (uncheck \"lock generator parameters while "
                   "editing\" to move them)");
      return false;
    }
    std::vector<std::pair<scene::ParameterId, double>> before;
    for (const scene::ParameterId p : drag.sliders())
      before.push_back({p, session_->scene()->parameters()[p].value});
    drag_.emplace(DragInProgress{std::move(drag), {}, std::move(before), session_->document().unresolved()});
    drag_->step.sliders = drag_->sliders_before;
    return true;
  } catch (const Error& e) {
    log_.error(e.what());
    return false;
  }
}

bool SessionController::apply_drag_state(const std::string& text,
                                         const std::vector<std::pair<scene::ParameterId, double>>& sliders) {
  try {
    session_->apply_drag_step(text, sliders);
    ++scene_text_version_;
    text_errors_.clear();
    return true;
  } catch (const scene::SceneError& e) {
    text_errors_ = e.diagnostics();
    log_.error(e);
  } catch (const std::exception& e) {
    log_.error(e.what());
  }
  return false;
}

bool SessionController::drag_to(const Vec3& offset) {
  if (!drag_) return false;
  DragStep step = drag_->drag.move(offset);
  if (!apply_drag_state(replaced_text(drag_->drag.text(), step.replacements), step.sliders)) return false;
  drag_->step = std::move(step);
  return true;
}

void SessionController::end_drag() {
  if (!drag_) return;
  DragInProgress done = std::move(*drag_);
  drag_.reset();
  const std::string before = done.drag.text();
  const std::string after = replaced_text(before, done.step.replacements);
  if (after == before && done.step.sliders == done.sliders_before) {
    log_.info("drag: nothing changed (" + done.drag.description() + ")");
    return;
  }
  report_unresolved(done.unresolved_before);
  std::vector<std::pair<scene::ParameterId, double>> undone = done.sliders_before;
  std::reverse(undone.begin(), undone.end());
  history_.push({[this, before, undone] { return apply_drag_state(before, undone); },
                 [this, after, sliders = done.step.sliders] { return apply_drag_state(after, sliders); },
                 ""});
  std::vector<std::string> changes;
  for (std::size_t i = 0; i < done.step.sliders.size(); ++i) {
    const auto& [parameter, value] = done.step.sliders[i];
    if (value != done.sliders_before[i].second)
      changes.push_back(session_->scene()->parameters()[parameter].full_name + " " +
                        scene::format_number(done.sliders_before[i].second) + " to " +
                        scene::format_number(value));
  }
  std::size_t rewritten = 0;
  for (const TextReplacement& r : done.step.replacements) {
    if (r.begin == r.end)
      changes.push_back("added" + r.text);
    else
      ++rewritten;
  }
  if (rewritten > 0) changes.push_back(std::to_string(rewritten) + " numbers of the text rewritten");
  std::string text;
  for (const std::string& c : changes) text += (text.empty() ? "" : ", ") + c;
  char miss[96] = "";
  if (done.step.slider_miss > 1e-6)
    std::snprintf(miss, sizeof miss, " (%.3g short of the drop: the sliders' ranges and steps)",
                  done.step.slider_miss);
  log_.info("drag: " + text + miss);
}

void SessionController::cancel_drag() {
  if (!drag_) return;
  DragInProgress cancelled = std::move(*drag_);
  drag_.reset();
  apply_drag_state(cancelled.drag.text(), cancelled.sliders_before);
}

std::vector<std::pair<std::size_t, std::size_t>> SessionController::drag_marks() const {
  std::vector<std::pair<std::size_t, std::size_t>> marks;
  if (!drag_) return marks;
  // Each replacement shifts the ones after it by its change of length.
  std::ptrdiff_t shift = 0;
  for (const TextReplacement& r : drag_->step.replacements) {
    const std::size_t begin = std::size_t(std::ptrdiff_t(r.begin) + shift);
    marks.push_back({begin + (r.begin == r.end ? 1 : 0), begin + r.text.size()});
    shift += std::ptrdiff_t(r.text.size()) - std::ptrdiff_t(r.end - r.begin);
  }
  return marks;
}

}  // namespace nome::viewer
