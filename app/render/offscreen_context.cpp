#include "render/offscreen_context.hpp"

#include "render/gl.hpp"

#define EGL_NO_X11
#define MESA_EGL_NO_X11_HEADERS
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>
#include <dlfcn.h>
#include <link.h>

#include <string_view>
#include <vector>

#include "nome/error.hpp"

namespace nome::render {
namespace {

// eglTerminate() unloads Mesa's *_dri.so; LeakSanitizer then reports that driver's allocations with
// `<unknown module>` frames it cannot suppress. Pinning the loaded drivers keeps them symbolizable.
int pin_driver(dl_phdr_info* info, size_t, void*) {
  const std::string_view name = info->dlpi_name ? info->dlpi_name : "";
  if (name.ends_with("_dri.so")) dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
  return 0;
}

const EGLint egl_config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                        EGL_OPENGL_BIT, EGL_NONE};
const EGLint egl_context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         3,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};

std::string egl_error(const char* call) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", unsigned(eglGetError()));
  return std::string(call) + " failed (EGL error " + code + ")";
}

}  // namespace

Backend parse_backend(const std::string& name) {
  if (name == "egl") return Backend::egl;
  if (name == "egl-device") return Backend::egl_device;
  if (name == "osmesa") return Backend::osmesa;
  throw InvalidInputError("unknown backend '" + name + "' (expected egl, egl-device or osmesa)");
}

struct OffscreenContext::State {
  std::string platform;
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext egl_context = EGL_NO_CONTEXT;
  OSMesaContext osmesa_context = nullptr;
  // OSMesa needs a colour buffer to make a context current; drawing goes to framebuffer objects.
  std::vector<unsigned char> osmesa_buffer;

  ~State() {
    if (display != EGL_NO_DISPLAY) {
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      if (egl_context != EGL_NO_CONTEXT) eglDestroyContext(display, egl_context);
      eglTerminate(display);
    }
    if (osmesa_context) OSMesaDestroyContext(osmesa_context);
  }

  // Takes an EGL display that is not initialized yet; on failure leaves nothing behind.
  bool start_egl(EGLDisplay candidate, std::string& failure) {
    if (candidate == EGL_NO_DISPLAY) return failure = "no display", false;
    if (!eglInitialize(candidate, nullptr, nullptr)) return failure = egl_error("eglInitialize"), false;
    display = candidate;
    EGLConfig config;
    EGLint count = 0;
    if (!eglBindAPI(EGL_OPENGL_API)) return failure = egl_error("eglBindAPI"), stop_egl();
    if (!eglChooseConfig(display, egl_config_attributes, &config, 1, &count) || count == 0)
      return failure = "no OpenGL config", stop_egl();
    egl_context = eglCreateContext(display, config, EGL_NO_CONTEXT, egl_context_attributes);
    if (egl_context == EGL_NO_CONTEXT) return failure = egl_error("eglCreateContext (3.3 core)"), stop_egl();
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_context))
      return failure = egl_error("eglMakeCurrent without a surface"), stop_egl();
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)))
      return failure = "the GL loader found no OpenGL 3.3", stop_egl();
    return true;
  }

  bool stop_egl() {
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (egl_context != EGL_NO_CONTEXT) eglDestroyContext(display, egl_context);
    eglTerminate(display);
    egl_context = EGL_NO_CONTEXT;
    display = EGL_NO_DISPLAY;
    return false;
  }

  bool start_egl_surfaceless(std::string& failure) {
    auto get_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) return failure = "no eglGetPlatformDisplayEXT", false;
    return start_egl(get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), failure);
  }

  bool start_egl_device(std::string& failure) {
    auto get_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (!get_display || !query_devices) return failure = "no EGL device extension", false;
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (!query_devices(8, devices, &count) || count == 0) return failure = "no EGL device", false;
    for (EGLint i = 0; i < count; ++i)
      if (start_egl(get_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr), failure)) return true;
    return false;
  }

  bool start_osmesa(std::string& failure) {
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    osmesa_context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!osmesa_context) return failure = "OSMesaCreateContextAttribs (3.3 core) failed", false;
    osmesa_buffer.assign(4, 0);
    if (!OSMesaMakeCurrent(osmesa_context, osmesa_buffer.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      OSMesaDestroyContext(osmesa_context);
      osmesa_context = nullptr;
      return failure = "OSMesaMakeCurrent failed", false;
    }
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress))) {
      OSMesaDestroyContext(osmesa_context);
      osmesa_context = nullptr;
      return failure = "the GL loader found no OpenGL 3.3", false;
    }
    return true;
  }
};

OffscreenContext::OffscreenContext(Backend backend) : state_(std::make_unique<State>()) {
  struct Attempt {
    const char* platform;
    bool (State::*start)(std::string&);
    Backend backend;
    bool forced_only = false;  // tried only when asked for by name
  };
  const Attempt attempts[] = {{"EGL surfaceless", &State::start_egl_surfaceless, Backend::egl},
                              {"EGL device", &State::start_egl_device, Backend::egl},
                              {"EGL device", &State::start_egl_device, Backend::egl_device, true},
                              {"OSMesa", &State::start_osmesa, Backend::osmesa}};
  std::string failures;
  for (const Attempt& attempt : attempts) {
    if (backend == Backend::automatic ? attempt.forced_only : backend != attempt.backend) continue;
    std::string failure;
    if ((state_.get()->*attempt.start)(failure)) {
      state_->platform = attempt.platform;
      dl_iterate_phdr(pin_driver, nullptr);
      return;
    }
    failures += std::string(failures.empty() ? "" : "; ") + attempt.platform + ": " + failure;
  }
  throw Error("no offscreen OpenGL 3.3 core context: " + failures);
}

OffscreenContext::~OffscreenContext() = default;

const std::string& OffscreenContext::platform() const {
  return state_->platform;
}

std::string OffscreenContext::description() const {
  auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return text(GL_VENDOR) + ", " + text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

}  // namespace nome::render
