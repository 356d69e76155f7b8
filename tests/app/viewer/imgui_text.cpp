#include "app/viewer/imgui_text.hpp"

#include <imgui.h>
#include <imgui_internal.h>

namespace nome::test {

std::string imgui_text(const std::function<void()>& draw) {
  ImGuiContext* previous = ImGui::GetCurrentContext();
  ImGuiContext* context = ImGui::CreateContext();
  ImGui::SetCurrentContext(context);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(800, 2000);
  io.DeltaTime = 1.0f / 60.0f;
  io.IniFilename = nullptr;
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  ImGui::NewFrame();
  ImGui::SetNextWindowSize(ImVec2(800, 2000));
  ImGui::Begin("panel");
  ImGui::LogToBuffer();
  draw();
  const std::string text = context->LogBuffer.c_str();
  ImGui::LogFinish();
  ImGui::End();
  ImGui::EndFrame();
  ImGui::DestroyContext(context);
  ImGui::SetCurrentContext(previous);
  return text;
}

}  // namespace nome::test
