// The parameter panel's text as ImGui draws it (imgui_text): what a sculptor reads beside each slider.
#include <catch2/catch.hpp>

#include <string>

#include "app/cli_support.hpp"
#include "app/viewer/imgui_text.hpp"
#include "app/viewer_support.hpp"
#include "viewer/panels/parameter_panel.hpp"
#include "viewer/session/session.hpp"

using namespace nome;

namespace {

std::string panel_text(const scene::Scene& scene, viewer::ParameterPanelState& state) {
  return nome::test::imgui_text([&] {
    viewer::LayoutReport report;
    viewer::draw_parameter_section(scene, {}, state, report);
  });
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
