#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace nome::viewer {

// The viewer's one undo history (Ctrl+Z / Ctrl+Y): the document's edits (each a step of the kernel's own
// history) and slider moves, in the order the user made them. A step that continues the last one (the
// same key, such as one slider dragged over many frames) merges into it: one drag is one step.
class UndoHistory {
 public:
  struct Step {
    std::function<bool()> undo;  // false when it could not be undone (and logged why)
    std::function<bool()> redo;
    std::string key;  // steps with the same non-empty key may merge
  };

  // Adds a done step, dropping the steps undone before it; with `continues`, a step with the last one's
  // key replaces its redo and keeps its undo.
  void push(Step step, bool continues = false);
  bool undo();
  bool redo();
  bool can_undo() const { return done_ > 0; }
  bool can_redo() const { return done_ < steps_.size(); }
  std::size_t size() const { return steps_.size(); }
  void clear();

 private:
  std::vector<Step> steps_;
  std::size_t done_ = 0;
};

}  // namespace nome::viewer
