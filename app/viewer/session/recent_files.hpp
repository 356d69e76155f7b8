#pragma once

#include <filesystem>
#include <vector>

namespace nome::viewer {

// The files opened last, newest first (File > Open Recent, Ctrl+1..4), kept in
// $XDG_CONFIG_HOME/nome/recent (or ~/.config/nome/recent) one path a line.
class RecentFiles {
 public:
  static constexpr std::size_t capacity = 8;

  explicit RecentFiles(std::filesystem::path store);
  // The store of this user, from the environment.
  static std::filesystem::path default_store();

  void add(const std::filesystem::path& file);
  const std::vector<std::filesystem::path>& files() const { return files_; }

 private:
  std::filesystem::path store_;
  std::vector<std::filesystem::path> files_;
};

}  // namespace nome::viewer
