// The log panel as a user reads it: it follows the newest message, and a scroll shows the older ones.
#include <catch2/catch.hpp>

#include <string>

#include <imgui.h>
#include <imgui_internal.h>

#include "app/viewer/imgui_text.hpp"
#include "viewer/panels/panels.hpp"

using namespace nome::viewer;

namespace {

const ScreenRect log_rect{{0.0, 0.0}, {400.0, 160.0}};

// The message list's window of the log panel.
const ImGuiWindow* message_list() {
  const ImGuiWindow* panel = ImGui::FindWindowByName("Log");
  return panel && !panel->DC.ChildWindows.empty() ? panel->DC.ChildWindows[0] : nullptr;
}

}  // namespace

TEST_CASE("the log panel follows its newest message, and scrolling up shows the first", "[app]") {
  MessageLog log;
  log.info("the first message");
  for (int i = 0; i < 60; ++i) log.info("message " + std::to_string(i));
  log.warning("the newest message");
  bool is_open = true;
  const nome::test::OwnImGuiContext context;
  std::string text;
  for (int frame = 0; frame < 4; ++frame)
    text = nome::test::imgui_frame(context, [&] { draw_log_panel(log, log_rect, is_open, 0.0); });
  INFO(text);
  CHECK(text.find("Log (62)") != std::string::npos);
  CHECK(text.find("warning: the newest message") != std::string::npos);
  const ImGuiWindow* list = message_list();
  REQUIRE(list);
  CHECK(list->ScrollMax.y > 500.0f);
  CHECK(list->Scroll.y == list->ScrollMax.y);
  // Scrolled up by 100 pixels, then held: it stays there and no longer follows.
  nome::test::imgui_frame(context, [&] { draw_log_panel(log, log_rect, is_open, -100.0); });
  for (int frame = 0; frame < 3; ++frame)
    nome::test::imgui_frame(context, [&] { draw_log_panel(log, log_rect, is_open, 0.0); });
  CHECK(list->Scroll.y == Approx(list->ScrollMax.y - 100.0f));
  // Past the top: the first message.
  for (int frame = 0; frame < 2; ++frame)
    nome::test::imgui_frame(context, [&] { draw_log_panel(log, log_rect, is_open, -1e6); });
  CHECK(list->Scroll.y == 0.0f);
}

TEST_CASE("a closed log panel shows its count and no message; a repeated warning is one line", "[app]") {
  MessageLog log;
  log.warning("something is odd");
  log.warning("something is odd");
  bool is_open = false;
  const std::string text = nome::test::imgui_text([&] { draw_log_panel(log, log_rect, is_open, 0.0); }, 2);
  INFO(text);
  CHECK(text.find("Log (1)") != std::string::npos);
  CHECK(text.find("something is odd") == std::string::npos);
  is_open = true;
  const std::string opened = nome::test::imgui_text([&] { draw_log_panel(log, log_rect, is_open, 0.0); }, 2);
  CHECK(opened.find("warning: something is odd (x2)") != std::string::npos);
}
