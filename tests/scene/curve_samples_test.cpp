// The curves' samples against independent evaluations written here: B-splines by de Boor's algorithm
// on uniform integer knots, Bézier curves by their Bernstein form, circles, helices and spirals by their
// closed forms; every sample, its count and whether the curve is a loop.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "nome/scene/scene.hpp"
#include "scene/scene_support.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

const std::vector<Vec3> curve_polygon = {{0, 0, 0}, {1, 2, 0.5}, {3, 3, -1},   {4, 0, 2},
                                         {6, 1, 1}, {7, -2, 0},  {5, -4, 1.5}, {2, -3, -2}};

std::string curve_points_text(std::size_t count) {
  std::ostringstream text;
  text.precision(17);
  for (std::size_t i = 0; i < count; ++i)
    text << "point p" << i << " (" << curve_polygon[i].x << " " << curve_polygon[i].y << " "
         << curve_polygon[i].z << ") endpoint\n";
  return text.str();
}

std::string curve_names(std::size_t count) {
  std::string names;
  for (std::size_t i = 0; i < count; ++i) names += (i ? " p" : "p") + std::to_string(i);
  return names;
}

// de Boor's algorithm for the curve of degree p over knots u_i = i at parameter x in [p, n], where n is
// the number of control points (the last span taken at x = n).
Vec3 curve_de_boor(const std::vector<Vec3>& control, int p, double x) {
  const int n = int(control.size());
  const int k = std::min(int(std::floor(x)), n - 1);
  std::vector<Vec3> d(std::size_t(p) + 1);
  for (int j = 0; j <= p; ++j) d[std::size_t(j)] = control[std::size_t(j + k - p)];
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const double alpha = (x - double(j + k - p)) / double((j + 1 + k - r) - (j + k - p));
      d[std::size_t(j)] = (1 - alpha) * d[std::size_t(j - 1)] + alpha * d[std::size_t(j)];
    }
  return d[std::size_t(p)];
}

// The Bernstein form: sum of C(n, i) (1 - t)^(n - i) t^i P_i.
Vec3 curve_bernstein(const std::vector<Vec3>& control, double t) {
  const int n = int(control.size()) - 1;
  Vec3 sum(0.0);
  double binomial = 1;
  for (int i = 0; i <= n; ++i) {
    sum += binomial * std::pow(1 - t, n - i) * std::pow(t, i) * control[std::size_t(i)];
    binomial = binomial * double(n - i) / double(i + 1);
  }
  return sum;
}

// The one instance's rim: its positions in order (checked to be the rim's order) and whether it closes.
struct CurveRim {
  std::vector<Vec3> points;
  bool is_loop = false;
};

CurveRim curve_rim(const std::string& text, const std::string& prefix = "v") {
  const Scene s = Scene::from_text(text + "instance i c endinstance\n", "t.nome");
  REQUIRE(s.instances().size() == 1);
  const Piece& piece = s.instances()[0].geometry;
  REQUIRE(piece.rims.size() == 1);
  CurveRim rim;
  rim.is_loop = piece.rims[0].is_loop;
  for (Index v : piece.rims[0].vertices) rim.points.push_back(piece.soup.positions[v]);
  for (std::size_t i = 0; i < rim.points.size(); ++i)
    CHECK(test::vertex_position(s, "i_" + prefix + std::to_string(i)) == rim.points[i]);
  return rim;
}

void check_curve_points(const std::vector<Vec3>& got, const std::vector<Vec3>& expected) {
  REQUIRE(got.size() == expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    INFO("sample " << i << ": " << got[i].x << " " << got[i].y << " " << got[i].z << ", expected "
                   << expected[i].x << " " << expected[i].y << " " << expected[i].z);
    CHECK(glm::length(got[i] - expected[i]) < 1e-12);
  }
}

}  // namespace

TEST_CASE("an open B-spline's samples are de Boor's points at uniform parameter steps", "[scene]") {
  for (int order = 2; order <= 5; ++order)
    for (std::size_t count : {std::size_t(order), std::size_t(6), std::size_t(8)})
      for (int segs : {1, 5, 12}) {
        INFO("order " << order << ", " << count << " points, " << segs << " segments");
        const CurveRim rim =
            curve_rim(curve_points_text(count) + "bspline c order " + std::to_string(order) + " (" +
                      curve_names(count) + ") segs " + std::to_string(segs) + " endbspline\n");
        const std::vector<Vec3> control(curve_polygon.begin(), curve_polygon.begin() + long(count));
        // The parameter runs over [K-1, n], where a full set of K basis functions lives.
        std::vector<Vec3> expected;
        for (int s = 0; s <= segs; ++s)
          expected.push_back(
              curve_de_boor(control, order - 1, (order - 1) + double(int(count) - order + 1) * s / segs));
        check_curve_points(rim.points, expected);
        CHECK_FALSE(rim.is_loop);
      }
}

TEST_CASE("a B-spline without order or segs is quadratic with 8 segments", "[scene]") {
  const CurveRim rim = curve_rim(curve_points_text(5) + "bspline c (" + curve_names(5) + ") endbspline\n");
  const std::vector<Vec3> control(curve_polygon.begin(), curve_polygon.begin() + 5);
  std::vector<Vec3> expected;
  for (int s = 0; s <= 8; ++s) expected.push_back(curve_de_boor(control, 2, 2 + 3.0 * s / 8));
  check_curve_points(rim.points, expected);
  // A quadratic B-spline starts half way along its first leg.
  CHECK(glm::length(rim.points[0] - 0.5 * (control[0] + control[1])) < 1e-12);
}

