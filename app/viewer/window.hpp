#pragma once

#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "nome/query/border_lookup.hpp"
#include "nome/query/screen_projection.hpp"
#include "nome/query/triangle_bvh.hpp"
#include "render/camera.hpp"
#include "render/cube_set.hpp"
#include "render/display_settings.hpp"
#include "render/line_set.hpp"
#include "render/mesh_buffers.hpp"
#include "render/renderer.hpp"
#include "viewer/autosave.hpp"
#include "viewer/background_job.hpp"
#include "viewer/file_browser.hpp"
#include "viewer/key_registry.hpp"
#include "viewer/message_log.hpp"
#include "viewer/recent_files.hpp"
#include "viewer/script.hpp"
#include "viewer/selection.hpp"
#include "viewer/session.hpp"
#include "viewer/stage_pipeline.hpp"
#include "viewer/viewer.hpp"

struct GLFWwindow;

namespace nome::viewer {

// One viewer window (DESIGN.md "App"): camera, renderer, selection and panels over one Session.
// Immediate mode: every frame reads the input, draws the scene with the shared renderer, then the
// ImGui panels that read and write the session.
class Window {
 public:
  // Needs a current GL 3.3 core context with glad loaded and ImGui initialised for `window`.
  Window(GLFWwindow* window, const ViewerOptions& options);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // One frame: input, script step, scene, panels. False once the window should close.
  bool frame();
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
  // Opens a file the user chose (drag and drop, File > Open, Open Recent): asks about unsaved changes
  // first.
  void request_open(const std::filesystem::path& path);
  // An .anom file applies to the open scene instead of replacing it (the original program's workflow).
  // Returns whether it applied (a failure is logged).
  bool apply_anom(const std::filesystem::path& path);
  // Files dropped on the window (GLFW's drop callback and the script's `drop`): the last one wins, as
  // there is one document per window.
  // Returns whether each file opened or applied (or waits for the unsaved-changes answer).
  bool drop(const std::vector<std::filesystem::path>& paths);

 private:
  // setup
  void register_keys();
  // input
  void handle_mouse();
  void handle_keys();
  void click(glm::dvec2 pixel);
  // False when no surface is under the pixel (the orbit centre stays).
  bool double_click(glm::dvec2 pixel);
  // editing (report 7.3.3)
  bool can_edit() const;
  // The script's `subdiv` and `offset` (the control panel sets the same settings directly).
  void set_subdivision(double levels);
  void set_offset(double distance);
  // "add-polygon", "accept", "clear", "delete", "zip", "merge", "undo", "redo": from buttons, keys and
  // scripts. Returns false when the action was refused (the log says why).
  bool run_action(const std::string& action);
  void apply_face_colors();
  // script
  void run_script_step();
  bool run_command(const ScriptCommand& command);
  // geometry on screen
  void update_stage();
  void show_result(StageResult result);
  const Mesh* shown_mesh() const { return shown_ ? shown_->mesh.get() : nullptr; }
  // The BVH of the shown mesh, for picks: built off the UI thread once the geometry has rested for a
  // moment (a slider drag never starts one), or at a pick that comes sooner (waiting for a build in
  // flight rather than starting another).
  const TriangleBvh& picking_bvh();
  void prefetch_picking_bvh();
  void take_picking_bvh(std::chrono::milliseconds patience);
  void refresh_selection();
  // The scene's rim lines (`polyline`, `circle`): drawn over every stage, as they have no faces.
  void refresh_rim_lines();
  ScreenProjection projection() const;
  glm::dvec2 window_size() const;
  double aspect() const;
  void frame_all();
  void reset_view();
  void set_view(double azimuth, double elevation);
  // outputs
  void save_screenshot(const std::filesystem::path& path);
  void export_mesh(const std::filesystem::path& path);
  std::filesystem::path next_screenshot_path() const;
  // panels
  void draw_scene();
  void draw_panels();
  void draw_menu();
  void draw_control_panel();
  void draw_slider_panels();
  void save(const std::optional<std::filesystem::path>& path);
  // Saves the scene (throwing on failure); the recovery file of the file it came from goes.
  void save_session(const std::filesystem::path& target);
  void set_slider(Index parameter, double value);
  void draw_topology_panel();
  void draw_log_panel();
  void draw_status_bar();
  void draw_help_overlay();
  void draw_unsaved_prompt();
  // The unsaved-changes prompt's buttons (and the script's `prompt`).
  enum class UnsavedAnswer { save, discard, cancel };
  void answer_unsaved_prompt(UnsavedAnswer answer);
  // crash recovery (window_recovery.cpp)
  void update_autosave();
  void draw_recovery_prompt();
  void answer_recovery(bool restore);
  void draw_progress();
  void poll_file_changes();

  GLFWwindow* window_;
  ViewerOptions options_;
  std::optional<Session> session_;
  std::filesystem::file_time_type file_time_{};
  double last_file_check_ = 0.0;

  std::unique_ptr<render::Renderer> renderer_;
  std::unique_ptr<render::MeshBuffers> buffers_;
  std::unique_ptr<render::CubeSet> cubes_;
  std::unique_ptr<render::LineSet> border_lines_;
  std::unique_ptr<render::LineSet> rim_lines_;
  std::vector<Vec3> rim_points_;  // framed with the mesh
  glm::vec3 rim_color_{0.05f, 0.45f, 0.55f};
  render::Camera camera_;
  render::DisplaySettings display_;

  // The displayed stage: computed by jobs off the UI thread, shown when the latest one finishes.
  PipelineSettings settings_ = initial_settings();
  StagePipeline pipeline_;
  BackgroundJob<std::optional<StageResult>> job_;
  std::uint64_t requested_version_ = 0;
  PipelineSettings requested_settings_;
  bool has_request_ = false;
  std::optional<StageResult> shown_;
  double shown_time_ = 0.0;  // when shown_ came (glfwGetTime)
  struct PickingBvh {
    std::shared_ptr<const Mesh> mesh;  // what it was built over
    std::shared_ptr<const TriangleBvh> bvh;
  };
  BackgroundJob<PickingBvh> bvh_job_;
  std::shared_ptr<const TriangleBvh> picking_bvh_;  // of shown_, once built
  ZipperOptions zipper_options_;
  glm::vec3 consolidated_color_{0.62f, 0.42f, 0.86f};
  glm::vec3 temporary_color_{0.30f, 0.76f, 0.42f};

  Selection selection_;
  MessageLog log_;
  KeyRegistry keys_;
  RecentFiles recent_;
  Autosave autosave_;
  std::optional<std::filesystem::path> recovery_offer_;  // left by a viewer that did not end cleanly
  FileBrowser browser_;
  enum class BrowserPurpose { open, save, export_mesh } browser_purpose_ = BrowserPurpose::open;

  // Mouse: a press-release that moves less than click_pixels is a click, otherwise a drag.
  static constexpr double click_pixels = 4.0;
  int pressed_button_ = -1;
  glm::dvec2 press_position_{0.0}, last_position_{0.0};
  bool is_dragging_ = false;

  bool show_help_ = false;
  bool show_log_ = true;
  // Waiting for the answer about unsaved changes: then quit (no file) or open the file.
  struct UnsavedPrompt {
    std::optional<std::filesystem::path> open;
  };
  std::optional<UnsavedPrompt> unsaved_prompt_;
  bool should_close_ = false;
  std::optional<std::filesystem::path> pending_screenshot_;

  std::vector<ScriptCommand> script_;
  std::size_t script_next_ = 0;
  int frames_drawn_ = 0;
  int exit_status_ = 0;
};

}  // namespace nome::viewer
