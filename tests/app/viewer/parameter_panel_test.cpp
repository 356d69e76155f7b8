#include <catch2/catch.hpp>

#include "app/viewer_support.hpp"
#include "viewer/panels/parameter_panel.hpp"
#include "viewer/session/session.hpp"

using namespace nome;

TEST_CASE("the filter keeps the sliders whose name (or bank's name) holds the text", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("parameter_filter");
  nome::test::write_twelve_banks(dir + "/twelve.nome");
  const viewer::Session session = viewer::Session::open(dir + "/twelve.nome");
  const scene::Scene& scene = *session.scene();
  const scene::Bank& b3 = scene.banks()[3];
  CHECK(viewer::filtered_parameters(scene, b3, "").size() == 4);
  const std::vector<Index> ro = viewer::filtered_parameters(scene, b3, "RO");
  REQUIRE(ro.size() == 1);
  CHECK(scene.parameters()[ro[0]].full_name == "b3_ro");
  CHECK(viewer::filtered_parameters(scene, b3, "b3").size() == 4);  // the bank's name: all of it
  CHECK(viewer::filtered_parameters(scene, b3, "b4").empty());
  CHECK(viewer::filtered_parameters(scene, b3, "height").empty());
}

TEST_CASE("resetting a bank returns the scene to the file's positions exactly", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("parameter_reset");
  nome::test::write_twelve_banks(dir + "/twelve.nome");
  viewer::Session session = viewer::Session::open(dir + "/twelve.nome");
  const auto file_positions = session.positions();
  viewer::ParameterPanelState state;
  state.track(*session.scene());
  const scene::Bank bank = session.scene()->banks()[5];
  session.set_parameter("b5_ro", 0.7);
  session.set_parameter("b5_ratio", -0.3);
  session.set_parameter("b5_n", 9);
  REQUIRE(session.positions() != file_positions);
  const scene::Parameter& ro = session.scene()->parameters()[bank.parameters[1]];
  CHECK(state.is_moved(ro, bank.parameters[1]));
  const auto moves = viewer::bank_reset(*session.scene(), bank, state);
  CHECK(moves.size() == 3);
  for (const auto& [id, value] : moves) session.set_parameter(id, value);
  CHECK(session.positions() == file_positions);
  CHECK(viewer::bank_reset(*session.scene(), bank, state).empty());
}

TEST_CASE("a slider snaps to its step within the range the sculptor narrowed", "[app]") {
  scene::Parameter p;
  p.min = -1.0;
  p.max = 1.0;
  p.step = 0.25;
  CHECK(viewer::snap_to_step(p, 0.3, {p.min, p.max}) == 0.25);
  CHECK(viewer::snap_to_step(p, 0.9, {-0.5, 0.5}) == 0.5);
  viewer::ParameterPanelState state;
  state.ranges[0] = {0.0, 0.5};
  CHECK(state.range(p, 0) == std::pair{0.0, 0.5});
  CHECK(state.range(p, 1) == std::pair{-1.0, 1.0});
}

TEST_CASE("the banks a selected vertex depends on come first", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("parameter_order");
  nome::test::write_twelve_banks(dir + "/twelve.nome");
  const viewer::Session session = viewer::Session::open(dir + "/twelve.nome");
  const scene::Scene& scene = *session.scene();
  const auto& names = session.polygons().vertex_names;
  const auto vertex =
      std::find_if(names.begin(), names.end(), [](const std::string& n) { return n.starts_with("i7_"); });
  REQUIRE(vertex != names.end());
  const std::vector<Index> parameters = scene.parameters_of_vertex(*vertex);
  REQUIRE_FALSE(parameters.empty());
  for (Index p : parameters) CHECK(scene.parameters()[p].bank == "b7");
  const std::vector<Index> order = viewer::bank_order(scene, parameters);
  REQUIRE(order.size() == 12);
  CHECK(order[0] == 7);
  CHECK(order[1] == 0);
  CHECK(order[7] == 6);
  CHECK(order[8] == 8);
  CHECK(viewer::bank_order(scene, {})[7] == 7);
  CHECK(scene.parameters_of_vertex("no_such_vertex").empty());
}
