// Function strings (`func [...]`) by the values they give: each function is the height of a cartesian
// surface, so a vertex's z is the function's value at its x and y. Truth tables, precedence and every
// function at points whose values are known by hand; then how the three function surfaces use them.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "nome/scene/scene.hpp"
#include "scene/scene_support.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

constexpr double fs_pi = 3.14159265358979323846;

// One cartesian surface per function over the same range, instance k{n} of function n.
Scene fs_scene(const std::vector<std::string>& functions, const std::string& range) {
  std::string text;
  for (size_t n = 0; n < functions.size(); ++n)
    text += "gencartesiansurf g" + std::to_string(n) + " func [" + functions[n] + "] " + range +
            " endgencartesiansurf\ninstance k" + std::to_string(n) + " g" + std::to_string(n) +
            " endinstance\n";
  return Scene::from_text(text, "t.nom");
}

// The value of function n at grid sample (i, j).
double fs_value(const Scene& s, size_t n, int i, int j) {
  return test::vertex_position(s,
                               "k" + std::to_string(n) + "_v" + std::to_string(i) + "_" + std::to_string(j))
      .z;
}

struct FsCase {
  std::string function;
  double value;
};

// Functions of no variable, each checked against its value.
void fs_check_constants(const std::vector<FsCase>& cases) {
  std::vector<std::string> functions;
  for (const FsCase& c : cases) functions.push_back(c.function);
  const Scene s = fs_scene(functions, "(0 1 0 1 1 1)");
  for (size_t n = 0; n < cases.size(); ++n) {
    INFO("[" << cases[n].function << "]");
    CHECK(fs_value(s, n, 0, 0) == Approx(cases[n].value).epsilon(1e-12).margin(1e-12));
  }
}

// A binary operator over every pair of x and y in {-1, 0, 1} (false is 0, true is 1), against `oracle`.
template <typename Oracle>
void fs_check_table(const Scene& s, size_t n, Oracle oracle) {
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) {
      const double x = i - 1, y = j - 1;
      INFO("x = " << x << ", y = " << y);
      CHECK(fs_value(s, n, i, j) == double(oracle(x, y)));
    }
}

}  // namespace

TEST_CASE("function strings: and, or, not and comparisons by their truth tables", "[scene]") {
  const std::vector<std::string> functions{"x and y", "x && y", "x & y",  "x or y", "x || y",   "x | y",
                                           "not x",   "!x",     "x < y",  "x <= y", "x > y",    "x >= y",
                                           "x == y",  "x = y",  "x != y", "x <> y", "2x and 3", "not not y"};
  const Scene s = fs_scene(functions, "(-1 1 -1 1 2 2)");
  for (size_t n = 0; n < 3; ++n) fs_check_table(s, n, [](double x, double y) { return x != 0 && y != 0; });
  for (size_t n = 3; n < 6; ++n) fs_check_table(s, n, [](double x, double y) { return x != 0 || y != 0; });
  for (size_t n = 6; n < 8; ++n) fs_check_table(s, n, [](double x, double) { return x == 0; });
  fs_check_table(s, 8, [](double x, double y) { return x < y; });
  fs_check_table(s, 9, [](double x, double y) { return x <= y; });
  fs_check_table(s, 10, [](double x, double y) { return x > y; });
  fs_check_table(s, 11, [](double x, double y) { return x >= y; });
  fs_check_table(s, 12, [](double x, double y) { return x == y; });
  fs_check_table(s, 13, [](double x, double y) { return x == y; });
  fs_check_table(s, 14, [](double x, double y) { return x != y; });
  fs_check_table(s, 15, [](double x, double y) { return x != y; });
  fs_check_table(s, 16, [](double x, double) { return x != 0; });
  fs_check_table(s, 17, [](double, double y) { return y != 0; });
}

TEST_CASE("function strings: precedence and associativity of the operators", "[scene]") {
  fs_check_constants({
      {"1+2*3", 7},
      {"(1+2)*3", 9},
      {"10-4-3", 3},
      {"12/3/2", 2},
      {"2^3^2", 512},
      {"2**3", 8},
      {"-2^2", -4},
      {"2*3^2", 18},
      {"2^-1", 0.5},
      {"7%4", 3},
      {"7.5%2", 1.5},
      {"-7%3", -1},
      {"8-2*3+1", 3},
      {"1 or 0 and 0", 1},
      {"0 and 0 or 1", 1},
      {"not 0 and 0", 0},
      {"1+1 == 2", 1},
      {"2 < 1+2", 1},
      {"3-1 > 2", 0},
      {"1 < 2 and 2 < 1", 0},
      {"1e2+2.5e-1", 100.25},
      {".5+1", 1.5},
      {"pi", fs_pi},
      {"2pi", 2 * fs_pi},
      {"--3", 3},
      {"+4", 4},
  });
}

