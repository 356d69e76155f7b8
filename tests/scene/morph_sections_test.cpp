// Where a sweepmorph's cross-sections land along a B-spline path: every control point's section in
// order, those of the end control points on the path's first and last samples (as JIPCAD places them).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "scene/scene_support.hpp"
#include "support/shared_examples.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

// Four points a section: section k is the square of corners (k, k/2), (-k/2, k), ... turned so that no
// two sections are scalings of each other's points in the same order.
std::string morph_section_points(int k) {
  const std::string n = "m" + std::to_string(k);
  const double a = k, b = k / 2.0;
  const auto point = [&](int j, double x, double y) {
    return "point " + n + "_" + std::to_string(j) + " (" + std::to_string(x) + " " + std::to_string(y) +
           " 0) endpoint\n";
  };
  return point(0, a, b) + point(1, -b, a) + point(2, -a, -b) + point(3, b, -a) + "polyline " + n + " (" + n +
         "_0 " + n + "_1 " + n + "_2 " + n + "_3) closed endpolyline\n";
}

// Point j of section k, as morph_section_points() writes it.
Vec3 morph_section_corner(int k, int j) {
  const double a = k, b = k / 2.0;
  const Vec3 corners[] = {{a, b, 0}, {-b, a, 0}, {-a, -b, 0}, {b, -a, 0}};
  return corners[j];
}

// The section the morph shows at sample i, read from a morphvisualizer placed there.
std::vector<Vec3> morph_shown_at(const Scene& s, int i, int points) {
  std::vector<Vec3> shown;
  for (int j = 0; j < points; ++j)
    shown.push_back(test::vertex_position(s, "mv" + std::to_string(i) + "_c" + std::to_string(j)));
  return shown;
}

std::string morph_visualizers(int samples) {
  std::string text;
  for (int i = 0; i < samples; ++i) {
    const std::string n = std::to_string(i);
    text += "morphvisualizer vis" + n + " sweep morph index (" + n + ") endmorphvisualizer\ninstance mv" + n +
            " vis" + n + " endinstance\n";
  }
  return text;
}

void check_morph_points(const std::vector<Vec3>& shown, const std::vector<Vec3>& expected) {
  REQUIRE(shown.size() == expected.size());
  for (std::size_t j = 0; j < shown.size(); ++j) {
    INFO("point " << j);
    CHECK(shown[j].x == Approx(expected[j].x).margin(1e-9));
    CHECK(shown[j].y == Approx(expected[j].y).margin(1e-9));
    CHECK(shown[j].z == Approx(expected[j].z).margin(1e-9));
  }
}

}  // namespace

// Thirteen control points, cubic, 30 segments: 3 samples per knot span, control point i (1..11) weighs
// most at sample 3 (i - 1); control points 0 and 12 peak outside the samples and land on 0 and 30.
TEST_CASE(
    "morph sections: a B-spline path carries every control point's section in order, the ends' on its "
    "end samples",
    "[scene]") {
  std::string text;
  const int with_section[] = {0, 3, 5, 8, 12};
  for (int k = 1; k <= 5; ++k) text += morph_section_points(k);
  std::string names;
  for (int i = 0; i < 13; ++i) {
    const std::string n = std::to_string(i);
    text += "point p" + n + " (" + n + " " + std::to_string(i % 2) + " 0) endpoint\n";
    int k = 0;
    for (int q = 0; q < 5; ++q)
      if (with_section[q] == i) k = q + 1;
    text += "controlpoint c" + n + " point p" + n +
            (k ? " crosssection m" + std::to_string(k) : std::string()) + " endcontrolpoint\n";
    names += " c" + n;
  }
  text += "bspline path order 4 (" + names + ") segs 30 endbspline\n";
  text += "sweepmorph morph path path endpath endsweepmorph\ninstance im morph endinstance\n";
  text += morph_visualizers(31);
  const Scene s = Scene::from_text(text, "t.nome");
  const auto section = [](int k) {
    std::vector<Vec3> points;
    for (int j = 0; j < 4; ++j) points.push_back(morph_section_corner(k, j));
    return points;
  };
  // Section k + 1 exactly at its control point's sample; between two, the linear blend by sample count.
  const int at[] = {0, 6, 12, 21, 30};
  for (int q = 0; q < 5; ++q) {
    INFO("section " << q + 1 << " at sample " << at[q]);
    check_morph_points(morph_shown_at(s, at[q], 4), section(q + 1));
  }
  for (int q = 0; q + 1 < 5; ++q)
    for (int i = at[q] + 1; i < at[q + 1]; ++i) {
      INFO("sample " << i);
      const double w = double(i - at[q]) / double(at[q + 1] - at[q]);
      std::vector<Vec3> blend;
      for (int j = 0; j < 4; ++j)
        blend.push_back((1 - w) * morph_section_corner(q + 1, j) + w * morph_section_corner(q + 2, j));
      check_morph_points(morph_shown_at(s, i, 4), blend);
    }
  // The sweep's own first and last rings are those sections, placed: each ring's points lie at the
  // section's distances from the path's end samples.
  const Vec3 first = test::vertex_position(s, "im_v0_0"), last = test::vertex_position(s, "im_v30_0");
  CHECK(glm::length(first - test::vertex_position(s, "im_v0_2")) == Approx(2 * glm::length(section(1)[0])));
  CHECK(glm::length(last - test::vertex_position(s, "im_v30_2")) == Approx(2 * glm::length(section(5)[0])));
}

