#include "viewer/session/undo_history.hpp"

namespace nome::viewer {

void UndoHistory::push(Step step, bool continues) {
  const bool merges =
      continues && done_ == steps_.size() && done_ > 0 && !step.key.empty() && steps_.back().key == step.key;
  steps_.resize(done_);
  if (merges) {
    steps_.back().redo = std::move(step.redo);
    return;
  }
  steps_.push_back(std::move(step));
  ++done_;
}

bool UndoHistory::undo() {
  if (!can_undo() || !steps_[done_ - 1].undo()) return false;
  --done_;
  return true;
}

bool UndoHistory::redo() {
  if (!can_redo() || !steps_[done_].redo()) return false;
  ++done_;
  return true;
}

void UndoHistory::clear() {
  steps_.clear();
  done_ = 0;
}

}  // namespace nome::viewer
