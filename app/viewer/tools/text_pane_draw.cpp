#include <algorithm>
#include <cstdio>

#include <imgui.h>
#include <imgui_internal.h>  // the active item: 1.86's multiline input reverts on Esc unless let go first
#include <imgui_stdlib.h>

#define GLFW_INCLUDE_NONE  // GL comes from glad (render/gl.hpp)
#include <GLFW/glfw3.h>

#include "nome/scene/source_text.hpp"
#include "viewer/tools/text_pane.hpp"

namespace nome::viewer {

using scene::byte_offset;
using scene::line_count;
namespace {

const ImVec4 error_color(0.85f, 0.15f, 0.15f, 1.0f);
const ImVec4 mark_color(0.95f, 0.65f, 0.10f, 1.0f);

ImU32 tint(const ImVec4& color, float alpha) {
  return ImGui::GetColorU32(ImVec4(color.x, color.y, color.z, alpha));
}

bool is_key_pressed(ImGuiKey key) {
  return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), false);
}

}  // namespace

int TextPane::on_edit(ImGuiInputTextCallbackData* data) {
  auto* pane = static_cast<TextPane*>(data->UserData);
  if (pane->pending_cursor_) {
    const int at = int(std::min<std::size_t>(*pane->pending_cursor_, std::size_t(data->BufTextLen)));
    data->CursorPos = data->SelectionStart = data->SelectionEnd = at;
    pane->pending_cursor_.reset();
  }
  pane->cursor_offset_ = std::size_t(data->CursorPos);
  return 0;
}

TextPaneRequest TextPane::draw() {
  TextPaneRequest request;
  if (!is_scene_) {
    ImGui::TextDisabled(file_.empty() ? "no file: open a scene (.nome) to see its text"
                                      : "no text: only scene files (.nome .nom .slf) are shown here");
    return request;
  }
  draw_toolbar(request);
  draw_editor(request);
  return request;
}

void TextPane::draw_toolbar(TextPaneRequest& request) {
  if (ImGui::Button("Apply")) request.apply = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("evaluate the text as a save would (Ctrl+Enter); on an error the geometry stays");
  ImGui::SameLine();
  if (ImGui::Button("Save")) request.save = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("write the text to %s and apply it (Ctrl+S while typing here)",
                      file_.filename().string().c_str());
  if (is_changed_on_disk_) {
    ImGui::SameLine();
    if (ImGui::Button("Load from disk")) request.loads_from_disk = true;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("another program changed the file: take its text, drop yours");
  }
  ImGui::SameLine();
  ImGui::TextDisabled("%s%s", file_.filename().string().c_str(), is_modified() ? " (modified)" : "");
  if (const scene::Diagnostic* error = first_error()) {
    ImGui::PushStyleColor(ImGuiCol_Text, error_color);
    ImGui::TextWrapped("%d:%d: %s", error->location.line, error->location.column, error->message.c_str());
    ImGui::PopStyleColor();
  } else if (is_changed_on_disk_) {
    ImGui::TextWrapped("the file changed on disk; the geometry shows it, this text is yours");
  }
}

void TextPane::handle_keys(unsigned id, TextPaneRequest& request) {
  if (ImGui::GetActiveID() != id) return;
  const ImGuiIO& io = ImGui::GetIO();
  // Let go before the field sees Esc, which would put back the text it had when it was clicked.
  if (is_key_pressed(ImGuiKey_Escape)) ImGui::ClearActiveID();
  if (io.KeyCtrl && (is_key_pressed(ImGuiKey_Enter) || is_key_pressed(ImGuiKey_KeyPadEnter))) {
    // The field lets go on Ctrl+Enter: take it back, cursor and all.
    request.apply = true;
    is_focus_pending_ = true;
  }
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_S, false)) request.save = true;
}

