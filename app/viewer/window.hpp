#pragma once

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "render/display_settings.hpp"
#include "render/scene_renderer.hpp"
#include "viewer/commands/actions.hpp"
#include "viewer/commands/script_runner.hpp"
#include "viewer/layout.hpp"
#include "viewer/message_log.hpp"
#include "viewer/panels/file_dialog.hpp"
#include "viewer/panels/panels.hpp"
#include "viewer/panels/parameter_panel.hpp"
#include "viewer/panels/prompt_dialog.hpp"
#include "viewer/platform.hpp"
#include "viewer/session/session_controller.hpp"
#include "viewer/session/stage_view.hpp"
#include "viewer/tools/tool.hpp"
#include "viewer/tools/tool_context.hpp"
#include "viewer/view/picking.hpp"
#include "viewer/view/selection.hpp"
#include "viewer/view/view_controller.hpp"
#include "viewer/viewer.hpp"

namespace nome::viewer {

// One viewer window: a thin loop over its rooms. Each frame reads the input (camera, clicks, keys), lets
// the script take a step, shows the latest stage, draws the scene through the renderer (GL, or null in
// tests) and the ImGui panels, and asks the prompts. The rooms, one concern each:
//   view/        camera and mouse, picking, the selection
//   commands/    the one table of keys, menu items, buttons and script names; the script's runner
//   session/     stage jobs and picking BVH, open, save, edits, autosave, one undo history
//   panels/      one panel each (controls, sliders, log, status, menus), the file and prompt dialogs
//   tools/       the tools (tool_list.cpp): sections, keys, clicks, overlays, script commands
//   layout       sidebars, pane, log, viewport
//   window_actions  what each action does here      window_panels  the panels in their places
//   window_tools    the tools asked in their order  window_history settings and colours as undo steps
class Window : private ScriptHost {
 public:
  // Needs ImGui initialised (a frame begun before each frame()); the platform and renderer outlive it.
  Window(Platform& platform, render::SceneRenderer& renderer, const ViewerOptions& options,
         const ViewerStores& stores);
  ~Window() override;
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // One frame. False once the window should close.
  bool frame(const InputFrame& input);
  // After the panels are drawn into the back buffer, before it is shown: takes a pending screenshot.
  void after_draw();
  // True while something moves without input (a stage being computed, a script, a drag): the loop then
  // draws continuously; otherwise it sleeps until an event (or the file watcher's next look).
  bool is_animating() const;
  // The window manager's close button, Ctrl+Q, File > Quit: asks about unsaved changes first.
  void request_quit();
  int exit_status() const { return exit_status_; }

  // Opens a file; on error logs it and keeps the current one.
  void open(const std::filesystem::path& path);
  // The file's stage blocks and render statements as the control panel's and the view's starting point.
  void apply_file_defaults();
  // A file whose subdivision level or offset reads a slider (SLIDE's subdivision node, `sd_level {expr
  // $b.n}`) is followed when its sliders move, as it was applied at opening.
  void follow_file_stages(const scene::Scene& scene);
  // Opens a file the user chose: asks about unsaved changes first; an .anom file applies instead.
  void request_open(const std::filesystem::path& path);
  // Files dropped on the window (GLFW's drop callback and the script's `drop`): the last scene or mesh
  // opens, as there is one document per window, then the .anom files apply to it. Returns whether each
  // opened or applied (or waits for the unsaved-changes answer).
  bool drop(const std::vector<std::filesystem::path>& paths) override;
  // Script commands from outside the window (a web page's call): parsed now, run one a frame after those
  // queued; the log echoes from now on. Throws InvalidInputError for text that is not a script.
  void run_script(const std::string& text, const std::string& origin);
  bool is_running_script() const { return !script_.is_done(); }
  // Writes the panels' arrangement for the next run (the window does when it closes; a web page, whose
  // window never closes, when it is hidden). Not in a scripted session, which starts from the defaults.
  void keep_layout();

  // What tests look at.
  const MessageLog& log() const { return log_; }
  const Selection& selection() const { return selection_; }
  const SessionController& sessions() const { return sessions_; }
  const StageResult* shown() const { return stage_.shown(); }
  const render::Camera& camera() const { return view_.camera(); }
  const render::DisplaySettings& display() const { return display_; }
  const PanelVisibility& panels() const { return panels_; }
  // The first tool of this type, if the window has one.
  template <typename T>
  const T* find_tool() const {
    for (const auto& tool : tools_)
      if (const T* found = dynamic_cast<const T*>(tool.get())) return found;
    return nullptr;
  }
  // Takes a tool after those of tool_list.cpp: its commands are bound and it is asked from now on.
  void add_tool(std::unique_ptr<Tool> tool);
  const LayoutSettings& layout_settings() const { return layout_settings_; }
  // Where the panels and the viewport are this frame, and what the last frame drew where.
  const ScreenLayout& layout() const { return layout_; }
  const LayoutReport& layout_report() const { return report_; }

