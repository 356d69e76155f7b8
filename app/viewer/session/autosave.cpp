#include "viewer/session/autosave.hpp"

#include <cstdio>
#include <cstdlib>

#include "viewer/session/session.hpp"

namespace nome::viewer {
namespace {

// FNV-1a: a name that stays the same from one run (and build) of the viewer to the next.
std::uint64_t path_hash(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

}  // namespace

Autosave::Autosave(std::filesystem::path folder) : folder_(std::move(folder)) {}

std::filesystem::path Autosave::default_folder() {
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state)
    return std::filesystem::path(state) / "nome" / "recovery";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".local" / "state" / "nome" / "recovery";
  return {};
}

std::filesystem::path Autosave::recovery_file(const std::filesystem::path& document) const {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(document, ec).lexically_normal();
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", (unsigned long long)path_hash(absolute.string()));
  return folder_ / (document.stem().string() + "-" + hash + ".nome");
}

std::optional<std::filesystem::path> Autosave::pending_recovery(const std::filesystem::path& document) const {
  if (folder_.empty()) return std::nullopt;
  const std::filesystem::path file = recovery_file(document);
  std::error_code ec;
  const auto recovered = std::filesystem::last_write_time(file, ec);
  if (ec) return std::nullopt;
  const auto saved = std::filesystem::last_write_time(document, ec);
  if (!ec && saved >= recovered) return std::nullopt;
  return file;
}

void Autosave::update(const Session& session, double now) {
  if (folder_.empty() || !session.scene()) return;
  const std::filesystem::path file = recovery_file(session.path());
  if (!session.is_modified()) {
    // Saved: the recovery file is out of date. One of another document (opened over unsaved changes)
    // stays, for the next time that document is opened.
    if (written_ == file) discard(session.path());
    return;
  }
  const bool is_due =
      written_ != file || session.accepted_edits() != written_edits_ || now - written_at_ >= interval_seconds;
  if (!is_due || (written_ == file && session.version() == written_version_)) return;
  // Recorded before writing: a failure is retried after the interval or the next edit, not every frame.
  written_ = file;
  written_at_ = now;
  written_version_ = session.version();
  written_edits_ = session.accepted_edits();
  std::error_code ec;
  std::filesystem::create_directories(folder_, ec);
  session.write_copy(file);
}

void Autosave::discard(const std::filesystem::path& document) {
  if (folder_.empty()) return;
  const std::filesystem::path file = recovery_file(document);
  std::error_code ec;
  std::filesystem::remove(file, ec);
  if (written_ == file) written_.clear();
}

}  // namespace nome::viewer
