#include "viewer/tools/text_pane.hpp"

#include <sstream>

#include "nome/io/read_scene.hpp"
#include "nome/scene/source_text.hpp"

namespace nome::viewer {

using scene::byte_offset;
using scene::line_count;
using scene::location_at;

void TextPane::sync(const std::filesystem::path& file, bool is_scene, std::uint64_t disk_version) {
  if (file == file_ && is_scene == is_scene_ && disk_version == disk_version_) return;
  const bool is_other_file = file != file_;
  file_ = file;
  is_scene_ = is_scene;
  disk_version_ = disk_version;
  if (!is_scene_ || file_.empty()) {
    set_text({});
    disk_text_.clear();
    errors_.clear();
    return;
  }
  std::string on_disk;
  try {
    on_disk = read_text_file(file_);
  } catch (const std::exception&) {
    return;  // the file went away: the pane keeps what it had, and the next save writes it back
  }
  if (is_other_file || text_ == disk_text_) {
    set_text(on_disk);
    is_changed_on_disk_ = false;
  } else if (on_disk != disk_text_) {
    is_changed_on_disk_ = true;
  }
  if (is_other_file) {
    errors_.clear();
    statement_line_.reset();
  }
  disk_text_ = std::move(on_disk);
}

void TextPane::load_from_disk() {
  set_text(disk_text_);
  is_changed_on_disk_ = false;
}

void TextPane::set_text(std::string text) {
  text_ = std::move(text);
  cursor_offset_ = followed_offset_ = std::min(cursor_offset_, text_.size());
  is_replaced_ = true;
}

void TextPane::set_errors(const std::vector<scene::Diagnostic>& errors) {
  errors_.clear();
  for (const scene::Diagnostic& d : errors)
    if (d.severity == scene::Severity::error && is_in_file(d.file)) errors_.push_back(d);
}

void TextPane::set_statement(const std::optional<scene::SourcePlace>& place) {
  const std::optional<int> line =
      place && is_in_file(place->file) ? std::optional(place->location.line) : std::nullopt;
  if (line && line != statement_line_) pending_scroll_line_ = line;
  statement_line_ = line;
}

void TextPane::set_marks(std::vector<std::pair<std::size_t, std::size_t>> marks) {
  if (!marks.empty() && (marks_.empty() || marks.front().first != marks_.front().first))
    pending_scroll_line_ = location_at(text_, marks.front().first).line;
  marks_ = std::move(marks);
}

void TextPane::go_to(scene::SourceLocation at) {
  cursor_offset_ = byte_offset(text_, at);
  pending_cursor_ = cursor_offset_;
  pending_scroll_line_ = location_at(text_, cursor_offset_).line;
  is_focus_pending_ = true;
}

scene::SourceLocation TextPane::cursor() const {
  return location_at(text_, cursor_offset_);
}

bool TextPane::is_in_file(const std::string& file) const {
  if (file_.empty() || file.empty()) return false;
  const std::filesystem::path place(file);
  if (place.lexically_normal() == file_.lexically_normal()) return true;
  std::error_code ec;
  return std::filesystem::equivalent(place, file_, ec);
}

std::string TextPane::error_text_on(int line) const {
  std::string text;
  for (const scene::Diagnostic& d : errors_)
    if (d.location.line == line) text += (text.empty() ? "" : "\n") + d.to_string();
  return text;
}

std::string TextPane::state_text(bool is_shown) const {
  std::ostringstream out;
  const scene::SourceLocation at = cursor();
  out << "text: " << (is_shown ? "shown" : "hidden") << ", " << line_count(text_) << " lines, cursor "
      << scene::location_text(at) << ", error "
      << (first_error() ? scene::location_text(first_error()->location) : "none") << ", statement "
      << (statement_line_ ? "line " + std::to_string(*statement_line_) : "none") << ", "
      << (is_modified() ? "modified" : "saved");
  return out.str();
}

}  // namespace nome::viewer
