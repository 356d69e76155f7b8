#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "nome/scene/source_place.hpp"

struct ImGuiInputTextCallbackData;

namespace nome::viewer {

// What the user asked of the text pane this frame.
struct TextPaneRequest {
  bool apply = false;            // Apply, Ctrl+Enter
  bool save = false;             // Save, Ctrl+S while typing in it
  bool loads_from_disk = false;  // "Load from disk" after another program changed the file
};

// The scene text pane (JIPCAD's editor beside the view): the open file's text with line numbers, edited
// in ImGui 1.86's multiline input. No syntax colours (that input has none); the line of the first error
// is marked in the line-number column and tinted, its column underlined, its message on hover; the
// statement that made the selected face or vertex is tinted and scrolled to. Applying and saving are the
// window's (SessionController::apply_text, save_text): the pane only keeps the text and the marks.
class TextPane {
 public:
  // The file shown. Reads its text when `disk_version` moved (opened, saved, changed by another
  // program): a pane whose text is the file's takes the new text; one with the user's changes keeps them
  // and says that the file changed (Load from disk replaces them). Flat files (.obj, ...) show no text.
  void sync(const std::filesystem::path& file, bool is_scene, std::uint64_t disk_version);
  // Replaces the text with the file's as it is on disk now.
  void load_from_disk();

  const std::filesystem::path& file() const { return file_; }
  bool is_scene() const { return is_scene_; }
  const std::string& text() const { return text_; }
  // The text as if the user typed it (the script's `text-set`): not applied, not saved.
  void set_text(std::string text);
  // The text differs from the file on disk.
  bool is_modified() const { return is_scene_ && text_ != disk_text_; }
  bool is_changed_on_disk() const { return is_changed_on_disk_; }
  // The file was written with the pane's text.
  void saved() { disk_text_ = text_; }

  // The errors of the last evaluation; those in this file are marked (the first one's line tinted).
  void set_errors(const std::vector<scene::Diagnostic>& errors);
  const std::vector<scene::Diagnostic>& errors() const { return errors_; }
  // The statement of the selected face or vertex (none: no selection, or one no statement made); a new
  // one is scrolled to.
  void set_statement(const std::optional<scene::SourcePlace>& place);
  std::optional<int> statement_line() const { return statement_line_; }
  // Byte ranges of the text to mark (the numbers a drag in progress rewrites); a new first one is scrolled
  // to.
  void set_marks(std::vector<std::pair<std::size_t, std::size_t>> marks);
  const std::vector<std::pair<std::size_t, std::size_t>>& marks() const { return marks_; }
  // Puts the text cursor at a place of this file, scrolled into view (a click on an error in the log).
  void go_to(scene::SourceLocation at);
  // Where the text cursor is (1-based line and byte column).
  scene::SourceLocation cursor() const;
  // Whether the place lies in the file shown.
  bool is_in_file(const std::string& file) const;

  // `text: shown, 14 lines, cursor 3:5, error 3:14, statement line 7, modified` for the script's `state`.
  std::string state_text(bool is_shown) const;

  // Draws into the current window (text_pane_draw.cpp).
  TextPaneRequest draw();

 private:
  void draw_toolbar(TextPaneRequest& request);
  void draw_editor(TextPaneRequest& request);
  void draw_gutter(float gutter, float width);
  void handle_keys(unsigned id, TextPaneRequest& request);
  void follow_cursor(float line_height);
  const scene::Diagnostic* first_error() const { return errors_.empty() ? nullptr : &errors_.front(); }
  std::string error_text_on(int line) const;
  static int on_edit(ImGuiInputTextCallbackData* data);

  std::filesystem::path file_;
  bool is_scene_ = false;
  std::string text_;
  std::string disk_text_;  // the file's text as the pane last read or wrote it
  std::uint64_t disk_version_ = ~std::uint64_t(0);
  bool is_changed_on_disk_ = false;
  std::vector<scene::Diagnostic> errors_;  // in this file
  std::optional<int> statement_line_;
  std::vector<std::pair<std::size_t, std::size_t>> marks_;
  std::size_t cursor_offset_ = 0;
  std::size_t followed_offset_ = 0;  // where the cursor was when the view last followed it
  std::optional<std::size_t> pending_cursor_;
  std::optional<int> pending_scroll_line_;
  bool is_focus_pending_ = false;
  bool is_replaced_ = false;  // the text changed under the input field, which must let go of its copy
};

}  // namespace nome::viewer
