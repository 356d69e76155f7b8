// Sculpting by hand: a drag rewrites the fewest tokens of the text, or solves for the sliders.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "nome/edit/scene_document.hpp"
#include "nome/edit/scene_drag.hpp"
#include "scene/scene_support.hpp"

using namespace nome;

namespace {

const std::string triangle_text =
    "# a triangle, placed twice\n"
    "point p1 (0 0 0) endpoint\n"
    "point p2 (1 0.50 0) endpoint\n"
    "point p3 (0 1 0) endpoint\n"
    "face f (p1 p2 p3) endface\n"
    "instance a f rotate (0 0 1) (90) translate (1 2 3) endinstance\n"
    "instance b f endinstance\n";

scene::Scene read(const std::string& text) {
  return scene::Scene::from_text(text, "t.nome");
}

// The text with the drag's step made, read again.
scene::Scene after(const SceneDrag& drag, const DragStep& step) {
  return read(replaced_text(drag.text(), step.replacements));
}

// The slider vertex's position at these slider values (a copy of the scene moved there).
Vec3 position_at(scene::Scene s, const std::vector<std::pair<std::string, double>>& values,
                 const std::string& vertex) {
  for (const auto& [name, value] : values) s.set_parameter(*s.find_parameter(name), value);
  return test::vertex_position(s, vertex);
}

}  // namespace

TEST_CASE("dragging a point written as numbers rewrites exactly its three numbers", "[scene]") {
  const scene::Scene s = read(triangle_text);
  const Vec3 start = test::vertex_position(s, "a_p2");
  SceneDrag drag(s, triangle_text, {{"a_p2"}, {}});
  CHECK(drag.description() == "the numbers of point 'p2'");
  const Vec3 offset(0.25, -0.5, 1.0);
  const DragStep step = drag.move(offset);
  REQUIRE(step.replacements.size() == 3);
  CHECK(step.sliders.empty());
  const std::string moved = replaced_text(triangle_text, step.replacements);
  // The point lands where it was dropped through the instance's rotation and translation: in the point's own
  // coordinates the offset is turned back by 90 degrees.
  std::string expected = triangle_text;
  expected.replace(expected.find("(1 0.50 0)"), 10, "(0.5 0.25 1)");
  CHECK(moved == expected);
  const scene::Scene again = read(moved);
  CHECK(glm::distance(test::vertex_position(again, "a_p2"), start + offset) < 1e-9);

  SECTION("no offset gives the numbers back as they are worth") {
    CHECK(read(replaced_text(triangle_text, drag.move(Vec3(0.0)).replacements)).instances().size() == 2);
    CHECK(test::vertex_position(after(drag, drag.move(Vec3(0.0))), "a_p2") == start);
  }
  SECTION("the same point through two instances moves once") {
    SceneDrag both(s, triangle_text, {{"a_p2", "b_p2"}, {}});
    CHECK(both.move(offset).replacements.size() == 3);
  }
}

TEST_CASE("dragging an instance changes its translate, or adds one after its transforms", "[scene]") {
  const scene::Scene s = read(triangle_text);
  SECTION("its translate written as numbers") {
    SceneDrag drag(s, triangle_text, {{}, {"a"}});
    CHECK(drag.description() == "the translate of a");
    const DragStep step = drag.move(Vec3(1, -1, 0.5));
    std::string expected = triangle_text;
    expected.replace(expected.find("translate (1 2 3)"), 17, "translate (2 1 3.5)");
    CHECK(replaced_text(triangle_text, step.replacements) == expected);
  }
  SECTION("an instance without transforms") {
    SceneDrag drag(s, triangle_text, {{}, {"b"}});
    CHECK(drag.description() == "a translate for b");
    CHECK(drag.move(Vec3(0.0)).replacements.empty());
    const std::string moved = replaced_text(triangle_text, drag.move(Vec3(0, 0, -2)).replacements);
    CHECK(moved.find("instance b f translate (0 0 -2) endinstance") != std::string::npos);
    CHECK(glm::distance(test::vertex_position(read(moved), "b_p3"), Vec3(0, 1, -2)) < 1e-12);
  }
  SECTION("a translate written before a rotation is changed through that rotation") {
    const std::string text =
        "point p (1 0 0) endpoint\nface f (p p p) endface\n"
        "point q (0 1 0) endpoint\npoint r (0 0 1) endpoint\nface g (p q r) endface\n"
        "instance c g translate (1 0 0) rotate (0 0 1) (90) endinstance\n";
    const scene::Scene t = read(text);
    SceneDrag drag(t, text, {{}, {"c"}});
    const Vec3 before = test::vertex_position(t, "c_q");
    const std::string moved = replaced_text(text, drag.move(Vec3(0, 3, 0)).replacements);
    CHECK(moved.find("translate (4 0 0) rotate") != std::string::npos);
    CHECK(glm::distance(test::vertex_position(read(moved), "c_q"), before + Vec3(0, 3, 0)) < 1e-12);
  }
}

