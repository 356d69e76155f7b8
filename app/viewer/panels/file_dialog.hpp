#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace nome::viewer {

// A small ImGui file dialog: the folders and the matching files of one folder, a name field, and the
// button that accepts. Used by File > Open, Save As and Export.
class FileBrowser {
 public:
  // Shows the dialog from the next frame on, in `folder`, listing files with these extensions
  // (".nome", ...); `accept_label` is "Open" or "Save".
  void open(std::string title, std::filesystem::path folder, std::vector<std::string> extensions,
            std::string accept_label, std::string name = {});
  bool is_open() const { return is_open_; }
  // Draws the dialog; returns the chosen path on the frame it is accepted.
  std::optional<std::filesystem::path> draw();

 private:
  void list(const std::filesystem::path& folder);
  bool matches(const std::filesystem::path& file) const;

  bool is_open_ = false;
  bool is_new_ = false;
  std::string title_;
  std::string accept_label_;
  std::filesystem::path folder_;
  std::vector<std::string> extensions_;
  std::vector<std::filesystem::path> folders_, files_;
  char name_[512] = {};
  std::string error_;
};

}  // namespace nome::viewer