void TextPane::draw_gutter(float gutter, float width) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float line_height = ImGui::GetFontSize();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float top = origin.y + style.FramePadding.y;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(ImVec2(origin.x + gutter, origin.y),
                      ImVec2(origin.x + width, top + line_count(text_) * line_height + style.FramePadding.y),
                      ImGui::GetColorU32(ImGuiCol_FrameBg));
  const int first = std::max(0, int((ImGui::GetScrollY() - style.FramePadding.y) / line_height));
  const int last = std::min(line_count(text_), first + int(ImGui::GetWindowHeight() / line_height) + 2);
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const bool is_hovered = ImGui::IsWindowHovered();
  for (int i = first; i < last; ++i) {
    const int line = i + 1;
    const float y = top + i * line_height;
    const std::string error = error_text_on(line);
    if (statement_line_ == line)
      draw->AddRectFilled(ImVec2(origin.x, y), ImVec2(origin.x + width, y + line_height),
                          ImGui::GetColorU32(ImGuiCol_TextSelectedBg));
    if (!error.empty()) {
      draw->AddRectFilled(ImVec2(origin.x, y), ImVec2(origin.x + width, y + line_height),
                          tint(error_color, 0.2f));
      const float r = line_height * 0.3f;
      draw->AddCircleFilled(ImVec2(origin.x + r + 2.0f, y + line_height * 0.5f), r, tint(error_color, 1.0f));
      if (is_hovered && mouse.y >= y && mouse.y < y + line_height && mouse.x < origin.x + width)
        ImGui::SetTooltip("%s", error.c_str());
    }
    char number[16];
    std::snprintf(number, sizeof number, "%d", line);
    const float w = ImGui::CalcTextSize(number).x;
    draw->AddText(ImVec2(origin.x + gutter - w - style.ItemSpacing.x, y),
                  ImGui::GetColorU32(error.empty() ? ImGuiCol_TextDisabled : ImGuiCol_Text), number);
  }
  // The numbers a drag rewrites, tinted and underlined.
  for (const auto& [begin, end] : marks_) {
    const scene::SourceLocation at = scene::location_at(text_, begin);
    if (at.line < first + 1 || at.line > last) continue;
    const std::size_t start = byte_offset(text_, {at.line, 1});
    const float x = origin.x + gutter + style.FramePadding.x +
                    ImGui::CalcTextSize(text_.data() + start, text_.data() + begin).x;
    const float w = ImGui::CalcTextSize(text_.data() + begin, text_.data() + std::min(end, text_.size())).x;
    const float y = top + (at.line - 1) * line_height;
    draw->AddRectFilled(ImVec2(x - 1.0f, y), ImVec2(x + w + 1.0f, y + line_height), tint(mark_color, 0.35f));
    draw->AddLine(ImVec2(x, y + line_height - 1.0f), ImVec2(x + w, y + line_height - 1.0f),
                  tint(mark_color, 1.0f), 2.0f);
  }
  // The first error's column, underlined under the text (while the field is not scrolled sideways).
  if (const scene::Diagnostic* e = first_error();
      e && e->location.line >= first + 1 && e->location.line <= last) {
    const std::size_t start = byte_offset(text_, {e->location.line, 1});
    const std::size_t at = byte_offset(text_, e->location);
    const float x = origin.x + gutter + style.FramePadding.x +
                    ImGui::CalcTextSize(text_.data() + start, text_.data() + at).x;
    const float y = top + e->location.line * line_height - 1.0f;
    const float w = std::max(ImGui::CalcTextSize("m").x, 4.0f);
    draw->AddLine(ImVec2(x, y), ImVec2(x + w, y), tint(error_color, 1.0f), 2.0f);
  }
}

void TextPane::follow_cursor(float line_height) {
  const float pad = ImGui::GetStyle().FramePadding.y;
  const float height = ImGui::GetWindowHeight();
  if (pending_scroll_line_) {
    // A jump puts its line a third of the way down.
    ImGui::SetScrollY(std::max(0.0f, pad + (*pending_scroll_line_ - 1) * line_height - height / 3.0f));
    pending_scroll_line_.reset();
    return;
  }
  if (cursor_offset_ == followed_offset_) return;
  followed_offset_ = cursor_offset_;
  // Typing or arrows moved the cursor: keep its line in view (the field is as tall as the text).
  const float y = pad + (cursor().line - 1) * line_height;
  if (y < ImGui::GetScrollY())
    ImGui::SetScrollY(y);
  else if (y + 2.0f * line_height > ImGui::GetScrollY() + height)
    ImGui::SetScrollY(y + 2.0f * line_height - height);
}

void TextPane::draw_editor(TextPaneRequest& request) {
  ImGui::BeginChild("##source", ImVec2(0, 0), true);
  const ImGuiStyle& style = ImGui::GetStyle();
  const float line_height = ImGui::GetFontSize();
  char widest[16];
  std::snprintf(widest, sizeof widest, "%d", std::max(line_count(text_), 99));
  const float gutter = ImGui::CalcTextSize(widest).x + line_height + 2.0f * style.ItemSpacing.x;
  const float width = std::max(ImGui::GetContentRegionAvail().x, gutter + 100.0f);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  draw_gutter(gutter, width);
  const ImGuiID id = ImGui::GetID("##text");
  handle_keys(id, request);
  if (is_replaced_ && ImGui::GetActiveID() == id) ImGui::ClearActiveID();
  is_replaced_ = false;
  if (is_focus_pending_) ImGui::SetKeyboardFocusHere();
  is_focus_pending_ = false;
  ImGui::SetCursorScreenPos(ImVec2(origin.x + gutter, origin.y));
  // The field is as tall as the text (one line spare), so that it never scrolls itself: the pane's
  // scroll moves the line numbers and the text together. Its background is the gutter's rectangle.
  const float height = (line_count(text_) + 1) * line_height + 2.0f * style.FramePadding.y;
  ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0, 0, 0, 0));
  ImGui::InputTextMultiline("##text", &text_, ImVec2(width - gutter, height),
                            ImGuiInputTextFlags_AllowTabInput | ImGuiInputTextFlags_CallbackAlways, on_edit,
                            this);
  ImGui::PopStyleColor();
  if (ImGui::IsItemHovered()) {
    const int line = int((ImGui::GetIO().MousePos.y - origin.y - style.FramePadding.y) / line_height) + 1;
    if (const std::string error = error_text_on(line); !error.empty()) ImGui::SetTooltip("%s", error.c_str());
  }
  follow_cursor(line_height);
  ImGui::EndChild();
}

}  // namespace nome::viewer
