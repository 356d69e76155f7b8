#pragma once

#include <filesystem>
#include <optional>
#include <vector>

namespace nome::viewer {

struct ViewerOptions {
  std::optional<std::filesystem::path> file;
  std::vector<std::filesystem::path> anom_files;  // applied to `file`'s scene in order
  std::optional<std::filesystem::path> script;    // replayed one command per frame, then the window stays
  int width = 1280;
  int height = 800;
  bool has_size = false;           // --size given: otherwise the window opens at the size it last had
  bool pair_sif_triangles = true;  // .sif triangles paired into quads (`--triangles`: not)
  // A script that cannot be read closes the window with status 1 (the desktop); otherwise the window
  // stays on its file with the error in the log, the script ended (a web page cannot close itself).
  bool quits_on_bad_script = true;
};

// Opens the window and runs until the user (or the script) quits. Returns the exit status: 0, or 1 when
// the window could not open or a script command failed.
int run_viewer(const ViewerOptions& options);

}  // namespace nome::viewer