TEST_CASE("a closed B-spline wraps its first K-1 points around and is one loop of segs samples", "[scene]") {
  for (int order = 2; order <= 5; ++order)
    for (int segs : {6, 10}) {
      INFO("order " << order << ", " << segs << " segments");
      const std::size_t count = 6;
      const CurveRim rim =
          curve_rim(curve_points_text(count) + "bspline c order " + std::to_string(order) + " (" +
                    curve_names(count) + ") segs " + std::to_string(segs) + " closed endbspline\n");
      std::vector<Vec3> wrapped(curve_polygon.begin(), curve_polygon.begin() + long(count));
      for (int i = 0; i < order - 1; ++i) wrapped.push_back(curve_polygon[std::size_t(i)]);
      std::vector<Vec3> expected;
      // The last sample repeats the first and is dropped.
      for (int s = 0; s < segs; ++s)
        expected.push_back(curve_de_boor(wrapped, order - 1, (order - 1) + double(count) * s / segs));
      check_curve_points(rim.points, expected);
      CHECK(rim.is_loop);
    }
}

TEST_CASE("a Bézier curve's samples are its Bernstein form at uniform steps, ends on its end points",
          "[scene]") {
  for (std::size_t count = 2; count <= 7; ++count)
    for (int segs : {1, 4, 9}) {
      INFO(count << " points, " << segs << " segments");
      const CurveRim rim = curve_rim(curve_points_text(count) + "beziercurve c (" + curve_names(count) +
                                     ") segs " + std::to_string(segs) + " endbeziercurve\n");
      const std::vector<Vec3> control(curve_polygon.begin(), curve_polygon.begin() + long(count));
      std::vector<Vec3> expected;
      for (int s = 0; s <= segs; ++s) expected.push_back(curve_bernstein(control, double(s) / segs));
      check_curve_points(rim.points, expected);
      CHECK(rim.points.front() == control.front());
      CHECK(glm::length(rim.points.back() - control.back()) < 1e-12);
      CHECK_FALSE(rim.is_loop);
    }
  // Without segs: 8 segments.
  const CurveRim plain =
      curve_rim(curve_points_text(4) + "beziercurve c (" + curve_names(4) + ") endbeziercurve\n");
  const std::vector<Vec3> control(curve_polygon.begin(), curve_polygon.begin() + 4);
  std::vector<Vec3> expected;
  for (int s = 0; s <= 8; ++s) expected.push_back(curve_bernstein(control, s / 8.0));
  check_curve_points(plain.points, expected);
  // `closed`: the same samples, joined end to start.
  const CurveRim closed = curve_rim(curve_points_text(4) + "beziercurve c (" + curve_names(4) +
                                    ") segs 8 closed endbeziercurve\n");
  check_curve_points(closed.points, expected);
  CHECK(closed.is_loop);
}

TEST_CASE("a Bézier curve that ends where it starts is a loop without the repeated sample", "[scene]") {
  const std::string text =
      "point a (2 0 0) endpoint\npoint b (0 3 1) endpoint\npoint d (-2 -1 0) endpoint\n"
      "beziercurve c (a b d a) segs 6 endbeziercurve\n";
  const CurveRim rim = curve_rim(text);
  const std::vector<Vec3> control = {{2, 0, 0}, {0, 3, 1}, {-2, -1, 0}, {2, 0, 0}};
  std::vector<Vec3> expected;
  for (int s = 0; s < 6; ++s) expected.push_back(curve_bernstein(control, s / 6.0));
  check_curve_points(rim.points, expected);
  CHECK(rim.is_loop);
}

TEST_CASE("circle, helix and spiral samples follow their closed forms", "[scene]") {
  constexpr double pi = std::numbers::pi;
  const CurveRim circle = curve_rim("circle c (7 2.5) endcircle\n", "c");
  std::vector<Vec3> expected;
  for (int i = 0; i < 7; ++i)
    expected.emplace_back(2.5 * std::cos(2 * pi * i / 7), 2.5 * std::sin(2 * pi * i / 7), 0);
  check_curve_points(circle.points, expected);
  CHECK(circle.is_loop);
  // JIPCAD's order (radius segs) reads the same circle.
  check_curve_points(curve_rim("circle c (2.5 7) endcircle\n", "c").points, expected);

  // Helix (radius rise theta_max segs): z = rise * angle in radians, from +x counter-clockwise.
  const CurveRim helix = curve_rim("helix c (1.5 0.25 450 10) endhelix\n");
  expected.clear();
  for (int i = 0; i <= 10; ++i) {
    const double a = 450.0 / 10 * i * pi / 180;
    expected.emplace_back(1.5 * std::cos(a), 1.5 * std::sin(a), 0.25 * a);
  }
  check_curve_points(helix.points, expected);
  CHECK_FALSE(helix.is_loop);

  // Spiral (rate angle segs): the radius grows by `rate` per turn, from the origin.
  const CurveRim spiral = curve_rim("spiral c (0.8 540 9) endspiral\n");
  expected.clear();
  for (int i = 0; i <= 9; ++i) {
    const double turned = 540.0 / 9 * i, a = turned * pi / 180, r = 0.8 * turned / 360;
    expected.emplace_back(r * std::cos(a), r * std::sin(a), 0);
  }
  check_curve_points(spiral.points, expected);
  CHECK_FALSE(spiral.is_loop);
}
