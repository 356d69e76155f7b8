#include "app/viewer/imgui_text.hpp"

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

std::string imgui_text(const std::function<void()>& draw) {
  const OwnImGuiContext own;
  ImGui::NewFrame();
  ImGui::SetNextWindowSize(ImVec2(800, 2000));
  ImGui::Begin("panel");
  ImGui::LogToBuffer();
  draw();
  const std::string text = own.context()->LogBuffer.c_str();
  ImGui::LogFinish();
  ImGui::End();
  ImGui::EndFrame();
  return text;
}

}  // namespace nome::test