TEST_CASE("function strings: implied products, if, and the variables at their samples", "[scene]") {
  // x in {3, 4}, y in {0, 1}.
  const std::vector<std::string> functions{"5x",
                                           "10(x+1)",
                                           "2x^2",
                                           "(x)(x+1)",
                                           "-x^2",
                                           "x - 2y",
                                           "y*10 + x",
                                           "x/(y+1)+1",
                                           "if(x > 3, 1, 2)",
                                           "if(y, x, -x)",
                                           "if(x < 4, if(y, 7, 8), 9)"};
  const Scene s = fs_scene(functions, "(3 4 0 1 1 1)");
  auto at = [&](size_t n, int i, int j) { return fs_value(s, n, i, j); };
  CHECK(at(0, 0, 0) == Approx(15));
  CHECK(at(0, 1, 0) == Approx(20));
  CHECK(at(1, 0, 1) == Approx(40));
  CHECK(at(2, 0, 0) == Approx(18));
  CHECK(at(3, 1, 0) == Approx(20));
  CHECK(at(4, 0, 0) == Approx(-9));
  CHECK(at(5, 1, 1) == Approx(2));
  CHECK(at(5, 0, 0) == Approx(3));
  CHECK(at(6, 0, 1) == Approx(13));
  CHECK(at(6, 1, 0) == Approx(4));
  CHECK(at(7, 1, 1) == Approx(3));
  CHECK(at(7, 0, 0) == Approx(4));
  CHECK(at(8, 0, 0) == Approx(2));
  CHECK(at(8, 1, 0) == Approx(1));
  CHECK(at(9, 0, 0) == Approx(-3));
  CHECK(at(9, 1, 1) == Approx(4));
  CHECK(at(10, 0, 1) == Approx(7));
  CHECK(at(10, 0, 0) == Approx(8));
  CHECK(at(10, 1, 1) == Approx(9));
}

TEST_CASE("function strings: each function at points whose values are known", "[scene]") {
  fs_check_constants({
      {"sin(pi/6)", 0.5},
      {"cos(pi/3)", 0.5},
      {"tan(pi/4)", 1},
      {"asin(0.5)", fs_pi / 6},
      {"acos(0.5)", fs_pi / 3},
      {"atan(1)", fs_pi / 4},
      {"atan2(1, -1)", 3 * fs_pi / 4},
      {"atan2(-1, 0)", -fs_pi / 2},
      {"sinh(log(2))", 0.75},
      {"cosh(log(2))", 1.25},
      {"tanh(log(3))", 0.8},
      {"sqrt(2.25)", 1.5},
      {"abs(-3.5)", 3.5},
      {"abs(2)", 2},
      {"exp(1)", 2.718281828459045},
      {"exp(-2)", 0.1353352832366127},
      {"log(7.38905609893065)", 2},
      {"log10(1000)", 3},
      {"log10(0.01)", -2},
      {"floor(-1.5)", -2},
      {"floor(2.7)", 2},
      {"ceil(-1.5)", -1},
      {"ceil(2.1)", 3},
      {"round(2.5)", 3},
      {"round(-2.5)", -3},
      {"round(1.4)", 1},
      {"sgn(-3)", -1},
      {"sgn(0)", 0},
      {"sgn(0.2)", 1},
      {"pow(2, 10)", 1024},
      {"pow(9, 0.5)", 3},
      {"hypot(5, 12)", 13},
      {"min(3, 1, 2)", 1},
      {"min(4)", 4},
      {"max(3, 1, 2)", 3},
      {"max(-5, -7)", -5},
      {"avg(1, 2, 6)", 3},
      {"sum(1, 2, 6)", 9},
      {"if(0, 1, 2)", 2},
      {"if(0.5, 1, 2)", 1},
  });
}

TEST_CASE("gencartesiansurf (x_min x_max y_min y_max x_segs y_segs): z = f(x, y) on the grid", "[scene]") {
  const Scene s = fs_scene({"x - 2y"}, "(-1 1 0 3 2 3)");
  const PolygonSoup soup = s.combined_soup();
  REQUIRE(soup.num_vertices() == 12);
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 3; ++j) {
      const double x = -1 + i, y = j;
      const Vec3 p = test::vertex_position(s, "k0_v" + std::to_string(i) + "_" + std::to_string(j));
      CHECK(glm::length(p - Vec3(x, y, x - 2 * y)) < 1e-12);
    }
  // The faces face up (+z over a level function).
  const Scene level = fs_scene({"1"}, "(0 2 0 1 2 1)");
  const PolygonSoup flat = level.combined_soup();
  REQUIRE(flat.num_faces() == 2);
  for (Index f = 0; f < 2; ++f) {
    const Vec3 a = flat.positions[flat.face_vertices[flat.face_offsets[f]]];
    const Vec3 b = flat.positions[flat.face_vertices[flat.face_offsets[f] + 1]];
    const Vec3 c = flat.positions[flat.face_vertices[flat.face_offsets[f] + 2]];
    CHECK(glm::cross(b - a, c - b).z > 0);
  }
}

