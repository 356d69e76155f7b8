#pragma once

#include <functional>
#include <string>

struct ImGuiContext;

namespace nome::test {

// An ImGui context of a test's own (no display, no renderer: fonts built, an 800 x 2000 screen), current
// while it lives; the context before it is made current again at the end.
class OwnImGuiContext {
 public:
  OwnImGuiContext();
  ~OwnImGuiContext();
  OwnImGuiContext(const OwnImGuiContext&) = delete;
  OwnImGuiContext& operator=(const OwnImGuiContext&) = delete;

  ImGuiContext* context() const { return context_; }

 private:
  ImGuiContext* previous_;
  ImGuiContext* context_;
};

// One frame of `context` (current) with `draw` called inside a window: the text it put on screen, as
// ImGui's log captures it, up to the end of the first window of its own that `draw` opens. ImGui draws
// every item while it logs, those scrolled out of view too: where a panel is scrolled is read from the
// window (imgui_internal.h), not from this text.
std::string imgui_frame(const OwnImGuiContext& context, const std::function<void()>& draw);

// The text the last of `frames` frames of `draw` puts on screen, in an OwnImGuiContext of its own: what a
// user reads in a panel (more frames: once scrolling and auto-sizing have settled).
std::string imgui_text(const std::function<void()>& draw, int frames = 1);

}  // namespace nome::test
