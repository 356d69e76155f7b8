// The parameter panel's text as ImGui draws it (captured with ImGui's own log), on a context of the
// test's own: what a sculptor reads beside each slider.
#include <catch2/catch.hpp>

#include <string>

#include <imgui.h>
#include <imgui_internal.h>

#include "app/cli_support.hpp"
#include "app/viewer_support.hpp"
#include "viewer/panels/parameter_panel.hpp"
#include "viewer/session/session.hpp"

using namespace nome;

namespace {

// The text of one frame of the parameter panel; the context is the test's own and goes with it.
std::string panel_text(const scene::Scene& scene, viewer::ParameterPanelState& state) {
  ImGuiContext* previous = ImGui::GetCurrentContext();
  ImGuiContext* context = ImGui::CreateContext();
  ImGui::SetCurrentContext(context);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(600, 2000);
  io.DeltaTime = 1.0f / 60.0f;
  io.IniFilename = nullptr;
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  ImGui::NewFrame();
  ImGui::SetNextWindowSize(ImVec2(600, 2000));
  ImGui::Begin("Parameters");
  ImGui::LogToBuffer();
  viewer::LayoutReport report;
  viewer::draw_parameter_section(scene, {}, state, report);
  const std::string text = context->LogBuffer.c_str();
  ImGui::LogFinish();
  ImGui::End();
  ImGui::EndFrame();
  ImGui::DestroyContext(context);
  ImGui::SetCurrentContext(previous);
  return text;
}

}  // namespace

TEST_CASE("a slider moved from the file's value is marked with a star until it is back", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("parameter_panel_text");
  nome::test::write_twelve_banks(dir + "/twelve.nome");
  viewer::Session session = viewer::Session::open(dir + "/twelve.nome");
  viewer::ParameterPanelState state;
  const std::string before = panel_text(*session.scene(), state);
  CHECK(before.find('*') == std::string::npos);
  const scene::ParameterId ro = *session.scene()->find_parameter("b2_ro");
  const double file_value = session.scene()->parameters()[ro].value;
  session.set_parameter(ro, file_value == 0.5 ? 0.6 : 0.5);
  const std::string moved = panel_text(*session.scene(), state);
  INFO(moved);
  CHECK(moved.find("* ") != std::string::npos);
  session.set_parameter(ro, file_value);
  CHECK(panel_text(*session.scene(), state).find('*') == std::string::npos);
}
