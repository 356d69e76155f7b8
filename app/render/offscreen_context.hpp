#pragma once

#include <memory>
#include <string>

namespace nome::render {

// egl: surfaceless, else a device; egl_device: only the device platform (the fallback, forced to test it).
enum class Backend { automatic, egl, egl_device, osmesa };

// "egl", "egl-device" or "osmesa"; throws InvalidInputError otherwise.
Backend parse_backend(const std::string& name);

// A current OpenGL 3.3 core context with no window, no display and no GPU needed, with glad loaded.
// Tries EGL on Mesa's surfaceless platform, then an EGL device, then OSMesa (or only the forced one);
// draw into a Framebuffer. One per process at a time.
class OffscreenContext {
 public:
  explicit OffscreenContext(Backend backend = Backend::automatic);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  // "EGL surfaceless", "EGL device" or "OSMesa".
  const std::string& platform() const;
  // GL_VENDOR, GL_RENDERER and GL_VERSION of the context.
  std::string description() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace nome::render
