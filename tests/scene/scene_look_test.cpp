// What the successor's files say about the picture: placed lights with their directions and colours,
// curves in their instance's surface colour, faces without a colour beside coloured ones.
#include <catch2/catch.hpp>

#include "nome/query/rim_pick.hpp"
#include "nome/scene/scene.hpp"
#include "nome/scene/scene_rim_lines.hpp"
#include "support/face_colors.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

bool is_near(const Vec3& a, const Vec3& b) {
  return glm::length(a - b) < 1e-12;
}

}  // namespace

TEST_CASE("placed lights: kinds, colours, directions turned by the instance, unplaced ones unused",
          "[scene]") {
  const Scene s = Scene::from_text(R"(
bank b set turn 90 0 180 1 set level 0.5 0 1 0.1 list (turn level) endbank
light amb type NOME_AMBIENT color (0.1 0.2 {expr $b.level}) endlight
light sun type NOME_DIRECTIONAL color (1 0.5 0) endlight
light spot type NOME_SPOT color (1 1 1) direction (0 0 -1) endlight
light unused type NOME_DIRECTIONAL color (1 1 1) endlight
instance a amb endinstance
instance s1 sun endinstance
instance s2 sun rotate (0 0 1) ({expr $b.turn}) endinstance
instance s3 spot rotate (0 1 0) (90) endinstance
)",
                                   "lights.nom");
  const RenderDefaults d = s.render_defaults();
  CHECK(d.light_count == 4);
  REQUIRE(d.lights.size() == 4);
  CHECK(d.lights[0].kind == SceneLight::Kind::ambient);
  CHECK(d.lights[0].color == Color(0.1f, 0.2f, 0.5f));
  CHECK(d.lights[1].kind == SceneLight::Kind::directional);
  CHECK(d.lights[1].color == Color(1.0f, 0.5f, 0.0f));
  CHECK(is_near(d.lights[1].direction, Vec3(0, 1, 0)));   // JIPCAD's +y
  CHECK(is_near(d.lights[2].direction, Vec3(-1, 0, 0)));  // +y turned 90 degrees about +z
  CHECK(d.lights[3].kind == SceneLight::Kind::directional);
  CHECK(is_near(d.lights[3].direction, Vec3(-1, 0, 0)));  // its own -z turned 90 degrees about +y
  Scene moved = s;
  moved.set_parameter(*moved.find_parameter("b.turn"), 180);
  moved.set_parameter(*moved.find_parameter("b.level"), 1);
  const RenderDefaults m = moved.render_defaults();
  CHECK(is_near(m.lights[2].direction, Vec3(0, -1, 0)));
  CHECK(m.lights[0].color == Color(0.1f, 0.2f, 1.0f));
  const Scene unplaced = Scene::from_text("light l type NOME_AMBIENT color (1 1 1) endlight\n", "l.nom");
  CHECK(unplaced.render_defaults().lights.empty());
}

TEST_CASE("curves take the surface of the nearest instance that names one", "[scene]") {
  const Scene s = Scene::from_text(R"(
# nome-dialect: jipcad
surface red color (1 0 0) endsurface
surface blue color (0 0 1) endsurface
point a (0 0 0) endpoint
point b (1 0 0) endpoint
polyline p (a b) endpolyline
circle c (1 8) endcircle
group g instance ip p endinstance instance ic c surface blue endinstance endgroup
instance painted g surface red endinstance
instance plain p endinstance
)",
                                   "curves.nom");
  const RimLines rims = scene_rim_lines(s);
  REQUIRE(rims.num_lines() == 3);
  REQUIRE(rims.colors.size() == 3);
  CHECK(rims.colors[0] == Color(1, 0, 0));  // the group's surface
  CHECK(rims.colors[1] == Color(0, 0, 1));  // its own instance's, nearer than the group's
  CHECK_FALSE(rims.colors[2].has_value());
}

TEST_CASE("faces without a colour beside coloured ones carry no colour, not a grey", "[scene]") {
  const Scene s = Scene::from_text(R"(
surface green color (0 1 0) endsurface
point a (0 0 0) endpoint
point b (1 0 0) endpoint
point c (1 1 0) endpoint
point d (0 1 0) endpoint
point e (2 0 0) endpoint
point f (2 1 0) endpoint
mesh m face p (a b c d) surface green endface face q (b e f c) endface endmesh
instance i m endinstance
)",
                                   "faces.nom");
  const PolygonSoup& soup = s.instances().at(0).geometry.soup;
  REQUIRE(test::face_colors(soup).size() == 2);
  CHECK(test::face_colors(soup)[0] == Color(0, 1, 0));
  CHECK(test::face_colors(soup)[1] == no_face_color);
  CHECK(written_face_color(test::face_colors(soup)[1]) == Color(0.75f));
  CHECK(written_face_color(test::face_colors(soup)[0]) == Color(0, 1, 0));
}
