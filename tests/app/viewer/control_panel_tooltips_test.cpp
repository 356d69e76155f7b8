// The control panel explains its controls: the mouse moved down the sidebar, as a user would, and the
// tooltips read where they appear.
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include <imgui.h>

#include "app/viewer/imgui_text.hpp"
#include "viewer/commands/actions.hpp"
#include "viewer/panels/panels.hpp"

using namespace nome;
using namespace nome::viewer;

TEST_CASE("hovering the control panel's stage controls shows what each one does", "[app]") {
  PipelineSettings settings;
  ZipperOptions zipper;
  render::DisplaySettings display;
  EditColors edit_colors;
  float sharpness = 1.0f;
  const ActionRegistry actions;
  const nome::test::OwnImGuiContext context;
  std::string seen;
  // Down the left edge of the panel's widgets, a few pixels at a time, each position one frame.
  for (float y = 0.0f; y < 1200.0f; y += 4.0f) {
    ImGui::GetIO().MousePos = ImVec2(75.0f, y);
    seen += nome::test::imgui_frame(context, [&] {
      draw_control_panel(actions,
                         {settings, zipper, display, edit_colors, nullptr, false, false, {}, sharpness});
    });
  }
  CHECK(seen.find(
            "how semi-sharp weights decay: uniform (1 per level) or Chaikin (evened out along a crease)") !=
        std::string::npos);
  CHECK(seen.find("OpenSubdiv's smooth triangle rule: edge points beside a triangle lean to its centre") !=
        std::string::npos);
}
