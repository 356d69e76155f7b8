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

// The text one frame of `draw` puts on screen, as ImGui's log captures it, drawn inside a window of an
// OwnImGuiContext: what a user reads in a panel.
std::string imgui_text(const std::function<void()>& draw);

}  // namespace nome::test
