// The Print preparation section as a user works it: its buttons and fields pressed through ImGui's own
// activation (as a keyboard user's Enter on the focused item), and what it hands back.
#include <catch2/catch.hpp>

#include <optional>

#include <imgui.h>
#include <imgui_internal.h>

#include "app/viewer/imgui_text.hpp"
#include "viewer/tools/print_setup_tool.hpp"

using namespace nome;
using namespace nome::viewer;

namespace {

// Two frames of the section: the first finds the item (`scope` then `label`, in the current window's id
// stack) and activates it, the second presses it. What the section handed back in the second.
std::optional<PrintPlacementOptions> press(const PrintPlacementOptions& setup, std::optional<Index> selected,
                                           const char* scope, const char* label) {
  const nome::test::OwnImGuiContext context;
  std::optional<PrintPlacementOptions> changed;
  nome::test::imgui_frame(context, [&] {
    if (scope) ImGui::PushID(scope);
    ImGui::ActivateItem(ImGui::GetID(label));
    if (scope) ImGui::PopID();
    changed = draw_print_setup_section(setup, selected);
  });
  if (changed) return changed;
  nome::test::imgui_frame(context, [&] { changed = draw_print_setup_section(setup, selected); });
  return changed;
}

}  // namespace

TEST_CASE("print preparation: the size's + button grows the fit by a millimetre", "[app]") {
  PrintPlacementOptions setup;
  setup.fit = FitTarget::height;
  setup.fit_size = 60.0;
  const std::string text = nome::test::imgui_text([&] { CHECK_FALSE(draw_print_setup_section(setup, {})); });
  CHECK(text.find("size (mm)") != std::string::npos);
  CHECK(text.find("60.0") != std::string::npos);
  const auto grown = press(setup, {}, "size (mm)", "+");
  REQUIRE(grown);
  CHECK(grown->fit_size == 61.0);
  CHECK(grown->fit == FitTarget::height);
}

TEST_CASE("print preparation: 'use the selected face' rests on the face selected now, and only when pressed",
          "[app]") {
  PrintPlacementOptions setup;
  setup.rest = RestOn::face;
  setup.rest_face = 3;
  const std::string text =
      nome::test::imgui_text([&] { CHECK_FALSE(draw_print_setup_section(setup, Index(5))); });
  CHECK(text.find("face 3") != std::string::npos);
  CHECK(text.find("use the selected face") != std::string::npos);
  const auto chosen = press(setup, Index(5), nullptr, "use the selected face");
  REQUIRE(chosen);
  CHECK(chosen->rest_face == 5);
  CHECK(chosen->rest == RestOn::face);
  // The face it rests on selected: no button to press.
  CHECK(nome::test::imgui_text([&] { draw_print_setup_section(setup, Index(3)); }).find("use the selected") ==
        std::string::npos);
}
