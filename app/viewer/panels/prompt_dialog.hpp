#pragma once

#include <filesystem>
#include <optional>

namespace nome::viewer {

enum class UnsavedAnswer { save, discard, cancel };

// The question about unsaved changes before quitting (no file) or opening another file.
struct UnsavedQuestion {
  std::optional<std::filesystem::path> open;
};

// The modal questions: unsaved changes (quit, open) and the crash-recovery offer. They hold only the
// question; the window acts on the answer, which comes from a button or a script's `prompt` / `recover`.
class Prompts {
 public:
  void ask_unsaved(UnsavedQuestion question) { unsaved_ = std::move(question); }
  const std::optional<UnsavedQuestion>& unsaved() const { return unsaved_; }
  // The open question, now answered.
  UnsavedQuestion take_unsaved();

  // Draws the unsaved-changes popup while the question is open; the button pressed this frame, if any.
  // `can_save`: a Save button (scenes only).
  std::optional<UnsavedAnswer> draw_unsaved(bool can_save);
  // Draws the recovery offer for `document` while `is_offered`; true: restore, false: discard.
  std::optional<bool> draw_recovery(bool is_offered, const std::filesystem::path& document);

 private:
  std::optional<UnsavedQuestion> unsaved_;
};

}  // namespace nome::viewer