TEST_CASE("a vertex that no slider and no number places is refused, naming its statement", "[scene]") {
  const std::string text =
      "point p1 ({expr 2 * 0.5} 0 0) endpoint\npoint p2 (0 1 0) endpoint\n"
      "point p3 (0 0 1) endpoint\nface f (p1 p2 p3) endface\ninstance a f endinstance\n"
      "funnel fun (8 0.5 0 0.3) endfunnel\ninstance b fun endinstance\n";
  const scene::Scene s = read(text);
  CHECK_THROWS_WITH(
      SceneDrag(s, text, {{"a_p1"}, {}}),
      Catch::Contains("vertex 'a_p1' cannot move: point 'p1' (t.nome:1:7) gives its coordinates as "
                      "expressions that read no slider"));
  CHECK_THROWS_WITH(SceneDrag(s, text, {{"b_hc3"}, {}}),
                    Catch::Contains("vertex 'b_hc3' cannot move: funnel 'fun' (t.nome:6:8)"));
  CHECK_THROWS_WITH(SceneDrag(s, text, {{}, {}}), Catch::Contains("nothing is selected"));
  CHECK_NOTHROW(SceneDrag(s, text, {{"a_p2"}, {}}));
}

TEST_CASE("dragging a funnel's vertex moves its sliders to land on a reachable target", "[scene]") {
  // The funnel cube's sliders on two of its funnels, in ranges small enough for the brute force below.
  const std::string text =
      "bank fp\n"
      "  set n 8 3 10 1\n"
      "  set ro 0.4 0.1 1.0 0.1\n"
      "  set ratio -0.2 -0.5 0.5 0.1\n"
      "  set h 0.2 0.1 0.8 0.1\n"
      "  set z -0.8 -1.0 -0.1 0.1\n"
      "endbank\n"
      "funnel fun ({expr $fp_n} {expr $fp_ro} {expr $fp_ratio} {expr $fp_h}) endfunnel\n"
      "instance fun1 fun translate (0 0 {expr $fp_z}) endinstance\n"
      "instance fun2 fun translate (0 0 {expr $fp_z}) rotate (1 0 0) (90) endinstance\n";
  const scene::Scene s = read(text);
  struct Range {
    const char* name;
    double min, max, step;
  };
  const Range ranges[] = {{"fp_ro", 0.1, 1.0, 0.1},
                          {"fp_ratio", -0.5, 0.5, 0.1},
                          {"fp_h", 0.1, 0.8, 0.1},
                          {"fp_z", -1.0, -0.1, 0.1}};
  // The least distance from the target the sliders can bring the vertex to, over every value on their steps.
  const auto closest_reachable = [&](const std::string& vertex, const Vec3& target) {
    double best = std::numeric_limits<double>::infinity();
    scene::Scene probe = s;
    const auto steps = [](const Range& r) { return int(std::lround((r.max - r.min) / r.step)); };
    const auto value = [](const Range& r, int i) { return std::round((r.min + i * r.step) * 1e9) / 1e9; };
    const auto set = [&](const Range& r, int i) {
      probe.set_parameter(*probe.find_parameter(r.name), value(r, i));
    };
    for (int a = 0; a <= steps(ranges[0]); ++a)
      for (int b = 0; b <= steps(ranges[1]); ++b)
        for (int d = 0; d <= steps(ranges[3]); ++d)
          for (int c = 0; c <= steps(ranges[2]); ++c) {
            set(ranges[0], a), set(ranges[1], b), set(ranges[3], d), set(ranges[2], c);
            best = std::min(best, glm::distance(test::vertex_position(probe, vertex), target));
          }
    return best;
  };
  const auto moved = [&](const DragStep& step) {
    scene::Scene out = s;
    for (const auto& [id, value] : step.sliders) {
      const scene::Parameter& p = s.parameters()[id];
      CHECK(value >= p.min);
      CHECK(value <= p.max);
      CHECK(std::abs(std::remainder(value - p.min, p.step)) < 1e-9);
      out.set_parameter(id, value);
    }
    return out;
  };
  // A vertex of the high circle reads all four; one of the base circle only the radius and the height.
  const std::pair<std::string, std::string> vertices[] = {{"fun2_hc3", "sliders fp_ro, fp_ratio, fp_h, fp_z"},
                                                          {"fun1_bc5", "sliders fp_ro, fp_z"}};
  for (const auto& [vertex, sliders] : vertices) {
    INFO(vertex);
    const Vec3 start = test::vertex_position(s, vertex);
    SceneDrag drag(s, text, {{vertex}, {}});
    // The count n changes the faces: it is no slider to drag with.
    CHECK(drag.description() == sliders);
    SECTION("a target the sliders reach on their steps") {
      const Vec3 target =
          position_at(s, {{"fp_ro", 0.7}, {"fp_ratio", 0.1}, {"fp_h", 0.6}, {"fp_z", -0.3}}, vertex);
      const DragStep step = drag.move(target - start);
      CHECK(step.replacements.empty());
      CHECK(step.slider_miss < 1e-6);
      CHECK(glm::distance(test::vertex_position(moved(step), vertex), target) < 1e-6);
      CHECK(closest_reachable(vertex, target) < 1e-9);
    }
    SECTION("a target out of reach stops the sliders at their range's end") {
      const Vec3 target = start + Vec3(3, 2, -10);
      const DragStep step = drag.move(target - start);
      const scene::Scene out = moved(step);
      const double reached = glm::distance(test::vertex_position(out, vertex), target);
      CHECK(reached == Approx(step.slider_miss));
      CHECK(reached <= closest_reachable(vertex, target) + 1e-9);
      bool is_at_an_end = false;
      for (const auto& [id, value] : step.sliders) {
        const scene::Parameter& p = out.parameters()[id];
        is_at_an_end = is_at_an_end || value == p.min || value == p.max;
      }
      CHECK(is_at_an_end);
    }
  }
}

