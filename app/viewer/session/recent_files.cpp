#include "viewer/session/recent_files.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

#include "nome/atomic_file.hpp"
#include "nome/error.hpp"

namespace nome::viewer {

RecentFiles::RecentFiles(std::filesystem::path store) : store_(std::move(store)) {
  std::ifstream in(store_);
  std::string line;
  while (std::getline(in, line) && files_.size() < capacity)
    if (!line.empty()) files_.emplace_back(line);
}

std::filesystem::path RecentFiles::default_store() {
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config)
    return std::filesystem::path(config) / "nome" / "recent";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".config" / "nome" / "recent";
  return {};
}

void RecentFiles::add(const std::filesystem::path& file) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(file, ec);
  const std::filesystem::path entry = ec ? file : absolute.lexically_normal();
  files_.erase(std::remove(files_.begin(), files_.end(), entry), files_.end());
  files_.insert(files_.begin(), entry);
  if (files_.size() > capacity) files_.resize(capacity);
  if (store_.empty()) return;
  std::string text;
  for (const auto& f : files_) text += f.string() + "\n";
  // A read-only home must not stop the viewer: the list then lives for this session only.
  try {
    std::filesystem::create_directories(store_.parent_path(), ec);
    write_file_atomically(store_, [&](std::ostream& out) { out << text; });
  } catch (const Error&) {
  }
}

}  // namespace nome::viewer
