#include "app/viewer_support.hpp"

#include <fstream>
#include <regex>
#include <sstream>

#include <imgui.h>
#include <glm/geometric.hpp>

#include "nome/io/read_scene.hpp"
#include "render/camera.hpp"
#include "viewer/window.hpp"

namespace nome::test {

CommandResult run_viewer(const std::string& arguments) {
  // A state folder of its own: a recovery file a crashed viewer left in the user's would be offered.
  const std::string state = private_scratch_dir("viewer_state");
  // An authority file of its own: without one xvfb-run makes a temporary folder and, when removing it
  // fails, exits 5 in place of the viewer's status.
  static int sessions = 0;
  const std::string auth = private_scratch_dir("xvfb") + "/auth-" + std::to_string(sessions++);
  return run_nome_prefixed(
      "env XDG_STATE_HOME=" + state + " xvfb-run -a -f " + auth + " -s \"-screen 0 1280x800x24\"", arguments);
}

namespace {

// The GL backend drawing into a multisampled framebuffer, whose pixels are read by resolving it.
class FramebufferRenderer final : public render::SceneRenderer {
 public:
  explicit FramebufferRenderer(const render::Framebuffer& framebuffer)
      : gl_(render::make_gl_scene_renderer()), framebuffer_(framebuffer) {}
  void set_mesh(const render::MeshDisplayData& data) override { gl_->set_mesh(data); }
  void set_face_colors(std::span<const std::array<std::uint8_t, 4>> colors) override {
    gl_->set_face_colors(colors);
  }
  void set_selected_faces(std::span<const Index> faces) override { gl_->set_selected_faces(faces); }
  void set_markers(std::span<const render::CubeMarker> markers) override { gl_->set_markers(markers); }
  void set_lines(render::Overlay overlay, std::span<const glm::vec3> points,
                 std::span<const std::uint32_t> segments, std::span<const glm::vec4> colors) override {
    gl_->set_lines(overlay, points, segments, colors);
  }
  void draw(const render::Camera& camera, glm::ivec2 size, const render::PixelRect& viewport,
            const render::DisplaySettings& display) override {
    gl_->draw(camera, size, viewport, display);
  }
  render::Image read_pixels(glm::ivec2) const override { return framebuffer_.read(false); }

