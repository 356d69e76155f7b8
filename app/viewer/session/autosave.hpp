#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

namespace nome::viewer {

class Session;

// Crash recovery for the open scene file. While it has unsaved changes, its state (as Save would write
// it) is kept in a recovery file in a per-user folder, named after the document's absolute path: written
// atomically at once after each accepted edit, at most every interval_seconds while only sliders move.
// A save, a clean quit or a discarded offer removes it, so a recovery file newer than its document means
// the viewer did not end cleanly.
class Autosave {
 public:
  static constexpr double interval_seconds = 30.0;

  // No folder: nothing is kept.
  explicit Autosave(std::filesystem::path folder);
  // $XDG_STATE_HOME/nome/recovery, else ~/.local/state/nome/recovery, else none.
  static std::filesystem::path default_folder();

  std::filesystem::path recovery_file(const std::filesystem::path& document) const;
  // The recovery file of `document` when one is left over and newer than the document.
  std::optional<std::filesystem::path> pending_recovery(const std::filesystem::path& document) const;

  // Once a frame, `now` in seconds of a steady clock. Flat geometry (no .nome to write) is not kept.
  // Throws nome::Error when the recovery file cannot be written (and waits an interval to try again).
  void update(const Session& session, double now);
  // Removes the recovery file of `document` (clean quit, restored or discarded offer).
  void discard(const std::filesystem::path& document);

 private:
  std::filesystem::path folder_;
  std::filesystem::path written_;  // the recovery file this viewer wrote last, if it still exists
  std::uint64_t written_version_ = 0;
  std::uint64_t written_edits_ = 0;
  double written_at_ = 0.0;
};

}  // namespace nome::viewer
