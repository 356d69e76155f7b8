#include <catch2/catch.hpp>

#include <memory>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>  // a window's header state, to open a collapsed section as a click would

#include "app/viewer_support.hpp"
#include "viewer/tools/tool.hpp"
#include "viewer/window.hpp"

using namespace nome;

namespace {

// A tool written against the public interface alone, as a new tool file would be: a section, a key and
// script command of its own, an overlay.
class CounterTool final : public viewer::Tool {
 public:
  explicit CounterTool(bool is_open) : is_open_(is_open) {}
  std::string title() const override { return is_open_ ? "Counter" : "Closed counter"; }
  bool is_section_open() const override { return is_open_; }
  void bind(viewer::ToolContext& context) override {
    if (!is_open_) return;
    context.actions.add({"count", GLFW_KEY_J, viewer::KeyModifier::none, "count one"}, [this] {
      ++count;
      return true;
    });
  }
  void draw_section(viewer::ToolContext&) override {
    ImGui::Text("count %d", count);
    ++sections_drawn;
  }
  void draw_overlay(viewer::ToolContext&) override { ++overlays_drawn; }

  int count = 0;
  int sections_drawn = 0;
  int overlays_drawn = 0;

 private:
  bool is_open_;
};

}  // namespace

TEST_CASE("a tool added through the tool interface alone gets its section, key, script command, overlay",
          "[app]") {
  const std::string dir = test::private_scratch_dir("tool_plugin");
  viewer::ViewerOptions options;
  options.file = std::string(NOME_SOURCE_DIR) + "/assets/mobius_band.nome";
  options.script = test::write_script(dir, "tool count\ntool count\nquit\n");
  test::TestViewer viewer(options);
  auto counter = std::make_unique<CounterTool>(true);
  auto closed = std::make_unique<CounterTool>(false);
  CounterTool& tool = *counter;
  CounterTool& closed_tool = *closed;
  viewer.window().add_tool(std::move(counter));
  viewer.window().add_tool(std::move(closed));
  viewer::InputFrame press;
  press.keys.push_back({GLFW_KEY_J, viewer::KeyModifier::none});
  viewer.frame(press);
  CHECK(tool.count == 1);
  CHECK(tool.sections_drawn > 0);
  CHECK(tool.overlays_drawn > 0);
  // A section collapsed until used opens when its header is opened.
  CHECK(closed_tool.sections_drawn == 0);
  ImGuiWindow* parameters = ImGui::FindWindowByName("Parameters");
  REQUIRE(parameters);
  parameters->StateStorage.SetInt(parameters->GetID("Closed counter"), 1);
  viewer.frame();
  CHECK(closed_tool.sections_drawn > 0);
  REQUIRE(viewer.run() == 0);
  CHECK(tool.count == 3);
}

TEST_CASE("a script's tool command that no tool has fails the session", "[app]") {
  const std::string dir = test::private_scratch_dir("tool_plugin_unknown");
  const auto r = test::run_window(std::string(NOME_SOURCE_DIR) + "/assets/mobius_band.nome --script " +
                                  test::write_script(dir, "tool count\nquit\n"));
  CHECK(r.status == 1);
  CHECK(r.err.find("no tool has a command 'count'") != std::string::npos);
}
