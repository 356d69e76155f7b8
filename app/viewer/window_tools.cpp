#include <algorithm>

#include <imgui.h>

#include "nome/error.hpp"
#include "viewer/window.hpp"

// The window's tools, asked in their order: their commands, sections, paints and script commands.
// The window knows them only through the Tool interface.
namespace nome::viewer {

void Window::add_tool(std::unique_ptr<Tool> tool) {
  tool->bind(tool_context_);
  tools_.push_back(std::move(tool));
}

void Window::paint_faces() {
  const StageResult* shown = stage_.shown();
  if (!shown) return;
  std::vector<FacePaint> paints;
  for (const std::unique_ptr<Tool>& tool : tools_)
    for (const FacePaint& paint : tool->face_paints(tool_context_)) paints.push_back(paint);
  show_face_colors(renderer_, *shown, edit_colors_, paints);
}

bool Window::has_unsaved_changes() const {
  return std::any_of(tools_.begin(), tools_.end(),
                     [](const auto& tool) { return tool->has_unsaved_changes(); });
}

bool Window::is_any_tool_busy() const {
  return std::any_of(tools_.begin(), tools_.end(), [](const auto& tool) { return tool->is_busy(); });
}

void Window::draw_tool_sections(ToolSide side) {
  for (const std::unique_ptr<Tool>& tool : tools_) {
    const std::string title = tool->title();
    if (title.empty() || tool->side() != side) continue;
    const ImGuiTreeNodeFlags flags = tool->is_section_open() ? ImGuiTreeNodeFlags_DefaultOpen : 0;
    if (ImGui::CollapsingHeader(title.c_str(), flags)) tool->draw_section(tool_context_);
  }
}

void Window::show_place(const scene::SourcePlace& place) {
  for (const std::unique_ptr<Tool>& tool : tools_)
    if (tool->show_place(tool_context_, place)) return;
  log_.info(place.file + ":" + std::to_string(place.location.line) + ": no tool shows source text");
}

bool Window::run_tool_script(const ScriptCommand& command) {
  for (const std::unique_ptr<Tool>& tool : tools_)
    if (const std::optional<bool> done = tool->run_script(tool_context_, command)) return *done;
  if (command.kind == ScriptCommand::Kind::tool) {
    if (const std::optional<bool> done = actions_.run_tool_command(command.words[0])) return *done;
    throw InvalidInputError("tool: no tool has a command '" + command.words[0] + "'");
  }
  throw InvalidInputError("no tool of this window takes this command");
}

}  // namespace nome::viewer
