// The viewer as a web page: the desktop's Window over Emscripten's GLFW (a WebGL2 canvas), driven by the
// browser's frame callback. The page (web/page) passes the scene and a script as arguments, keeps the
// stores in the browser's storage and calls the exported functions below for files and script commands.
#include <emscripten.h>
#include <emscripten/html5.h>

#include <algorithm>
#include <cstring>
#include <iostream>
#include <memory>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "render/scene_renderer.hpp"
#include "viewer/session/session_controller.hpp"
#include "viewer/viewer.hpp"
#include "viewer/window.hpp"

namespace nome::web {
namespace {

// The element the canvas fills; the page sizes it to the browser window.
constexpr const char* stage_element = "#stage";

glm::ivec2 stage_size() {
  double width = 0.0, height = 0.0;
  emscripten_get_element_css_size(stage_element, &width, &height);
  return {std::max(64, int(width)), std::max(64, int(height))};
}

class BrowserPlatform final : public viewer::Platform {
 public:
  explicit BrowserPlatform(GLFWwindow* window) : window_(window) {}
  glm::dvec2 window_size() const override {
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    return {std::max(width, 1), std::max(height, 1)};
  }
  glm::ivec2 framebuffer_size() const override {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {std::max(width, 1), std::max(height, 1)};
  }
  double now() const override { return glfwGetTime(); }
  void set_title(const std::string& title) override { emscripten_set_window_title(title.c_str()); }
  float content_scale() const override { return 1.0f; }
  bool pick_file_to_open() override {
    EM_ASM(nomePage.pickFile());
    return true;
  }
  void offer_saved_file(const std::filesystem::path& path) override {
    EM_ASM({ nomePage.download(UTF8ToString($0)); }, path.c_str());
  }

 private:
  GLFWwindow* window_;
};

struct Page {
  GLFWwindow* glfw = nullptr;
  std::unique_ptr<BrowserPlatform> platform;
  std::unique_ptr<render::SceneRenderer> renderer;
  std::unique_ptr<viewer::Window> window;
  bool has_shown_model = false;
  bool was_running_script = false;
};

Page page;

void on_drop(GLFWwindow*, int count, const char** paths) {
  if (page.window) page.window->drop(std::vector<std::filesystem::path>(paths, paths + count));
}

void frame() {
  const glm::ivec2 size = stage_size();
  int width = 0, height = 0;
  glfwGetWindowSize(page.glfw, &width, &height);
  if (size != glm::ivec2(width, height)) glfwSetWindowSize(page.glfw, size.x, size.y);
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const bool is_running = page.window->frame(viewer::read_imgui_input());
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  page.window->after_draw();
  if (!page.has_shown_model && page.window->shown()) {
    page.has_shown_model = true;
    EM_ASM(nomePage.modelShown());
  }
  // The page (and its tests) learn when a script has run to its end.
  if (page.was_running_script && !page.window->is_running_script()) EM_ASM(nomePage.scriptDone());
  page.was_running_script = page.window->is_running_script();
  if (!is_running) {
    // A page cannot close itself: the quit ends the frames and tells the page.
    emscripten_cancel_main_loop();
    EM_ASM({ nomePage.finished($0); }, page.window->exit_status());
  }
}

viewer::ViewerOptions options_from(int argc, char** argv) {
  viewer::ViewerOptions options;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--script") == 0 && i + 1 < argc)
      options.script = argv[++i];
    else
      options.file = argv[i];
  }
  options.quits_on_bad_script = false;
  const glm::ivec2 size = stage_size();
  options.width = size.x;
  options.height = size.y;
  options.has_size = true;
  return options;
}

}  // namespace
}  // namespace nome::web

using nome::web::page;

extern "C" {

// A file the page wrote into the file system (picked or dropped): opens it as a drop on the window does.
EMSCRIPTEN_KEEPALIVE void nome_open(const char* path) {
  if (page.window) page.window->drop({std::filesystem::path(path)});
}

// The page is being hidden or left: the layout goes to the stores (the page then writes them to its storage).
EMSCRIPTEN_KEEPALIVE void nome_keep_layout() {
  if (page.window) page.window->keep_layout();
}

// Script commands, one a line, as `nome --script` takes them; the log echoes to the page's console.
EMSCRIPTEN_KEEPALIVE int nome_script(const char* text) {
  if (!page.window) return 0;
  try {
    page.window->run_script(text, "page script");
    // Reported done by the frame that runs its last command, even when that is the next one.
    page.was_running_script = true;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "nome: " << e.what() << "\n";
    return 0;
  }
}
}

int main(int argc, char** argv) {
  using namespace nome;
  const viewer::ViewerOptions options = web::options_from(argc, argv);
  if (!glfwInit()) {
    std::cerr << "nome: GLFW did not start in this page\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  page.glfw = glfwCreateWindow(options.width, options.height, "Nome", nullptr, nullptr);
  if (!page.glfw) {
    std::cerr << "nome: this browser gives no WebGL2 context\n";
    EM_ASM(nomePage.failed("This browser gives no WebGL2 context."));
    return 1;
  }
  glfwMakeContextCurrent(page.glfw);
  glfwSetDropCallback(page.glfw, web::on_drop);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(page.glfw, true);
  ImGui_ImplOpenGL3_Init("#version 300 es");
  page.platform = std::make_unique<web::BrowserPlatform>(page.glfw);
  page.renderer = render::make_gl_scene_renderer();
  page.window = std::make_unique<viewer::Window>(*page.platform, *page.renderer, options,
                                                 viewer::ViewerStores::from_environment());
  // The address's script is reported done even when it could not be read (the error is in the log).
  page.was_running_script = options.script.has_value();
  emscripten_set_main_loop(web::frame, 0, false);
  return 0;
}
