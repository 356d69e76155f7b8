// Colours given to instances (report 8.4), as the viewer gives them: a surface in the instance statement.
#include <catch2/catch.hpp>

#include "nome/scene/save_nome.hpp"
#include "scene/scene_support.hpp"
#include "support/face_colors.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

const char* const two_funnels = R"(surface R color (1 0 0) endsurface
funnel fun (6 1 0.5 1) endfunnel
group pair
  instance a fun endinstance
  instance b fun translate (3 0 0) surface R endinstance
endgroup
instance p pair endinstance
)";

std::vector<Color> colors_of(const Scene& scene, const std::string& prefix) {
  std::vector<Color> out;
  const PolygonSoup soup = scene.combined_soup();
  for (Index f = 0; f < soup.num_faces(); ++f)
    if (soup.face_names[f].starts_with(prefix)) out.push_back(test::face_colors(soup)[f]);
  return out;
}

}  // namespace

TEST_CASE("an instance coloured by path keeps its colour through saving, and the surface can be put back",
          "[scene]") {
  Scene scene = Scene::from_text(two_funnels, "pair.nome");
  const PolygonSoup soup = scene.combined_soup();
  REQUIRE(scene.instance_of_face(soup.face_names[0]) == "p_a");
  CHECK_FALSE(scene.instance_of_face("nothing_f0"));
  CHECK(scene.instance_surface("p_b") == "R");
  scene.set_instance_color("p_a", {0.0f, 0.5f, 1.0f});
  CHECK(scene.instance_surface("p_a") == "rgb_0080ff");
  for (const Color& c : colors_of(scene, "p_a_")) CHECK(c == Color(0.0f, 0.5f, 1.0f));
  for (const Color& c : colors_of(scene, "p_b_")) CHECK(c == Color(1.0f, 0.0f, 0.0f));

  const Scene saved = Scene::from_text(to_nome_text(scene), "saved.nome");
  CHECK(saved.instance_surface("p_a") == "rgb_0080ff");
  CHECK(colors_of(saved, "p_a_") == colors_of(scene, "p_a_"));
  CHECK(saved.combined_soup().num_faces() == soup.num_faces());

  // The same colour again reuses its surface; the old surface comes back as an undo would put it.
  scene.set_instance_color("p_b", {0.0f, 0.5f, 1.0f});
  CHECK(scene.instance_surface("p_b") == "rgb_0080ff");
  scene.set_instance_surface("p_b", std::string("R"));
  for (const Color& c : colors_of(scene, "p_b_")) CHECK(c == Color(1.0f, 0.0f, 0.0f));
  scene.set_instance_surface("p_a", std::nullopt);
  CHECK_FALSE(scene.instance_surface("p_a"));
  CHECK_THROWS_AS(scene.set_instance_color("p_c", {1, 1, 1}), InvalidInputError);
  CHECK_THROWS_AS(scene.set_instance_surface("p_a", std::string("Q")), InvalidInputError);
}

TEST_CASE("faces without a colour of their own take the default; a scene with none carries no colours",
          "[scene]") {
  const char* const plain = "funnel fun (6 1 0.5 1) endfunnel\ninstance a fun endinstance\n";
  CHECK(Scene::from_text(plain, "plain.nome").combined_soup().face_attributes.empty());

  // One coloured face in a mesh whose other face is deleted, beside an instance without colours.
  const char* const mixed = R"(surface R color (1 0 0) endsurface
point p0 (0 0 0) endpoint
point p1 (1 0 0) endpoint
point p2 (1 1 0) endpoint
point p3 (0 1 0) endpoint
point p4 (0 2 0) endpoint
mesh m
  face q0 (p0 p1 p2) surface R endface
  face q1 (p0 p2 p3) endface
  face q2 (p3 p2 p4) endface
endmesh
funnel fun (6 1 0.5 1) endfunnel
instance a m endinstance
instance b fun endinstance
delete face a_q1 endface enddelete
)";
  const PolygonSoup soup = Scene::from_text(mixed, "mixed.nome").combined_soup();
  REQUIRE(test::face_colors(soup).size() == soup.num_faces());
  for (Index f = 0; f < soup.num_faces(); ++f) {
    CAPTURE(soup.face_names[f]);
    CHECK(soup.face_names[f] != "a_q1");
    CHECK(test::face_colors(soup)[f] == (soup.face_names[f] == "a_q0" ? Color(1, 0, 0) : no_face_color));
  }
}

// A colour is not a new scene: only the pieces under the coloured statement are made again, every
// placement of that statement (a group placed twice colours both), and the rest keep their pieces.
TEST_CASE("colouring an instance makes again only the pieces under its statement", "[scene]") {
  const std::string text = std::string(two_funnels) + "instance q pair translate (0 5 0) endinstance\n" +
                           "instance lone fun translate (0 -5 0) endinstance\n";
  Scene scene = Scene::from_text(text, "pairs.nome");
  const std::vector<Color> lone_before = colors_of(scene, "lone_");
  const std::size_t before = scene.placement_evaluations();
  scene.set_instance_color("p_a", {0.0f, 1.0f, 0.0f});
  // Statement `a` of group `pair` is placed twice: p_a and q_a.
  CHECK(scene.placement_evaluations() - before == 2);
  for (const char* prefix : {"p_a_", "q_a_"}) {
    INFO(prefix);
    const std::vector<Color> colors = colors_of(scene, prefix);
    REQUIRE(colors.size() == 6);
    for (const Color& c : colors) CHECK(c == Color(0.0f, 1.0f, 0.0f));
  }
  for (const Color& c : colors_of(scene, "q_b_")) CHECK(c == Color(1.0f, 0.0f, 0.0f));
  CHECK(colors_of(scene, "lone_") == lone_before);
  CHECK(scene.instance_surface("q_a") == "rgb_00ff00");
  // Named back: the file's own colours again, with the same single pass.
  const std::size_t again = scene.placement_evaluations();
  scene.set_instance_surface("lone", "R");
  CHECK(scene.placement_evaluations() - again == 1);
  for (const Color& c : colors_of(scene, "lone_")) CHECK(c == Color(1.0f, 0.0f, 0.0f));
  scene.set_instance_surface("lone", std::nullopt);
  CHECK(colors_of(scene, "lone_") == lone_before);
  CHECK_THROWS_WITH(scene.set_instance_surface("lone", "nothing"), "no surface 'nothing'");
  CHECK(colors_of(scene, "lone_") == lone_before);
}

TEST_CASE("a surface that cannot be evaluated is refused, and the instance keeps its colour", "[scene]") {
  Scene scene = Scene::from_text(std::string("bank b\n  set x 0 0 1 0.5\nendbank\n") +
                                     "surface Half color ({expr 1 / $b_x} 0 0) endsurface\n" + two_funnels,
                                 "half.nome");
  const std::vector<Color> before = colors_of(scene, "p_a_");
  CHECK_THROWS_WITH(scene.set_instance_surface("p_a", "Half"), Catch::Contains("division by zero"));
  CHECK_FALSE(scene.instance_surface("p_a"));
  CHECK(colors_of(scene, "p_a_") == before);
  // The slider that would have coloured it evaluates nothing that names the surface.
  scene.set_parameter(*scene.find_parameter("b_x"), 0.5);
  CHECK(colors_of(scene, "p_a_") == before);
  scene.set_instance_surface("p_a", "Half");
  for (const Color& c : colors_of(scene, "p_a_")) CHECK(c == Color(1.0f, 0.0f, 0.0f));
}
