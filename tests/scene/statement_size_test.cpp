#include <catch2/catch.hpp>

#include <string>

#include "nome/error.hpp"
#include "nome/scene/scene.hpp"

using nome::scene::Dialect;
using nome::scene::Scene;
using nome::scene::SceneOptions;

namespace {

std::string refusal(const std::string& text, SceneOptions options = {}) {
  try {
    Scene::from_text(text, "t.nom", options);
  } catch (const nome::BudgetError& e) {
    return e.what();
  }
  return "accepted";
}

SceneOptions successor(std::uint64_t face_budget = SceneOptions{}.face_budget) {
  return {.face_budget = face_budget, .dialect = Dialect::jipcad};
}

}  // namespace

// Each statement that makes many faces from a few numbers counts them before it makes any: the hostile
// sizes below would need tens of gigabytes, and are refused at once, at the statement's name.
TEST_CASE("statements past the face budget are refused before they make their piece, at the statement",
          "[scene]") {
  CHECK(refusal("torusknot k (2 3 1 0.3 0.1 20000 20000) endtorusknot\ninstance i k endinstance\n",
                successor()) ==
        "t.nom:1:11: torusknot 'k' would make about 400000000 faces (about 55.9 GB), "
        "over the scene's budget of 20000000 faces");
  CHECK(refusal("sphere s (1 360 -90 90 30000 30000) endsphere\ninstance i s endinstance\n", successor()) ==
        "t.nom:1:8: sphere 's' would make about 900000000 faces (about 125.7 GB), over the scene's budget of "
        "20000000 faces");
  // Every kind, against a small budget: refused with its estimate, which is the count it makes when forced.
  const std::string kinds[] = {
      "torus t (2 0.5 360 0 360 40 30) endtorus",
      "ellipsoid e (1 2 360 -90 90 40 30) endellipsoid",
      "dupin d (2 1 0.5 1 2 2 40) enddupin",
      "mobiusstrip m (1 1 4 300) endmobiusstrip",
      "hyperboloid h (40 1 1 20 0 2) endhyperboloid",
      "hyperboloid h (1 1 1 30 40 2) endhyperboloid",  // NOME3's order, two sheets
      "gencartesiansurf c func [x*y] (-1 1 -1 1 40 30) endgencartesiansurf",
      "genparametricsurf p funcX [u] funcY [v] funcZ [u*v] (0 1 0 1 40 30) endgenparametricsurf",
  };
  for (const std::string& statement : kinds) {
    INFO(statement);
    const std::string keyword = statement.substr(0, statement.find(' '));
    const std::string name = statement.substr(keyword.size() + 1, 1);
    const std::string text = statement + "\ninstance i " + name + " endinstance\n";
    const std::string refused = refusal(text, successor(1000));
    const std::string head = "t.nom:1:" + std::to_string(keyword.size() + 2) + ": " + keyword + " '" + name +
                             "' would make about ";
    REQUIRE_THAT(refused,
                 Catch::StartsWith(head) && Catch::EndsWith("over the scene's budget of 1000 faces"));
    const double estimate = std::stod(refused.substr(head.size()));
    SceneOptions forced = successor(1000);
    forced.force = true;
    const double made = double(Scene::from_text(text, "t.nom", forced).combined_soup().num_faces());
    CHECK(estimate == made);
  }
}

TEST_CASE("a sweep past the face budget is refused before it is made, at the sweep", "[scene]") {
  const std::string text =
      "point a (0 0 0) endpoint\npoint b (0 0 10) endpoint\npoint c (0 5 10) endpoint\n"
      "bspline path order 2 (a b c) segs 5000 endbspline\n"
      "circle ring (1 400) endcircle\n"
      "sweep s crosssection ring endcrosssection path path endpath endsweep\n"
      "instance i s endinstance\n";
  const std::string refused = refusal(text, successor(100000));
  CHECK_THAT(refused, Catch::StartsWith("t.nom:6:7: sweep 's' would make about 2") &&
                          Catch::EndsWith("over the scene's budget of 100000 faces"));
}

TEST_CASE("a slider moved to a size past the budget is refused and put back, the shape unchanged",
          "[scene]") {
  const std::string text =
      "bank b\n set n 10 3 100000 1\nendbank\n"
      "torus t (2 0.5 360 0 360 {expr $b.n} {expr $b.n}) endtorus\ninstance i t endinstance\n"
      "funnel f (4 1 0.5 {expr $b.n}) endfunnel\ninstance j f endinstance\n";
  Scene scene = Scene::from_text(text, "t.nom", successor(10000));
  const std::size_t faces = scene.combined_soup().num_faces();
  const auto positions = scene.combined_positions();
  const auto n = scene.find_parameter("b.n");
  REQUIRE(n);
  try {
    scene.set_parameter(*n, 30000);
    FAIL("a torus of 900 million faces was accepted");
  } catch (const nome::BudgetError& e) {
    CHECK(std::string(e.what()) ==
          "t.nom:4:7: torus 't' would make about 900000000 faces (about 125.7 GB), "
          "over the scene's budget of 10000 faces");
  }
  CHECK(scene.parameters()[*n].value == 10);
  CHECK(scene.combined_soup().num_faces() == faces);
  CHECK(scene.combined_positions() == positions);
  scene.set_parameter(*n, 20);
  CHECK(scene.combined_soup().num_faces() == 20 * 20 + 20);
}
