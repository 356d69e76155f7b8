#include "app/viewer/imgui_text.hpp"

#include <cstdio>
#include <cstdlib>

#include <imgui.h>
#include <imgui_internal.h>

namespace nome::test {

OwnImGuiContext::OwnImGuiContext() : previous_(ImGui::GetCurrentContext()), context_(ImGui::CreateContext()) {
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(800, 2000);
  io.DeltaTime = 1.0f / 60.0f;
  io.IniFilename = nullptr;
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
}

OwnImGuiContext::~OwnImGuiContext() {
  ImGui::DestroyContext(context_);
  ImGui::SetCurrentContext(previous_);
}

std::string imgui_frame(const OwnImGuiContext& context, const std::function<void()>& draw) {
  ImGui::NewFrame();
  ImGui::SetNextWindowSize(ImVec2(800, 2000));
  ImGui::Begin("panel");
  // ImGui ends (and clears) a buffer log at the End() of any window that is not a child, so a panel that
  // opens a window of its own is logged to a stream, which the end of its window closes and keeps.
  char* logged = nullptr;
  std::size_t size = 0;
  ImGui::LogBegin(ImGuiLogType_File, -1);
  context.context()->LogFile = open_memstream(&logged, &size);
  draw();
  ImGui::LogFinish();
  ImGui::End();
  ImGui::EndFrame();
  std::string text(logged, size);
  std::free(logged);
  return text;
}

std::string imgui_text(const std::function<void()>& draw, int frames) {
  const OwnImGuiContext own;
  std::string text;
  for (int f = 0; f < frames; ++f) text = imgui_frame(own, draw);
  return text;
}

}  // namespace nome::test
