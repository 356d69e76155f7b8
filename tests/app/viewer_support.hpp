#pragma once

#include "render/image.hpp"

#include <memory>
#include <optional>
#include <span>
#include <string>

#include <glm/vec2.hpp>

#include "app/cli_support.hpp"
#include "app/screen_oracle.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/query/screen_projection.hpp"
#include "render/framebuffer.hpp"
#include "render/offscreen_context.hpp"
#include "render/scene_renderer.hpp"
#include "viewer/platform.hpp"
#include "viewer/session/session_controller.hpp"
#include "viewer/viewer.hpp"

struct ImGuiContext;

namespace nome::viewer {
class Window;
}

namespace nome::test {

// The viewer's window in the scripted sessions: Xvfb's screen holds it whole, and the in-process
// window has its size.
constexpr int viewer_width = 1280;
constexpr int viewer_height = 800;

// Runs `nome ARGUMENTS` on a fresh virtual display (xvfb-run), as a user's session would run.
CommandResult run_viewer(const std::string& arguments);

// The viewer names the vertices of a flat file as its lines do: v1, v2, ...
std::string obj_vertex(Index v);

// A script line that clicks the window at p.
std::string click_line(glm::dvec2 p);

// Writes a viewer script into `dir` and returns its path.
std::string write_script(const std::string& dir, const std::string& text);
// A scene of twelve funnels in a ring, each with a bank of its own (b0 .. b11, four sliders each): a
// parameter panel longer than the window.
void write_twelve_banks(const std::string& path);
// How many pixels of the picture are close to the colour (each channel within the tolerance).
int count_pixels(const render::Image& image, int r, int g, int b, int tolerance);

// A fixed-size window whose clock moves a sixtieth of a second a frame.
class TestPlatform final : public viewer::Platform {
 public:
  explicit TestPlatform(glm::ivec2 size) : size_(size) {}
  glm::dvec2 window_size() const override { return glm::dvec2(size_); }
  glm::ivec2 framebuffer_size() const override { return size_; }
  double now() const override { return time_; }
  void set_title(const std::string& title) override { title_ = title; }
  float content_scale() const override { return scale_; }
  void advance() { time_ += 1.0 / 60.0; }
  void set_content_scale(float scale) { scale_ = scale; }
  const std::string& title() const { return title_; }

 private:
  glm::ivec2 size_;
  double time_ = 1.0;
  float scale_ = 1.0f;
  std::string title_;
};

// null: draws nothing (logic only); gl: the GL backend into a headless (EGL, else OSMesa) framebuffer,
// the scene without the panels (ImGui has no renderer backend here).
enum class TestRenderer { null, gl };

// A viewer window in this process: ImGui without a platform backend, a test clock and state folders of
// its own (no recovery file or recent list of the user's is read or written).
class TestViewer {
 public:
  explicit TestViewer(const viewer::ViewerOptions& options,
                      const viewer::ViewerStores& stores = private_stores(),
                      TestRenderer renderer = TestRenderer::null);
  ~TestViewer();
  TestViewer(const TestViewer&) = delete;
  TestViewer& operator=(const TestViewer&) = delete;

  static viewer::ViewerStores private_stores();

  viewer::Window& window() { return *window_; }
  TestPlatform& platform() { return platform_; }
  // One frame with this input; false once the window closes.
  bool frame(const viewer::InputFrame& input = {});
  // Frames until the window closes (a script's `quit`) or a frame limit; the exit status.
  int run();
  // The log as a scripted session prints it on stderr.
  std::string messages() const;

 private:
  ImGuiContext* context_;
  std::unique_ptr<render::OffscreenContext> gl_context_;
  std::unique_ptr<render::Framebuffer> framebuffer_;
  TestPlatform platform_;
  std::unique_ptr<render::SceneRenderer> renderer_;
  std::unique_ptr<viewer::Window> window_;
};

// `nome ARGUMENTS` (FILE, .anom files, --script S.txt, --size WxH) in this process: the status and the
// log as err.
CommandResult run_window(const std::string& arguments,
                         const viewer::ViewerStores& stores = TestViewer::private_stores(),
                         TestRenderer renderer = TestRenderer::null);

// The camera of the viewer after the script command `view AZ EL` (framed to the mesh in the viewport of
// a scripted session's window, between its panels).
ScreenProjection viewer_projection(const Mesh& mesh, double azimuth, double elevation);
// The same framed to any points (a scene with rim lines frames them with its mesh).
ScreenProjection viewer_projection(std::span<const Vec3> points, double azimuth, double elevation);

// One `state: ...` line of a scripted session's log (the script command `state`): what the viewer shows.
struct ViewerState {
  std::string stage;
  long long vertices = 0, edges = 0, faces = 0, chi = 0;
  bool orientable = false;
  long long borders = 0, mobius_edges = 0, parts = 0;
  long long selected_vertices = 0, selected_faces = 0, selected_borders = 0, selected_instances = 0;
  long long scene_faces = 0, consolidated_faces = 0, temporary_faces = 0;
};
// Every state line of the log, in order.
std::vector<ViewerState> logged_states(const std::string& log);

}  // namespace nome::test