 private:
  // window_actions.cpp: what each action does here
  void bind_actions();
  void bind_file_actions();
  void bind_view_actions();
  void open_browser(Action action);
  bool edit(Action action);
  bool can_edit() const;
  // Whether the open .sif file's triangles are paired; none when no .sif file is open.
  std::optional<bool> sif_pairing() const;
  // window.cpp
  void handle_mouse(const InputFrame& input);
  void update_stage();
  void show_result(StageResult result);
  void refresh_selection();
  // New rim lines (new ids: a selection of rim vertices is cleared), or new positions for the same lines.
  void show_rim_lines(RimLines lines);
  void move_rim_lines(std::vector<Vec3> positions);
  void draw_rim_lines();
  void frame_all();
  void draw_prompts();
  // window_tools.cpp: the tools asked in their order
  void paint_faces();
  // Writes the stage on screen (as a tool places it for export); throws nome::Error when it cannot.
  void write_shown_mesh(const std::filesystem::path& path);
  bool has_unsaved_changes() const;
  bool is_any_tool_busy() const;
  void draw_tool_sections(ToolSide side);
  void draw_tool_pane();
  // Shows a place of a located message the user clicked in the log.
  void show_place(const scene::SourcePlace& place);
  bool run_tool_script(const ScriptCommand& command) override;
  std::vector<double> followed_values_;  // the sliders the file's stage settings were last read at
  scene::StageSettings followed_stages_;
  // window_history.cpp
  struct ViewState {
    PipelineSettings settings;
    render::DisplaySettings colors;  // only its colours are recorded
    EditColors edit_colors;
  };
  ViewState view_state() const;
  void restore(const ViewState& state);
  void record_view_state();
  // window_panels.cpp
  void apply_style();
  void arrange_layout();
  render::PixelRect viewport_pixels() const;
  void draw_panels();
  void draw_sidebars();
  void draw_status();
  void draw_browser();
  double take_scroll(ScrolledPanel panel);
  // The sliders the selected vertices and faces depend on.
  std::vector<scene::ParameterId> selection_parameters(const scene::Scene& scene) const;
  void print_layout() override { is_layout_print_pending_ = true; }
  void print_state() override;
  void scroll(ScrolledPanel panel, double pixels) override;
  // ScriptHost (window_actions.cpp)
  void click(glm::dvec2 pixel) override;
  bool double_click(glm::dvec2 pixel) override;
  void answer_unsaved(UnsavedAnswer answer) override;
  // A script's key: to the tool that holds the input (a drag) as a key pressed now, else to the action table.
  bool press_key(const std::string& label) override;
  bool run_action(Action action) override { return actions_.run(action); }
  void set_view(double azimuth, double elevation) override;
  void take_screenshot(const std::filesystem::path& path) override {
    pending_screenshot_ = path;
    is_screenshot_of_model_ = false;
  }
  bool export_mesh(const std::filesystem::path& path) override;
  void answer_recovery(bool restore) override;
  void set_parameter(const std::string& name, double value) override { sessions_.set_parameter(name, value); }
  void save(const std::filesystem::path& path) override { sessions_.save(path); }
  void set_subdivision(double levels) override;
  void set_offset(double distance) override;
  void set_display_color(const std::string& name, glm::vec3 color) override;
  void apply_setting(const std::string& name, const std::string& value) override;
  void quit() override { should_close_ = true; }

  Platform& platform_;
  render::SceneRenderer& renderer_;
  MessageLog log_;
  SessionController sessions_;
  StageView stage_;
  ViewController view_;
  Selection selection_;
  ActionRegistry actions_;
  ScriptRunner script_;
  Prompts prompts_;
  FileBrowser browser_;
  Action browser_purpose_ = Action::open;

  render::DisplaySettings display_;
  EditColors edit_colors_;
  ZipperOptions zipper_options_;
  float sharpness_ = infinite_sharpness;  // the weight K gives the selected edges (the Edit section's)
  RimLines rim_lines_;                    // the scene's, drawn over every stage and framed with the mesh
  render::SceneLights scene_lights_;      // the lights the scene places, at the current slider values
  PickableRims rims_;                     // rim_lines_ numbered after the shown mesh's vertices
  glm::dvec3 shown_size_{0.0};            // the shown stage's bounding box
  PanelVisibility panels_;
  glm::dvec3 shown_low_{0.0}, shown_high_{0.0};  // the shown stage's bounding box
  ParameterPanelState parameters_;

  LayoutSettings layout_settings_;
  std::filesystem::path layout_file_;  // none for a scripted session, which starts from the defaults
  ScreenLayout layout_;
  ToolContext tool_context_;
  std::vector<std::unique_ptr<Tool>> tools_;
  LayoutReport report_;
  bool is_layout_known_ = false;
  bool is_framing_pending_ = false;  // framing waits for the first layout
  bool is_layout_print_pending_ = false;
  std::array<double, 3> pending_scroll_{};
  int settle_frames_ = 0;               // frames a script waits for ImGui to apply a scroll
  ViewState recorded_{};                // the stage settings and colours the undo history last saw
  bool is_settings_drag_open_ = false;  // a held widget's changes merge into one step
  float style_scale_ = 0.0f;
  bool is_style_dark_ = false;

  glm::dvec2 last_cursor_{0.0};  // where this frame's input put the cursor
  bool should_close_ = false;
  std::optional<std::filesystem::path> pending_screenshot_;
  bool is_screenshot_of_model_ = false;  // P: the viewport only; the script's screenshot: the window
  int frames_drawn_ = 0;
  int exit_status_ = 0;
};

}  // namespace nome::viewer