 private:
  std::unique_ptr<render::SceneRenderer> gl_;
  const render::Framebuffer& framebuffer_;
};

}  // namespace

TestViewer::TestViewer(const viewer::ViewerOptions& options, const viewer::ViewerStores& stores,
                       TestRenderer renderer)
    : context_(ImGui::CreateContext()), platform_({options.width, options.height}) {
  if (renderer == TestRenderer::gl) {
    gl_context_ = std::make_unique<render::OffscreenContext>();
    framebuffer_ = std::make_unique<render::Framebuffer>(options.width, options.height);
    framebuffer_->bind();
    renderer_ = std::make_unique<FramebufferRenderer>(*framebuffer_);
  } else {
    renderer_ = render::make_null_scene_renderer();
  }
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = ImVec2(float(options.width), float(options.height));
  io.DeltaTime = 1.0f / 60.0f;
  // A font atlas is all ImGui needs to lay out panels; no texture is ever drawn.
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  io.Fonts->SetTexID(ImTextureID(1));
  window_ = std::make_unique<viewer::Window>(platform_, *renderer_, options, stores);
}

TestViewer::~TestViewer() {
  window_.reset();
  renderer_.reset();
  framebuffer_.reset();
  ImGui::DestroyContext(context_);
}

viewer::ViewerStores TestViewer::private_stores() {
  const std::string state = private_scratch_dir("viewer_state");
  return {state + "/recent", state + "/recovery", state + "/layout"};
}

bool TestViewer::frame(const viewer::InputFrame& input) {
  ImGui::NewFrame();
  const bool is_open = window_->frame(input);
  window_->after_draw();
  platform_.advance();
  return is_open;
}

int TestViewer::run() {
  for (int i = 0; i < 100000 && frame();) ++i;
  return window_->exit_status();
}

std::string TestViewer::messages() const {
  std::string text;
  for (const viewer::Message& m : window_->log().messages()) {
    const char* prefix = m.level == viewer::MessageLevel::error     ? "error: "
                         : m.level == viewer::MessageLevel::warning ? "warning: "
                                                                    : "";
    text += std::string("nome: ") + prefix + m.text + "\n";
  }
  return text;
}

CommandResult run_window(const std::string& arguments, const viewer::ViewerStores& stores,
                         TestRenderer renderer) {
  viewer::ViewerOptions options;
  std::istringstream words(arguments);
  char x = 0;
  for (std::string word; words >> word;) {
    if (word == "--script" && words >> word)
      options.script = word;
    else if (word == "--size" && words >> options.width >> x >> options.height)
      continue;
    else if (is_anom_file(word) && options.file)
      options.anom_files.emplace_back(word);
    else
      options.file = word;
  }
  TestViewer viewer(options, stores, renderer);
  CommandResult result;
  result.status = viewer.run();
  result.err = viewer.messages();
  return result;
}

ScreenProjection viewer_projection(const Mesh& mesh, double azimuth, double elevation) {
  return viewer_projection(std::span(mesh.positions().data(), mesh.positions().size()), azimuth, elevation);
}

ScreenProjection viewer_projection(std::span<const Vec3> points, double azimuth, double elevation) {
  // The viewport of a window with no file, as a scripted session lays it out (the same every time).
  static const viewer::ScreenRect viewport = [] {
    ImGuiContext* const current = ImGui::GetCurrentContext();
    viewer::ViewerOptions options;
    options.script = write_script(private_scratch_dir("viewer_projection"), "");
    viewer::ScreenRect rect;
    {
      TestViewer viewer(options);
      viewer.frame();
      rect = viewer.window().layout().viewport;
    }
    ImGui::SetCurrentContext(current);
    return rect;
  }();
  render::Camera camera;
  camera.set_view(azimuth, elevation);
  camera.fit(points, viewport.size.x / viewport.size.y);
  return camera.screen_projection(viewport.size, viewport.origin);
}

std::string obj_vertex(Index v) {
  return "v" + std::to_string(v + 1);
}

std::string click_line(glm::dvec2 p) {
  return "click " + std::to_string(int(p.x)) + " " + std::to_string(int(p.y)) + "\n";
}

std::string write_script(const std::string& dir, const std::string& text) {
  const std::string path = dir + "/script.txt";
  std::ofstream(path) << text;
  return path;
}

void write_twelve_banks(const std::string& path) {
  std::ofstream out(path);
  for (int i = 0; i < 12; ++i)
    out << "bank b" << i << "\n  set n 6 3 10 1\n  set ro 0.4 0.1 1.0 0.1\n  set ratio 0.2 -0.5 0.5 0.1\n"
        << "  set h 0.3 0.1 1.5 0.1\nendbank\n"
        << "funnel f" << i << " ({expr $b" << i << "_n} {expr $b" << i << "_ro} {expr $b" << i
        << "_ratio} {expr $b" << i << "_h}) endfunnel\n";
  for (int i = 0; i < 12; ++i)
    out << "instance i" << i << " f" << i << " translate (3 0 0) rotate (0 1 0) (" << 30 * i
        << ") endinstance\n";
}

int count_pixels(const render::Image& image, int r, int g, int b, int tolerance) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      n += std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
           std::abs(p[2] - b) <= tolerance;
    }
  return n;
}

std::vector<ViewerState> logged_states(const std::string& log) {
  static const std::regex line(
      "state: (.+) stage: V (\\d+), E (\\d+), F (\\d+), chi (-?\\d+), (orientable|non-orientable), (\\d+) "
      "borders, (\\d+) Möbius edges, (\\d+) parts \\| selection: (\\d+) vertices, (\\d+) faces, (\\d+) "
      "borders, (\\d+) instances \\| faces: (\\d+) scene, (\\d+) consolidated, (\\d+) temporary");
  std::vector<ViewerState> out;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), line); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    auto number = [&](int i) { return std::stoll(m[i].str()); };
    out.push_back({m[1].str(), number(2), number(3), number(4), number(5), m[6].str() == "orientable",
                   number(7), number(8), number(9), number(10), number(11), number(12), number(13),
                   number(14), number(15), number(16)});
  }
  return out;
}

}  // namespace nome::test