TEST_CASE("genparametricsurf: each of funcX, funcY, funcZ gives its coordinate, in any order", "[scene]") {
  // u over [0, 2] in 4, v over [-1, 1] in 2; the functions written Z, X, Y.
  const Scene s = Scene::from_text(
      "genparametricsurf g funcZ [u*v] funcX [u + 1] funcY [v - u] (0 2 -1 1 4 2) endgenparametricsurf\n"
      "instance i g endinstance\n",
      "t.nom");
  REQUIRE(s.combined_soup().num_vertices() == 15);
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 2; ++j) {
      const double u = 0.5 * i, v = -1 + j;
      const Vec3 p = test::vertex_position(s, "i_v" + std::to_string(i) + "_" + std::to_string(j));
      INFO("u = " << u << ", v = " << v);
      CHECK(glm::length(p - Vec3(u + 1, v - u, u * v)) < 1e-12);
    }
}

TEST_CASE("genimplicitsurf: the vertices of a plane's zero set lie on it, faces towards f > 0", "[scene]") {
  // f is linear, so interpolating along the sample grid's edges is exact: every vertex is on the plane.
  const Scene s = Scene::from_text(
      "genimplicitsurf g func [x + 2y + 3z - 0.3] (-1 1 -1 1 -1 1 4 4 4) endgenimplicitsurf\n"
      "instance i g endinstance\n",
      "t.nom");
  const PolygonSoup soup = s.combined_soup();
  REQUIRE(soup.num_faces() > 0);
  for (const Vec3& p : soup.positions) {
    CHECK(std::abs(p.x + 2 * p.y + 3 * p.z - 0.3) < 1e-12);
    CHECK(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) <= 1 + 1e-12);
  }
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const Vec3 a = soup.positions[soup.face_vertices[soup.face_offsets[f]]];
    const Vec3 b = soup.positions[soup.face_vertices[soup.face_offsets[f] + 1]];
    const Vec3 c = soup.positions[soup.face_vertices[soup.face_offsets[f] + 2]];
    CHECK(glm::dot(glm::cross(b - a, c - b), Vec3(1, 2, 3)) > 0);
  }
  // The plane x = 0.3 across the box: its part in the box is the 2 x 2 square, the faces' area.
  const Scene wall = Scene::from_text(
      "genimplicitsurf g func [x - 0.3] (-1 1 -1 1 -1 1 4 4 4) endgenimplicitsurf\ninstance i g "
      "endinstance\n",
      "t.nom");
  const PolygonSoup w = wall.combined_soup();
  double area = 0;
  for (Index f = 0; f < w.num_faces(); ++f) {
    const Vec3 o = w.positions[w.face_vertices[w.face_offsets[f]]];
    for (Index k = w.face_offsets[f] + 1; k + 1 < w.face_offsets[f + 1]; ++k)
      area += 0.5 * glm::length(glm::cross(w.positions[w.face_vertices[k]] - o,
                                           w.positions[w.face_vertices[k + 1]] - o));
  }
  CHECK(area == Approx(4).epsilon(1e-9));
  for (const Vec3& p : w.positions) CHECK(p.x == Approx(0.3).epsilon(1e-12));
}

// The nesting limit counts how deep a function goes, not how long it is: 300 groups side by side are
// fine, 201 inside each other are refused.
TEST_CASE("function strings: many groups side by side are not nesting", "[scene]") {
  std::string wide = "(x)";
  for (int k = 1; k < 300; ++k) wide += "+(x)";
  const Scene s = fs_scene({wide}, "(0 1 0 1 1 1)");
  CHECK(fs_value(s, 0, 1, 0) == Approx(300.0));
  std::string deep = "x";
  for (int k = 0; k < 201; ++k) deep = "(" + deep + ")";
  const std::vector<std::string> errors = test::scene_errors(
      "gencartesiansurf g func [" + deep + "] (0 1 0 1 1 1) endgencartesiansurf\ninstance k g endinstance\n");
  REQUIRE(errors.size() == 1);
  CHECK_THAT(errors[0], Catch::Contains("nested over 200 levels"));
}
