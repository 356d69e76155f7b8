#include <catch2/catch.hpp>

#include <string>

#include "nome/error.hpp"
#include "scene/scene_support.hpp"

using nome::scene::Scene;
using nome::scene::SceneOptions;
using nome::test::scene_errors;

namespace {

std::string funnel_with_height(const std::string& expression) {
  return "funnel f (4 1 0.5 {expr " + expression + "}) endfunnel\ninstance i f endinstance\n";
}

std::string repeated(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

// A chain of `depth` groups, each holding the next, the last one a funnel.
std::string nested_groups(int depth) {
  std::string text = "funnel m (4 1 0.5 1) endfunnel\n";
  for (int i = 0; i < depth; ++i)
    text += "group g" + std::to_string(i) + "\n instance x " +
            (i + 1 < depth ? "g" + std::to_string(i + 1) : std::string("m")) + " endinstance\nendgroup\n";
  return text + "instance r g0 endinstance\n";
}

// Groups g1..g{depth}, each instancing the previous one twice (g0 holds a funnel): 2^depth funnels.
// One instance of g{k} expands to s(k) = 2 + 2 s(k-1) placements below it, s(0) = 1.
std::string doubling_groups(int depth) {
  std::string text = "funnel f (4 1 0.5 1) endfunnel\ngroup g0\n instance a f endinstance\nendgroup\n";
  for (int k = 1; k <= depth; ++k) {
    const std::string previous = "g" + std::to_string(k - 1);
    text += "group g" + std::to_string(k) + "\n instance a " + previous + " endinstance\n instance b " +
            previous + " translate (1 0 0) endinstance\nendgroup\n";
  }
  return text + "instance r g" + std::to_string(depth) + " endinstance\n";
}

std::string budget_error(const std::string& text, const SceneOptions& options) {
  try {
    Scene::from_text(text, "t.nome", options);
  } catch (const nome::BudgetError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// Regression: these overflowed the stack (the parser, evaluation and instance expansion recurse).
TEST_CASE("expressions nested too deep are refused with their location, not a stack overflow", "[scene]") {
  const std::string too_deep = "expression nested more than 256 levels deep";
  const std::string inputs[] = {
      repeated("(", 1000000) + "1" + repeated(")", 1000000),  // the catalogue's million parentheses
      repeated("-", 100000) + "1", repeated("2^", 100000) + "1",
      "1" + repeated("+1", 200000),  // no recursion while parsing, but a tree 200,000 deep
  };
  for (const std::string& expression : inputs) {
    const auto errors = scene_errors(funnel_with_height(expression));
    REQUIRE(errors.size() == 1);
    CHECK_THAT(errors[0], Catch::StartsWith("t.nome:1:") && Catch::Contains(too_deep));
  }
  // Deep but within the limit: accepted and evaluated.
  CHECK(scene_errors(funnel_with_height(repeated("(", 200) + "1" + repeated(")", 200))).empty());
  CHECK(scene_errors(funnel_with_height("1" + repeated("+1", 200))).empty());
}

TEST_CASE("instances nested too deep are refused with their location, not a stack overflow", "[scene]") {
  CHECK(scene_errors(nested_groups(200)).empty());
  const auto errors = scene_errors(nested_groups(20000));
  REQUIRE(errors.size() == 1);
  CHECK_THAT(errors[0], Catch::Contains("instances nested more than 256 levels deep"));
}

TEST_CASE("a scene whose instance tree exceeds the budget is refused before it is expanded", "[scene]") {
  // 2^40 funnels: counting is instant where expanding would exhaust memory.
  const std::string huge = doubling_groups(40);
  const std::string line = std::to_string(5 + 4 * 40);
  CHECK(budget_error(huge, {}) ==
        "t.nome:" + line +
            ":1: the scene would expand to about 3298534883327 instances, over the budget of 1000000");
  // Forcing cannot go past what 32-bit placement ids number.
  const auto errors = [&] {
    try {
      Scene::from_text(huge, "t.nome", {.force = true});
    } catch (const nome::scene::SceneError& e) {
      return e.diagnostics();
    }
    return std::vector<nome::scene::Diagnostic>{};
  }();
  REQUIRE(errors.size() == 1);
  CHECK(errors[0].to_string() ==
        "t.nome:" + line +
            ":1: the scene would expand to about 3298534883327 instances, more than Nome can number");

  // The count is exact: 1 + s(3) = 23 placements.
  const std::string small = doubling_groups(3);
  CHECK(budget_error(small, {.instance_budget = 23}).empty());
  CHECK_THAT(budget_error(small, {.instance_budget = 22}), Catch::Contains("about 23 instances"));
  // Forced, a scene over the budget is expanded in full: 2^10 funnels of 4 faces.
  const Scene forced =
      Scene::from_text(doubling_groups(10), "t.nome", {.instance_budget = 100, .force = true});
  CHECK(forced.combined_soup().num_faces() == 4 * 1024);
}

TEST_CASE("the instance budget adds up every top-level instance and is located at the one crossing it",
          "[scene]") {
  std::string text = doubling_groups(3);  // r: 23 placements
  text += "instance s g3 endinstance\ninstance t g3 endinstance\n";
  const std::string message = budget_error(text, {.instance_budget = 50});
  CHECK_THAT(message, Catch::StartsWith("t.nome:" + std::to_string(5 + 4 * 3 + 2) + ":1: ") &&
                          Catch::Contains("about 69 instances"));
  // Cycles are still reported as such, not counted forever.
  CHECK_THAT(scene_errors("group a\n instance x a endinstance\nendgroup\ninstance r a endinstance\n").at(0),
             Catch::Contains("group 'a' contains itself"));
}

// Found by the nome fuzz target (tests/data/fuzz/nome_fuzzer/unknown_name_in_doubling_groups.nome): an
// error was reported once per placement of its group, 2^16 times here, which took seconds to list.
TEST_CASE("an error inside a group placed many times is reported once", "[scene]") {
  std::string text = doubling_groups(40);
  const std::string group = "group g24\n instance a g23 endinstance\n instance b g23 translate";
  const auto at = text.find(group);
  REQUIRE(at != std::string::npos);
  text.replace(at, group.size(), "group g24\n instance a g23x endinstance\n instance b g23x translate");
  const auto errors = scene_errors(text);
  REQUIRE(errors.size() == 2);
  CHECK_THAT(errors[0], Catch::Contains("unknown name 'g23x' to instantiate (did you mean g23"));
  CHECK_THAT(errors[1], Catch::Contains("unknown name 'g23x' to instantiate (did you mean g23"));
  CHECK(errors[0] != errors[1]);
}

// The same scene, found again by the fuzz target (unknown_name_halfway_down_doubling_groups.nome): under
// the budget, its 2^17 placements were still expanded before the scene failed. The unknown names are now
// found first, each group read once, and reported as the tree meets them; a group no instance reaches
// reports nothing.
TEST_CASE("unknown names are reported in the order the instance tree meets them", "[scene]") {
  const auto errors = scene_errors(
      "point p (0 0 0) endpoint\n"
      "group unused\n instance w nope3 endinstance\nendgroup\n"
      "group g1\n instance x nope1 endinstance\nendgroup\n"
      "group g2\n instance y g1 endinstance\n instance z nope2 endinstance\n instance y2 g1 "
      "endinstance\nendgroup\n"
      "instance r g2 endinstance\ninstance s g1 endinstance\n");
  REQUIRE(errors.size() == 2);
  CHECK_THAT(errors[0], Catch::StartsWith("t.nome:6:13: unknown name 'nope1'"));
  CHECK_THAT(errors[1], Catch::StartsWith("t.nome:10:13: unknown name 'nope2'"));
}

namespace {

// `count` funnels of n = $b_n segments side by side (n quads each).
std::string funnel_row(int count) {
  std::string text = "bank b\n set n 10 3 1000 1\nendbank\nfunnel f ({expr $b_n} 1 0.5 1) endfunnel\n";
  for (int i = 0; i < count; ++i)
    text +=
        "instance i" + std::to_string(i) + " f translate (" + std::to_string(3 * i) + " 0 0) endinstance\n";
  return text;
}

}  // namespace

TEST_CASE(
    "pieces past the face budget stop the evaluation with an estimate, and a slider past it changes nothing",
    "[scene]") {
  // 30 funnels of 100 quads against a budget of 1,000 faces: refused at the 11th, estimated from the 11.
  std::string text = funnel_row(30);
  text.replace(text.find("set n 10"), 8, "set n 100");
  CHECK(budget_error(text, {.face_budget = 1000}) ==
        "t.nome:15:1: the scene's pieces would have about 3000 faces, over the budget of 1000");
  CHECK(Scene::from_text(text, "t.nome", {.face_budget = 1000, .force = true}).combined_soup().num_faces() ==
        3000);

  Scene scene = Scene::from_text(funnel_row(30), "t.nome", {.face_budget = 1000});
  REQUIRE(scene.combined_soup().num_faces() == 300);
  const auto n = scene.find_parameter("b_n");
  REQUIRE(n);
  CHECK_THROWS_AS(scene.set_parameter(*n, 100), nome::BudgetError);
  CHECK(scene.parameters()[*n].value == 10);
  CHECK(scene.combined_soup().num_faces() == 300);
  scene.set_parameter(*n, 20);
  CHECK(scene.combined_soup().num_faces() == 600);
}
