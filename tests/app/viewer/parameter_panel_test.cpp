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
  const std::vector<scene::ParameterId> ro = viewer::filtered_parameters(scene, b3, "RO");
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
  state.ranges[scene::ParameterId(0)] = {0.0, 0.5};
  CHECK(state.range(p, scene::ParameterId(0)) == std::pair{0.0, 0.5});
  CHECK(state.range(p, scene::ParameterId(1)) == std::pair{-1.0, 1.0});
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
  const std::vector<scene::ParameterId> parameters = scene.parameters_of_vertex(*vertex);
  REQUIRE_FALSE(parameters.empty());
  for (scene::ParameterId p : parameters) CHECK(scene.parameters()[p].bank == "b7");
  const std::vector<Index> order = viewer::bank_order(scene, parameters);
  REQUIRE(order.size() == 12);
  CHECK(order[0] == 7);
  CHECK(order[1] == 0);
  CHECK(order[7] == 6);
  CHECK(order[8] == 8);
  CHECK(viewer::bank_order(scene, {})[7] == 7);
  CHECK(scene.parameters_of_vertex("no_such_vertex").empty());
}

// What a value typed into a slider (Ctrl+click, or the slider menu's value field) or dragged becomes: on
// the slider's step counted from its minimum, within the range shown. The expected values are worked out
// by hand for each case.
TEST_CASE("a typed slider value is clamped to the range and snapped to the step counted from the minimum",
          "[app]") {
  auto slider = [](double min, double max, double step) {
    scene::Parameter p;
    p.min = min;
    p.max = max;
    p.step = step;
    return p;
  };
  const auto snapped = [](const scene::Parameter& p, double value) {
    return viewer::snap_to_step(p, value, {p.min, p.max});
  };

  SECTION("a positive range whose steps start off zero: 0.1, 0.35, 0.6, 0.85") {
    const scene::Parameter p = slider(0.1, 1.1, 0.25);
    CHECK(snapped(p, 0.3) == Approx(0.35));   // from zero the nearest step would be 0.25
    CHECK(snapped(p, 0.5) == Approx(0.6));    // 1.6 steps: rounded up, not cut down
    CHECK(snapped(p, 0.44) == Approx(0.35));  // 1.36 steps: rounded down
    CHECK(snapped(p, 0.85) == Approx(0.85));  // on a step already
    CHECK(snapped(p, 0.1) == 0.1);
    CHECK(snapped(p, -7.0) == 0.1);  // below the minimum: the minimum
    CHECK(snapped(p, 0.0) == 0.1);
    CHECK(snapped(p, 42.0) == 1.1);  // above the maximum: the maximum
    CHECK(snapped(p, 1.1) == 1.1);
  }
  SECTION("a range below zero: -3, -2.5, ..., -1") {
    const scene::Parameter p = slider(-3.0, -1.0, 0.5);
    CHECK(snapped(p, -2.2) == Approx(-2.0));  // 1.6 steps from -3
    CHECK(snapped(p, -2.3) == Approx(-2.5));  // 1.4 steps
    CHECK(snapped(p, -1.1) == Approx(-1.0));
    CHECK(snapped(p, -2.9) == Approx(-3.0));
    CHECK(snapped(p, -5.0) == -3.0);
    CHECK(snapped(p, 0.0) == -1.0);
    CHECK(snapped(p, 3.0) == -1.0);
  }
  SECTION("a range across zero with a step that does not divide it: -1, -0.3, 0.4, 1.1, and 1.5 the top") {
    const scene::Parameter p = slider(-1.0, 1.5, 0.7);
    CHECK(snapped(p, 0.0) == Approx(-0.3));   // 1.43 steps
    CHECK(snapped(p, 0.1) == Approx(0.4));    // 1.57 steps
    CHECK(snapped(p, -0.7) == Approx(-1.0));  // 0.43 steps
    CHECK(snapped(p, -0.6) == Approx(-0.3));  // 0.57 steps
    CHECK(snapped(p, 1.0) == Approx(1.1));
    CHECK(snapped(p, 2.0) == 1.5);  // above: the maximum, though off the steps
    CHECK(snapped(p, -1.2) == -1.0);
  }
  SECTION("whole steps: a count slider rounds to the nearest whole number") {
    const scene::Parameter p = slider(3.0, 10.0, 1.0);
    CHECK(snapped(p, 5.4) == 5.0);
    CHECK(snapped(p, 5.6) == 6.0);
    CHECK(snapped(p, 2.4) == 3.0);
    CHECK(snapped(p, 11.7) == 10.0);
  }
  SECTION("a range the sculptor narrowed: clamped to it, stepped from the file's minimum") {
    const scene::Parameter p = slider(-1.0, 1.0, 0.25);
    const std::pair<double, double> narrowed{-0.4, 0.6};
    CHECK(viewer::snap_to_step(p, 0.3, narrowed) == Approx(0.25));
    CHECK(viewer::snap_to_step(p, 0.9, narrowed) == 0.6);    // the narrowed top, not the file's 1
    CHECK(viewer::snap_to_step(p, -0.9, narrowed) == -0.4);  // the narrowed bottom, not the file's -1
    CHECK(viewer::snap_to_step(p, -0.3, narrowed) == Approx(-0.25));
  }
  SECTION("no step: the value as typed, only clamped") {
    const scene::Parameter p = slider(-2.0, 2.0, 0.0);
    CHECK(snapped(p, 0.123456) == 0.123456);
    CHECK(snapped(p, -2.5) == -2.0);
    CHECK(snapped(p, 2.5) == 2.0);
  }
}
