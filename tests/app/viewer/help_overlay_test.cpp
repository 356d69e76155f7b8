// The help overlay: every key of the action table on one table, in the middle of the window.
#include <catch2/catch.hpp>

#include <string>

#include <imgui.h>
#include <imgui_internal.h>

#include "app/viewer/imgui_text.hpp"
#include "viewer/commands/actions.hpp"
#include "viewer/panels/panels.hpp"

using namespace nome::viewer;

TEST_CASE("the help overlay lists the keys in the middle of the window", "[app]") {
  const ActionRegistry actions;
  bool is_shown = true;
  const nome::test::OwnImGuiContext context;
  std::string text;
  for (int frame = 0; frame < 3; ++frame)
    text = nome::test::imgui_frame(context, [&] { draw_help_overlay(actions, is_shown); });
  INFO(text);
  CHECK(text.find("left drag | turn (arcball)") != std::string::npos);
  CHECK(text.find("W | wire mode / polygon mode") != std::string::npos);
  const ImGuiWindow* overlay = ImGui::FindWindowByName("Keys and mouse (? or F1 closes)");
  REQUIRE(overlay);
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  CHECK(overlay->Pos.x + overlay->Size.x * 0.5f == Approx(display.x * 0.5f).margin(1.0));
  CHECK(overlay->Pos.y + overlay->Size.y * 0.5f == Approx(display.y * 0.5f).margin(1.0));
  CHECK(overlay->Size.x > 200.0f);
  CHECK(overlay->Size.x < display.x);
}
