// A slider value the scene refuses (a statement made invalid, the face budget passed) after other
// placements reading the slider were already moved or made again: the scene must be as it was, and
// later moves must give what a fresh reading gives. Oracle: the same text read fresh.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "nome/error.hpp"
#include "scene/fresh_scene_oracle.hpp"
#include "support/face_colors.hpp"

using namespace nome;

namespace {

// Placements reading slider s in every way, in a group and at the top: a sweep whose vertices alone move,
// one whose colour follows s, one that s turns inside out, a funnel made again that t moves too, copies
// of the first sweep's vertices, a funnel of 2 s + 3 faces, and last a funnel that needs s <= 4 (n >= 3).
std::string refusal_text(double s, double t) {
  return "bank b set s " + std::to_string(s) + " 0 8 1 set t " + std::to_string(t) + " 0 4 1 endbank\n" +
         test::swept_triangle_text +
         "point z1 (0 {expr $b_s / 4} 1) endpoint\n"
         "surface col color ({expr $b_s - 1} 0.5 0.5) endsurface\n"
         "funnel grow (5 {expr 1 + $b_s / 4} 0.5 1) endfunnel\n"
         "funnel wide ({expr 3 + 2 * $b_s} 1 0.5 1) endfunnel\n"
         "funnel needs ({expr 7 - $b_s} 1 0.5 1) endfunnel\n"
         "group gs\n"
         "  instance moved sw endinstance\n"
         "  instance tinted sw translate (3 0 0) surface col endinstance\n"
         "  instance turned sw scale ({expr 1 - $b_s / 2} 1 1) translate (6 0 0) endinstance\n"
         "  instance both grow translate ({expr $b_t} 0 {expr $b_s}) endinstance\n"
         "endgroup\n"
         "instance g gs endinstance\n"
         "mesh patch face p (g_moved_v0_0 g_moved_v0_1 g_moved_v1_1 g_moved_v1_0) endface endmesh\n"
         "instance c patch translate (0 {expr $b_t} 0) endinstance\n"
         "instance w wide translate (0 -4 0) endinstance\n"
         "instance late needs translate (0 0 -4) endinstance\n";
}

// What a refused value must leave as it was: the geometry, each instance's, the sliders, the document's.
struct Snapshot {
  PolygonSoup combined;
  std::vector<Buffer<Vec3>> instance_positions;
  std::vector<std::vector<Color>> instance_colors;
  std::vector<double> values;
  PolygonSoup input;
};

Snapshot snapshot(const SceneDocument& doc) {
  Snapshot out{doc.scene()->combined_soup(), {}, {}, {}, doc.pipeline_input().soup};
  for (const auto& instance : doc.scene()->instances()) {
    out.instance_positions.push_back(instance.geometry.soup.positions);
    out.instance_colors.push_back(test::face_colors(instance.geometry.soup));
  }
  for (const auto& p : doc.scene()->parameters()) out.values.push_back(p.value);
  return out;
}

void check_unchanged(const SceneDocument& doc, const Snapshot& before) {
  const Snapshot now = snapshot(doc);
  CHECK(now.values == before.values);
  CHECK(now.instance_positions == before.instance_positions);
  CHECK(now.instance_colors == before.instance_colors);
  CHECK(now.combined.positions == before.combined.positions);
  CHECK(now.combined.face_vertices == before.combined.face_vertices);
  CHECK(test::face_colors(now.combined) == test::face_colors(before.combined));
  CHECK(now.input.positions == before.input.positions);
  CHECK(now.input.face_vertices == before.input.face_vertices);
}

}  // namespace

TEST_CASE("a refused slider value leaves every placement as it was, and later moves read fresh", "[scene]") {
  SceneDocument doc = SceneDocument::from_scene(scene::Scene::from_text(refusal_text(0, 0), "t.nome"));
  const Snapshot at_start = snapshot(doc);
  // s = 5: the sweeps have moved or been made again, the funnels made again, before `late` refuses it.
  CHECK_THROWS_AS(doc.set_parameter("b_s", 5), scene::SceneError);
  check_unchanged(doc, at_start);
  test::check_same_as_fresh(doc, refusal_text(0, 0));
  // t remakes the group (all its placements joined again) and moves the copies of its sweep's vertices.
  doc.set_parameter("b_t", 1);
  test::check_same_as_fresh(doc, refusal_text(0, 1));
  // s = 3 gives the colour and the handedness that s = 5 gave: nothing kept from the refused try may stand.
  doc.set_parameter("b_s", 3);
  test::check_same_as_fresh(doc, refusal_text(3, 1));
  const Snapshot at_three = snapshot(doc);
  CHECK_THROWS_AS(doc.set_parameter("b_s", 6), scene::SceneError);
  check_unchanged(doc, at_three);
  doc.set_parameter("b_t", 2);
  test::check_same_as_fresh(doc, refusal_text(3, 2));
  doc.set_parameter("b_s", 1);
  test::check_same_as_fresh(doc, refusal_text(1, 2));
}

TEST_CASE("a slider value over the face budget leaves every placement as it was", "[scene]") {
  // The budget holds the scene at s = 3; at s = 4 the funnel `wide` passes it (`late` is still valid).
  const auto faces = [](double s) {
    return scene::Scene::from_text(refusal_text(s, 0), "t.nome").combined_soup().num_faces();
  };
  REQUIRE(faces(4) > faces(3));
  scene::SceneOptions options;
  options.face_budget = faces(3);
  SceneDocument doc =
      SceneDocument::from_scene(scene::Scene::from_text(refusal_text(0, 0), "t.nome", options));
  const Snapshot at_start = snapshot(doc);
  CHECK_THROWS_AS(doc.set_parameter("b_s", 4), BudgetError);
  check_unchanged(doc, at_start);
  doc.set_parameter("b_t", 1);
  test::check_same_as_fresh(doc, refusal_text(0, 1));
  doc.set_parameter("b_s", 3);
  test::check_same_as_fresh(doc, refusal_text(3, 1));
}
