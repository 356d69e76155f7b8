// Where instances land and what colour they take, against matrices and values worked out by hand.
#include <catch2/catch.hpp>

#include "nome/scene/scene.hpp"
#include "scene/scene_support.hpp"
#include "support/face_colors.hpp"

using namespace nome;
using nome::scene::Scene;

namespace {

const std::string placement_triangle =
    "point p (1 0 0) endpoint point q (0 1 0) endpoint point r (0 0 1) endpoint\n"
    "face t (p q r) endface\n";

void check_at(const Vec3& actual, const Vec3& expected) {
  INFO(actual.x << " " << actual.y << " " << actual.z);
  CHECK(glm::length(actual - expected) < 1e-12);
}

}  // namespace

TEST_CASE("a group's transform applies after its members' own transforms", "[scene]") {
  // p = (1 0 0): the member moves it to (3 0 0), then the group's quarter turn about z to (0 3 0); the
  // other order would give (2 1 0).
  const Scene s = Scene::from_text(placement_triangle +
                                       "group g instance i t translate (2 0 0) endinstance endgroup\n"
                                       "instance top g rotate (0 0 1) (90) endinstance\n",
                                   "t.nome");
  check_at(test::vertex_position(s, "top_i_p"), Vec3(0, 3, 0));
  check_at(test::vertex_position(s, "top_i_q"), Vec3(-1, 2, 0));
  // Two levels of groups, each scaling then moving: 2 * (1 0 0) + (0 0 1), then 3 * that + (1 1 1).
  const Scene nested =
      Scene::from_text(placement_triangle +
                           "group inner instance i t scale (2 2 2) translate (0 0 1) endinstance "
                           "endgroup\n"
                           "group outer instance j inner endinstance endgroup\n"
                           "instance top outer scale (3 3 3) translate (1 1 1) endinstance\n",
                       "t.nome");
  check_at(test::vertex_position(nested, "top_j_i_p"), Vec3(7, 1, 4));
}

TEST_CASE("a surface's colour channels are clamped to [0, 1] on both sides", "[scene]") {
  const Scene s = Scene::from_text(placement_triangle +
                                       "surface S color (2 0.25 -1) endsurface\n"
                                       "instance i t surface S endinstance\n",
                                   "t.nome");
  const std::vector<Color> colors = test::face_colors(s.instances()[0].geometry.soup);
  REQUIRE(colors.size() == 1);
  CHECK(colors[0] == Color(1.0f, 0.25f, 0.0f));
}