TEST_CASE("a text read again with other numbers but the same faces moves the document's positions alone",
          "[scene]") {
  SceneDocument doc = SceneDocument::from_scene(read(triangle_text));
  const std::uint64_t topology = doc.input_topology_version();
  SceneDrag drag(*doc.scene(), triangle_text, {{"a_p2"}, {}});
  doc.reload(after(drag, drag.move(Vec3(0, 0, 1))));
  CHECK(doc.input_topology_version() == topology);
  CHECK(doc.pipeline_positions() != read(triangle_text).combined_positions());
  doc.reload(read(triangle_text));
  CHECK(doc.input_topology_version() == topology);
  CHECK(doc.pipeline_positions() == read(triangle_text).combined_positions());
  doc.reload(read(triangle_text + "instance c f endinstance\n"));
  CHECK(doc.input_topology_version() != topology);
}

TEST_CASE("a rim line's vertex drags by its point's numbers", "[scene]") {
  const std::string text =
      "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (1 1 0) endpoint\n"
      "polyline rim (a b c) endpolyline\ninstance r rim translate (0 0 1) endinstance\n";
  const scene::Scene s = read(text);
  SceneDrag drag(s, text, {{"r_b"}, {}});
  const std::string moved = replaced_text(text, drag.move(Vec3(0, 2, 0)).replacements);
  CHECK(moved.find("point b (1 2 0)") != std::string::npos);
  CHECK(test::vertex_position(read(moved), "r_b") == Vec3(1, 2, 1));
}

TEST_CASE("positions at trial slider values are those the sliders give, the scene unchanged", "[scene]") {
  // The consolidated funnel cube's patches copy the funnels' vertices through rotations: a chain of copies.
  scene::Scene s = test::load_scene_file(test::assets_dir() + "funnel_cube_consolidated.nome");
  std::vector<std::string> names = {s.resolve_vertex_name("fun1_hc3")};
  for (const scene::SceneInstance& instance : s.instances())
    if (instance.name == "tp1" || instance.name == "tp6")
      names.push_back(instance.geometry.soup.vertex_names[0]);
  REQUIRE(names.size() == 3);
  std::vector<scene::PlacedVertex> vertices;
  for (const std::string& name : names) {
    const auto v = s.find_placed_vertex(name);
    REQUIRE(v);
    vertices.push_back(*v);
  }
  const scene::ParameterId ro = *s.find_parameter("fp_ro"), z = *s.find_parameter("fp_z");
  const std::vector<Vec3> before = s.positions_with(vertices, {});
  const std::vector<std::pair<scene::ParameterId, double>> trial = {{ro, 0.8}, {z, -0.3}};
  const std::vector<Vec3> with = s.positions_with(vertices, trial);
  for (std::size_t i = 0; i < vertices.size(); ++i) CHECK(s.position(vertices[i]) == before[i]);
  scene::Scene moved = s;
  moved.set_parameter(ro, 0.8);
  moved.set_parameter(z, -0.3);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    INFO(names[i]);
    CHECK(with[i] != before[i]);
    CHECK(glm::distance(with[i], test::vertex_position(moved, names[i])) < 1e-12);
  }
}

TEST_CASE("a slider stopped at its range's end leaves the others to come as close as they can", "[scene]") {
  // x reaches 1 at most; the second coordinate is x + y, so y must make up what x cannot.
  const std::string text =
      "bank b\n  set x 0.5 0 1 0.001\n  set y 0 -5 5 0.001\nendbank\n"
      "point p ({expr $b_x} {expr $b_x + $b_y} 0) endpoint\n"
      "point q (0 0 1) endpoint point r (1 0 1) endpoint\n"
      "face f (p q r) endface\ninstance a f endinstance\n";
  const scene::Scene s = read(text);
  SceneDrag drag(s, text, {{"a_p"}, {}});
  const Vec3 start = test::vertex_position(s, "a_p");
  const DragStep step = drag.move(Vec3(3, 3, 0) - start);
  REQUIRE(step.sliders.size() == 2);
  CHECK(step.sliders[0].second == 1.0);
  CHECK(step.sliders[1].second == Approx(2.0));
  CHECK(step.slider_miss == Approx(2.0));
}