TEST_CASE("morph sections: a control point that weighs most on the end sample wins over the one before it",
          "[scene]") {
  std::string text = morph_section_points(1) + morph_section_points(2) + morph_section_points(3);
  text +=
      "point p0 (0 0 0) endpoint\npoint p1 (1 1 0) endpoint\npoint p2 (2 0 0) endpoint\n"
      "point p3 (3 1 0) endpoint\npoint p4 (4 0 0) endpoint\n"
      "controlpoint c0 point p0 crosssection m1 endcontrolpoint\n"
      "controlpoint c1 point p1 crosssection m2 endcontrolpoint\n"
      "controlpoint c4 point p4 crosssection m3 endcontrolpoint\n"
      "bspline path order 4 (c0 c1 p2 p3 c4) segs 4 endbspline\n"
      "sweepmorph morph path path endpath endsweepmorph\n";
  text += morph_visualizers(5);
  const Scene s = Scene::from_text(text, "t.nome");
  std::vector<Vec3> second, third;
  for (int j = 0; j < 4; ++j) {
    second.push_back(morph_section_corner(2, j));
    third.push_back(morph_section_corner(3, j));
  }
  check_morph_points(morph_shown_at(s, 0, 4), second);  // c1 peaks on sample 0, c0 before it
  check_morph_points(morph_shown_at(s, 4, 4), third);
}

// JIPCAD's demo: leaf, star, circle, fish and cross on control points 0, 3, 5, 8 and 12 of a cubic
// B-spline of 30 segments, every control point scaled by 0.5.
TEST_CASE("morph sections: JIPCAD's sweeps__morph_demo.nom runs leaf, star, circle, fish, cross", "[scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const std::string file = test::shared_examples_dir("jipcad") + "/sweeps__morph_demo.nom";
  std::string text = test::read_text(file) + "\n" + morph_visualizers(31);
  // Each curve's points in the order its polyline names them (a polyline's vertices keep their names).
  const char* curves[] = {"leaf", "star", "circ", "fish", "cross"};
  const char* prefixes[] = {"le", "st", "ci", "fi", "cr"};
  const int first_point[] = {1, 2, 1, 1, 2};
  for (const char* c : curves) text += std::string("instance x") + c + " " + c + " endinstance\n";
  const Scene s = Scene::from_text(text, file);
  const int at[] = {0, 6, 12, 21, 30};
  for (int q = 0; q < 5; ++q) {
    INFO(curves[q] << " at sample " << at[q]);
    std::vector<Vec3> expected;
    for (int j = 0; j < 12; ++j) {
      const std::string point = prefixes[q] + std::to_string((first_point[q] - 1 + j) % 12 + 1);
      expected.push_back(0.5 * test::vertex_position(s, std::string("x") + curves[q] + "_" + point));
    }
    check_morph_points(morph_shown_at(s, at[q], 12), expected);
  }
}
