#include "viewer/viewer.hpp"

#include <dlfcn.h>
#include <link.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string_view>

#include "render/gl.hpp"

#define GLFW_INCLUDE_NONE  // GL comes from glad (render/gl.hpp)
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "render/scene_renderer.hpp"
#include "viewer/layout.hpp"
#include "viewer/window.hpp"

namespace nome::viewer {
namespace {

class GlfwPlatform final : public Platform {
 public:
  explicit GlfwPlatform(GLFWwindow* window) : window_(window) {}
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
  void set_title(const std::string& title) override { glfwSetWindowTitle(window_, title.c_str()); }
  float content_scale() const override {
    float x = 1.0f, y = 1.0f;
    glfwGetWindowContentScale(window_, &x, &y);
    return std::clamp(std::max(x, y), 0.5f, 4.0f);
  }

 private:
  GLFWwindow* window_;
};

Window* drop_target = nullptr;

void on_drop(GLFWwindow*, int count, const char** paths) {
  if (drop_target) drop_target->drop(std::vector<std::filesystem::path>(paths, paths + count));
}

// glfwTerminate() unloads Mesa's *_dri.so; the sanitizer's leak check then cannot name the driver's
// frames and reports its caches as leaks. Keeping the driver loaded to the end avoids that.
int keep_driver_loaded(dl_phdr_info* info, size_t, void*) {
  const std::string_view name = info->dlpi_name ? info->dlpi_name : "";
  if (name.ends_with("_dri.so")) dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
  return 0;
}

void on_glfw_error(int code, const char* description) {
  std::cerr << "nome: GLFW error " << code << ": " << description << "\n";
}

// A GL 3.3 core window with glad loaded, or none (the reason printed; GLFW is terminated then).
GLFWwindow* open_window(const ViewerOptions& options) {
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) {
    std::cerr << "nome: cannot start GLFW on this display; try `nome render FILE -o picture.png`\n";
    return nullptr;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 4);
  glm::ivec2 size(options.width, options.height);
  // The size the last run ended with, unless asked for one or scripted (a script's pixels repeat).
  if (!options.has_size && !options.script) size = read_layout(default_layout_file()).window_size;
  GLFWwindow* window = glfwCreateWindow(size.x, size.y, "Nome", nullptr, nullptr);
  if (!window) {
    std::cerr << "nome: cannot open a GL 3.3 core window; try `nome render FILE -o picture.png`\n";
    glfwTerminate();
    return nullptr;
  }
  glfwMakeContextCurrent(window);
  dl_iterate_phdr(keep_driver_loaded, nullptr);
  glfwSwapInterval(1);
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress))) {
    std::cerr << "nome: cannot load OpenGL 3.3 core functions\n";
    glfwDestroyWindow(window);
    glfwTerminate();
    return nullptr;
  }
  return window;
}

void start_imgui(GLFWwindow* window) {
  // Our callbacks go in before ImGui's so that ImGui chains them.
  glfwSetDropCallback(window, on_drop);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the user's folder: the layout file keeps ours
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330");
}

// The frame loop: continuous while something moves, else asleep until an event.
int run_frames(GLFWwindow* window, const ViewerOptions& options) {
  GlfwPlatform platform(window);
  const std::unique_ptr<render::SceneRenderer> renderer = render::make_gl_scene_renderer();
  Window viewer(platform, *renderer, options, ViewerStores::from_environment());
  drop_target = &viewer;
  bool is_running = true;
  int frames_to_draw = 0;  // ImGui settles its layout over a frame or two after an input
  while (is_running) {
    if (viewer.is_animating() || frames_to_draw > 0) {
      glfwPollEvents();
      frames_to_draw = std::max(0, frames_to_draw - 1);
    } else {
      glfwWaitEventsTimeout(0.5);
      frames_to_draw = 2;
    }
    if (glfwWindowShouldClose(window)) {
      glfwSetWindowShouldClose(window, GLFW_FALSE);
      viewer.request_quit();
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    is_running = viewer.frame(read_imgui_input());
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    viewer.after_draw();
    glfwSwapBuffers(window);
  }
  drop_target = nullptr;
  return viewer.exit_status();
}

}  // namespace

int run_viewer(const ViewerOptions& options) {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland)) {
    std::cerr << "nome: no display to open the viewer on (DISPLAY is not set).\n"
                 "  To draw a picture without a display: nome render FILE -o picture.png\n"
                 "  To run the viewer on a virtual display: xvfb-run -a nome FILE\n";
    return 1;
  }
  GLFWwindow* window = open_window(options);
  if (!window) return 1;
  start_imgui(window);
  const int status = run_frames(window, options);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}

}  // namespace nome::viewer
