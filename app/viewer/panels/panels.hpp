#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <imgui.h>
#include <glm/vec3.hpp>

#include "nome/edit/document.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/zipper.hpp"
#include "nome/scene/scene.hpp"
#include "render/display_settings.hpp"
#include "viewer/commands/actions.hpp"
#include "viewer/layout.hpp"
#include "viewer/message_log.hpp"
#include "viewer/panels/menu_sink.hpp"
#include "viewer/session/recent_files.hpp"
#include "viewer/session/stage_pipeline.hpp"
#include "viewer/view/picking.hpp"
#include "viewer/view/selection.hpp"

// The ImGui panels, one file each: each draws from what it is given and reports what the user changed;
// actions go through the registry, so a button does what its key and its script name do.
namespace nome::viewer {

// Which panels are up (Help, its key); the sidebars and the log are in LayoutSettings.
struct PanelVisibility {
  bool is_help_shown = false;
};

// The panels a script can scroll (`scroll PANEL PIXELS`).
enum class ScrolledPanel { controls, parameters, log };

// A panel pinned to its place in the layout, with a title bar and no collapse or move. When `width` is
// given the panel can be resized by its edge: the width the user dragged it to is written there. Call
// ImGui::End() after it whatever it returns. `scroll` pixels are added to its scroll position.
bool begin_docked_panel(const char* title, const ScreenRect& rect, double* width = nullptr,
                        double scroll = 0.0);

// What the menu bar needs to know to enable its items.
struct MenuContext {
  const RecentFiles& recent;
  bool has_document;
  bool has_scene;
  bool can_undo;
  bool can_redo;
};
// The menu bar, drawn through `menus`; returns the recent file chosen in File > Open Recent, if any.
std::optional<std::filesystem::path> draw_main_menu(MenuSink& menus, const ActionRegistry& actions,
                                                    const MenuContext& context,
                                                    render::DisplaySettings& display, LayoutSettings& layout);

// The control panel's state: stage settings, edit buttons, colours.
struct ControlPanelModel {
  PipelineSettings& settings;
  ZipperOptions& zipper;
  render::DisplaySettings& display;
  EditColors& edit_colors;
  const Document* document;  // none without a file
  bool can_edit;
  bool is_parameter_lock_on;
  std::optional<bool> sif_pairing;  // a .sif file is open: whether its triangles are paired
  float& sharpness;                 // the weight K gives the selected edges
};
// What the control panel changed that needs the renderer told.
struct ControlPanelChanges {
  bool is_selection_changed = false;
  bool is_edit_color_changed = false;
};
// Draws into the current window (the left sidebar, under the tools' sections there).
ControlPanelChanges draw_control_panel(const ActionRegistry& actions, ControlPanelModel model);

// The shown stage's report and its bounding box's size (in the export unit: mm).
void draw_topology_section(const TopologyReport& report, const glm::dvec3& size);

// The log across the bottom of the viewport: a bar that opens and collapses it (`is_open`), then the
// messages, scrolled to the newest unless the user scrolled up (or by `scroll` pixels). Returns the place
// of a located message the user clicked.
std::optional<scene::SourcePlace> draw_log_panel(const MessageLog& log, const ScreenRect& rect, bool& is_open,
                                                 double scroll);
// Errors red, warnings amber, in the log and the status bar.
ImVec4 message_color(MessageLevel level);

// The status bar's summary of the document and the shown stage (empty file: no document).
struct StatusLine {
  std::string file;
  bool is_modified = false;
  Stage stage = Stage::scene;
  Index vertices = 0;
  Index faces = 0;
  glm::dvec3 size{0.0};            // the bounding box of the shown stage
  std::vector<std::string> notes;  // the tools' words ("vertex mode", "line 7"), in their order
};
// "12.5 x 8 x 3.25 mm": a bounding box's size in the export unit.
std::string size_text(const glm::dvec3& size);
void draw_status_bar(const std::optional<StatusLine>& status, const MessageLog& log);
void draw_help_overlay(const ActionRegistry& actions, bool& is_shown);
// The spinner while a stage takes longer than a frame, with the kernel task and its percentage once the
// pipeline reports them.
void draw_progress(double seconds_running, const WorkProgress& progress);

// The status bar's height, which the log panel sits above.
float status_bar_height();

}  // namespace nome::viewer
