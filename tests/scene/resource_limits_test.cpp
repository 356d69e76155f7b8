#include <catch2/catch.hpp>

#include <string>

#include "scene/scene_support.hpp"

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
