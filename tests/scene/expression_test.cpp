#include <catch2/catch.hpp>

#include <cmath>

#include "nome/scene/scene.hpp"
#include "scene/scene_support.hpp"

using nome::scene::Scene;

namespace {

// The x coordinate of point p instanced alone, with `expr` as its value.
double eval(const std::string& expr) {
  const Scene s = Scene::from_text(
      "bank b set a 2 -10 10 1 set c 3 -10 10 1 endbank\n"
      "point p ({expr " +
          expr +
          "} 0 0) endpoint point q (0 1 0) endpoint point r (0 0 1) endpoint\n"
          "face f (p q r) endface instance i f endinstance\n",
      "t.nome");
  return nome::test::vertex_position(s, "i_p").x;
}

}  // namespace

TEST_CASE("comparisons are exact at equality, on both sides", "[scene]") {
  CHECK(eval("1 <= 1") == 1);
  CHECK(eval("1 >= 1") == 1);
  CHECK(eval("1 < 1") == 0);
  CHECK(eval("1 > 1") == 0);
  CHECK(eval("2 <= 1") == 0);
  CHECK(eval("1 >= 2") == 0);
  CHECK(eval("1 == 1") == 1);
  CHECK(eval("1 != 1") == 0);
}

TEST_CASE("expressions follow the usual precedence and associativity", "[scene]") {
  CHECK(eval("1 + 2 * 3") == 7);
  CHECK(eval("(1 + 2) * 3") == 9);
  CHECK(eval("2 ^ 3 ^ 2") == 512);
  CHECK(eval("-2 ^ 2") == -4);
  CHECK(eval("10 - 4 - 3") == 3);
  CHECK(eval("7 % 4") == 3);
  CHECK(eval("8 / 4 / 2") == 1);
  CHECK(eval("$b_a * $b_c + 1") == 7);
  CHECK(eval("$b.a - -$b.c") == 5);
  CHECK(eval("1 < 2") == 1);
  CHECK(eval("2 <= 1") == 0);
  CHECK(eval("$b_a == 2") == 1);
  CHECK(eval("$b_a != 2") == 0);
  CHECK(eval("7.45058e-009") == Approx(7.45058e-9));
  CHECK(eval(".5") == 0.5);
}

TEST_CASE("expression functions use radians and pi", "[scene]") {
  CHECK(eval("sin(pi / 2)") == Approx(1));
  CHECK(eval("cos(pi)") == Approx(-1));
  CHECK(eval("tan(pi / 4)") == Approx(1));
  CHECK(eval("asin(1)") == Approx(M_PI / 2));
  CHECK(eval("acos(1)") == Approx(0).margin(1e-12));
  CHECK(eval("atan(1)") == Approx(M_PI / 4));
  CHECK(eval("atan2(1, 0)") == Approx(M_PI / 2));
  CHECK(eval("sqrt(16)") == 4);
  CHECK(eval("abs(-3)") == 3);
  CHECK(eval("pow(2, 10)") == 1024);
  CHECK(eval("exp(0)") == 1);
  CHECK(eval("log(exp(2))") == Approx(2));
  CHECK(eval("floor(2.7)") == 2);
  CHECK(eval("ceil(2.1)") == 3);
  CHECK(eval("min(4, $b_c)") == 3);
  CHECK(eval("max(4, $b_c)") == 4);
}
