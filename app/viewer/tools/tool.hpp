#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "nome/mesh/mesh.hpp"
#include "nome/scene/source_place.hpp"
#include "render/cube_set.hpp"
#include "viewer/commands/script.hpp"
#include "viewer/tools/tool_context.hpp"

namespace nome::viewer {

// A face of the shown mesh and the RGBA colour painted over its own.
using FacePaint = std::pair<Index, std::array<std::uint8_t, 4>>;

// Which sidebar holds a tool's section: the controls (left) or the sliders (right).
enum class ToolSide { left, right };

// A piece of the viewer the window knows only through this interface: its section in a sidebar, its keys
// and script commands, its mouse clicks, what it draws over the view. Every hook has a default that does
// nothing, so a tool overrides only what it has. Tools are made in one place (tool_list.cpp), one line
// each; the window calls them in that order.
class Tool {
 public:
  virtual ~Tool() = default;

  // The title of its section (a header collapsed until opened); empty: no section.
  virtual std::string title() const { return {}; }
  virtual ToolSide side() const { return ToolSide::right; }
  // Whether its section starts open.
  virtual bool is_section_open() const { return false; }
  virtual void draw_section(ToolContext&) {}

  // Once, when the window takes the tool: binds its rows of the action table (context.actions.bind) and
  // adds its own keys and `tool NAME` script commands (context.actions.add).
  virtual void bind(ToolContext&) {}
  // After the window looked at the stage (each frame, and after each change of the document).
  virtual void update(ToolContext&) {}
  // Each frame, just before the scene is drawn: what the tool sets on the display.
  virtual void before_draw(ToolContext&) {}
  // Over the viewport, after the panels.
  virtual void draw_overlay(ToolContext&) {}
  // This frame's mouse and keys before the camera and the shortcuts see them: true when the tool took
  // them (a drag it holds), and nothing else gets them.
  virtual bool take_input(ToolContext&, const InputFrame&) { return false; }
  // A left click in the viewport on the shown stage: true when the tool took it (the first one wins).
  virtual bool click(ToolContext&, glm::dvec2) { return false; }
  // A script command the tool answers (mode, color, text-set, ...): none when it is not the tool's, else
  // whether it succeeded.
  virtual std::optional<bool> run_script(ToolContext&, const ScriptCommand&) { return std::nullopt; }

  // What it paints over the shown stage's faces and the markers it puts on it.
  virtual std::vector<FacePaint> face_paints(const ToolContext&) const { return {}; }
  virtual std::vector<render::CubeMarker> markers() const { return {}; }
  // The mesh File > Export writes instead of the shown one (the print preparation's placing).
  virtual std::optional<Mesh> exported(const ToolContext&, const Mesh&) const { return std::nullopt; }

  // The status bar's words ("vertex mode") and the script `state` line's part; empty: none.
  virtual std::string status_text(const ToolContext&) const { return {}; }
  virtual std::string state_text(const ToolContext&) const { return {}; }

  // The pane beside the left sidebar, shown and hidden by the layout (one tool may have it).
  virtual std::string pane_title() const { return {}; }
  virtual void draw_pane(ToolContext&) {}
  // A click on a located message of the log: true when the tool showed the place.
  virtual bool show_place(ToolContext&, const scene::SourcePlace&) { return false; }

  // Changes of its own that quitting or opening another file would lose, and saving them (false: the save
  // failed and was logged).
  virtual bool has_unsaved_changes() const { return false; }
  virtual bool save_changes(ToolContext&) { return true; }

  // The script waits while a tool is busy; the loop keeps drawing while one is animating.
  virtual bool is_busy() const { return false; }
  virtual bool is_animating() const { return false; }
};

}  // namespace nome::viewer
