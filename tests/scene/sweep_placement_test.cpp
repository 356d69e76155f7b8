// Where a sweep puts its cross-sections, against frames known in closed form: on a straight path along +z
// the section's x runs along +y and its y along -x (N = T x (1,0,0), B = T x N); around a circle N points
// to the centre and B along the axis; at a polyline's corner the section is stretched across the bend by
// 1 / cos(half the turn). Twist, azimuth and a control point's turn are right-handed about the tangent
// (from N towards B); scale, tilt, reverse, caps, cut ends and morphs are checked by position.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "nome/scene/scene.hpp"
#include "nome/scene/sweep.hpp"
#include "scene/scene_support.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

constexpr double sweep_pi = std::numbers::pi;

// An asymmetric triangle, so that a turn, a mirror or a shifted start all show.
const CrossSection sweep_triangle{{{1, 0}, {0, 2}, {-1, -0.5}}, true};

constexpr const char* sweep_triangle_text =
    "point s0 (1 0 0) endpoint\npoint s1 (0 2 0) endpoint\npoint s2 (-1 -0.5 0) endpoint\n"
    "polyline tri (s0 s1 s2) isloop endpolyline\n";

// The section point (x, y) turned by `degrees` about the tangent, in a frame (N, B): x N + y B after the
// turn from N towards B.
Vec3 sweep_turned(glm::dvec2 p, double degrees, const Vec3& n, const Vec3& b) {
  const double a = degrees * sweep_pi / 180;
  const double x = p.x * std::cos(a) - p.y * std::sin(a), y = p.x * std::sin(a) + p.y * std::cos(a);
  return x * n + y * b;
}

// On the straight path along +z: N = +y, B = -x.
Vec3 sweep_on_z(double z, glm::dvec2 p, double degrees) {
  return Vec3(0, 0, z) + sweep_turned(p, degrees, Vec3(0, 1, 0), Vec3(-1, 0, 0));
}

void check_sweep_point(const Vec3& got, const Vec3& expected) {
  INFO("got " << got.x << " " << got.y << " " << got.z << ", expected " << expected.x << " " << expected.y
              << " " << expected.z);
  CHECK(glm::length(got - expected) < 1e-9);
}

std::vector<PathSample> sweep_straight_path(int n) {
  std::vector<PathSample> path;
  for (int i = 0; i < n; ++i) path.push_back({Vec3(0, 0, 0.5 * i)});
  return path;
}

std::string sweep_straight_points(int n) {
  std::string text;
  for (int i = 0; i < n; ++i)
    text += "point z" + std::to_string(i) + " (0 0 " + std::to_string(0.5 * i) + ") endpoint\n";
  return text;
}

// The corners of face f of a soup, as vertex indices.
std::vector<Index> sweep_face(const PolygonSoup& soup, Index f) {
  return {soup.face_vertices.begin() + soup.face_offsets[f],
          soup.face_vertices.begin() + soup.face_offsets[f + 1]};
}

// de Boor's algorithm on knots u_i = i, for the scalars a B-spline blends (a control point's scale, turn).
double sweep_de_boor(const std::vector<double>& control, int p, double x) {
  const int n = int(control.size());
  const int k = std::min(int(std::floor(x)), n - 1);
  std::vector<double> d(std::size_t(p) + 1);
  for (int j = 0; j <= p; ++j) d[std::size_t(j)] = control[std::size_t(j + k - p)];
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const double alpha = (x - double(j + k - p)) / double(p + 1 - r);
      d[std::size_t(j)] = (1 - alpha) * d[std::size_t(j - 1)] + alpha * d[std::size_t(j)];
    }
  return d[std::size_t(p)];
}

// The Bézier curve over `control` at t by its Bernstein form, sum of C(n, i) t^i (1 - t)^(n - i) c_i: a
// control point's scale as the curve blends it.
double sweep_bernstein(const std::vector<double>& control, double t) {
  const int n = int(control.size()) - 1;
  double sum = 0.0, binomial = 1.0;
  for (int i = 0; i <= n; ++i) {
    sum += binomial * std::pow(t, i) * std::pow(1 - t, n - i) * control[std::size_t(i)];
    binomial = binomial * (n - i) / (i + 1);
  }
  return sum;
}

}  // namespace

TEST_CASE(
    "on a straight path the section's x runs along N = +y, its y along B = -x; twist turns it right-handed",
    "[scene]") {
  for (const FrameKind frames : {FrameKind::frenet, FrameKind::minimal_torsion}) {
    INFO("mintorsion " << (frames == FrameKind::minimal_torsion));
    SweepOptions o;
    o.frames = frames;
    o.twist = 90;
    o.azimuth = 30;
    const std::vector<PathSample> path = sweep_straight_path(4);
    const PolygonSoup soup = sweep(path, {&sweep_triangle, 1}, o).piece.soup;
    REQUIRE(soup.num_vertices() == 12);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 3; ++j) {
        INFO("sample " << i << ", point " << j);
        CHECK(soup.vertex_names[Index(3 * i + j)] == "v" + std::to_string(i) + "_" + std::to_string(j));
        // The twist grows evenly to its full amount at the last sample.
        check_sweep_point(soup.positions[Index(3 * i + j)],
                          sweep_on_z(0.5 * i, sweep_triangle.points[std::size_t(j)], 30 + 90.0 * i / 3));
      }
    // Faces f{i}_{j}: (v_i_j, v_i_j+1, v_i+1_j+1, v_i+1_j), so that they face away from the path.
    REQUIRE(soup.num_faces() == 9);
    CHECK(soup.face_names[5] == "f1_2");
    CHECK(sweep_face(soup, 5) == std::vector<Index>{5, 3, 6, 8});
  }
}

TEST_CASE("a sweep statement reads azimuth, twist, reverse, caps and the triangle brep as written",
          "[scene]") {
  const std::string text = std::string(sweep_triangle_text) + sweep_straight_points(4) +
                           "polyline p (z0 z1 z2 z3) endpolyline\n"
                           "sweep s crosssection tri reverse begincap endcap endcrosssection\n"
                           "  path p azimuth (20) twist (-60) endpath brep TRIANGLES endsweep\n"
                           "instance i s endinstance\n";
  const Scene s = Scene::from_text(text, "t.nome");
  const PolygonSoup& soup = s.instances().at(0).geometry.soup;
  REQUIRE(soup.num_vertices() == 12);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) {
      INFO("sample " << i << ", point " << j);
      // Reversed: point j of each ring is the section's point 2 - j.
      check_sweep_point(test::vertex_position(s, "i_v" + std::to_string(i) + "_" + std::to_string(j)),
                        sweep_on_z(0.5 * i, sweep_triangle.points[std::size_t(2 - j)], 20 - 60.0 * i / 3));
    }
  // Triangles f{i}_{j}a and b split each band quad along its (i,j)-(i+1,j+1) diagonal; then the caps.
  REQUIRE(soup.num_faces() == 3 * 3 * 2 + 2);
  CHECK(soup.face_names[2] == "i_f0_1a");
  CHECK(sweep_face(soup, 2) == std::vector<Index>{1, 2, 5});
  CHECK(sweep_face(soup, 3) == std::vector<Index>{1, 5, 4});
  // The begin cap runs the first ring backwards, the end cap the last ring forwards.
  CHECK(soup.face_names[18] == "i_begincap");
  CHECK(sweep_face(soup, 18) == std::vector<Index>{2, 1, 0});
  CHECK(soup.face_names[19] == "i_endcap");
  CHECK(sweep_face(soup, 19) == std::vector<Index>{9, 10, 11});
}

TEST_CASE("a sweep without begincap or endcap has no cap there; cutbegin and cutend drop the end rings",
          "[scene]") {
  const std::string points = std::string(sweep_triangle_text) + sweep_straight_points(5) +
                             "polyline p (z0 z1 z2 z3 z4) endpolyline\n";
  const auto soup_of = [&](const std::string& section_flags, const std::string& path_options) {
    const Scene s =
        Scene::from_text(points + "sweep s crosssection tri " + section_flags + " endcrosssection path p " +
                             path_options + " endpath endsweep\ninstance i s endinstance\n",
                         "t.nome");
    return s.instances().at(0).geometry.soup;
  };
  const PolygonSoup begin_only = soup_of("begincap", "");
  REQUIRE(begin_only.num_faces() == 4 * 3 + 1);
  CHECK(begin_only.face_names[12] == "i_begincap");
  const PolygonSoup end_only = soup_of("endcap", "");
  REQUIRE(end_only.num_faces() == 4 * 3 + 1);
  CHECK(end_only.face_names[12] == "i_endcap");
  CHECK(sweep_face(end_only, 12) == std::vector<Index>{12, 13, 14});
  CHECK(soup_of("", "").num_faces() == 4 * 3);

  // Cut ends: the first and last samples only aim the path; the twist still counts every sample.
  const PolygonSoup cut = soup_of("begincap endcap", "twist (120) cutbegin cutend");
  REQUIRE(cut.num_vertices() == 9);
  CHECK(cut.vertex_names[0] == "i_v1_0");
  CHECK(cut.vertex_names[8] == "i_v3_2");
  for (int i = 1; i <= 3; ++i)
    for (int j = 0; j < 3; ++j)
      check_sweep_point(cut.positions[Index(3 * (i - 1) + j)],
                        sweep_on_z(0.5 * i, sweep_triangle.points[std::size_t(j)], 120.0 * i / 4));
  REQUIRE(cut.num_faces() == 2 * 3 + 2);
  CHECK(sweep_face(cut, 6) == std::vector<Index>{2, 1, 0});
  CHECK(sweep_face(cut, 7) == std::vector<Index>{6, 7, 8});
  const PolygonSoup cut_begin = soup_of("", "cutbegin");
  CHECK(cut_begin.num_vertices() == 12);
  check_sweep_point(cut_begin.positions[0], sweep_on_z(0.5, sweep_triangle.points[0], 0));
  const PolygonSoup cut_end = soup_of("", "cutend");
  CHECK(cut_end.num_vertices() == 12);
  check_sweep_point(cut_end.positions[11], sweep_on_z(1.5, sweep_triangle.points[2], 0));
}

TEST_CASE("a control point scales its section in section coordinates, turns it, tilts it and reverses it",
          "[scene]") {
  const std::string text =
      std::string(sweep_triangle_text) + sweep_straight_points(5) +
      "controlpoint c1 point z1 scale (2 0.5 0) rotate (0 0 40) endcontrolpoint\n"
      "controlpoint c2 point z2 rotate (30 0 0) endcontrolpoint\n"
      "controlpoint c3 point z3 rotate (0 -20 0) reverse endcontrolpoint\n"
      "polyline p (z0 c1 c2 c3 z4) endpolyline\n"
      "sweep s crosssection tri endcrosssection path p azimuth (10) twist (80) endpath endsweep\n"
      "instance i s endinstance\n";
  const Scene s = Scene::from_text(text, "t.nome");
  const auto at = [&](int i, int j) {
    return test::vertex_position(s, "i_v" + std::to_string(i) + "_" + std::to_string(j));
  };
  const Vec3 n(0, 1, 0), b(-1, 0, 0), t(0, 0, 1);
  for (int j = 0; j < 3; ++j) {
    INFO("point " << j);
    const glm::dvec2 p = sweep_triangle.points[std::size_t(j)];
    check_sweep_point(at(0, j), sweep_on_z(0, p, 10));
    // Scaled by (2, 0.5) along the section's own axes, then turned by azimuth, twist and its own 40.
    check_sweep_point(at(1, j), sweep_on_z(0.5, {2 * p.x, 0.5 * p.y}, 10 + 20 + 40));
    // Tilted by 30 degrees about N: the section's B component leans towards +T.
    const Vec3 turned = sweep_turned(p, 10 + 40, n, b);
    const double along_b = glm::dot(turned, b), tilt = 30 * sweep_pi / 180;
    check_sweep_point(at(2, j), Vec3(0, 0, 1) + glm::dot(turned, n) * n +
                                    along_b * (std::cos(tilt) * b + std::sin(tilt) * t));
    // From the reversing point on: the section's order reversed, azimuth and twist turn the other way;
    // a tilt of -20 degrees about B takes the N component towards +T.
    const glm::dvec2 r = sweep_triangle.points[std::size_t(2 - j)];
    const Vec3 back = sweep_turned(r, -(10 + 60), n, b);
    const double along_n = glm::dot(back, n), lean = -20 * sweep_pi / 180;
    check_sweep_point(at(3, j), Vec3(0, 0, 1.5) + glm::dot(back, b) * b +
                                    along_n * (std::cos(lean) * n - std::sin(lean) * t));
    check_sweep_point(at(4, j), sweep_on_z(2, r, -(10 + 80)));
  }
}

TEST_CASE("around a circle N points to the centre and B along +z, with either frame, twist once around",
          "[scene]") {
  constexpr int n = 12;
  constexpr double radius = 3;
  std::vector<PathSample> path;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * sweep_pi * i / n;
    path.push_back({Vec3(radius * std::cos(a), radius * std::sin(a), 0)});
  }
  // Each sample's section lies in the plane bisecting its corner: stretched across the bend by 1/cos(pi/n).
  const double stretch = 1 / std::cos(sweep_pi / n);
  for (const FrameKind frames : {FrameKind::frenet, FrameKind::minimal_torsion}) {
    INFO("mintorsion " << (frames == FrameKind::minimal_torsion));
    SweepOptions o;
    o.frames = frames;
    o.is_path_closed = true;
    o.twist = 360;
    o.azimuth = 15;
    const SweepResult r = sweep(path, {&sweep_triangle, 1}, o);
    CHECK(r.warnings.empty());
    const PolygonSoup& soup = r.piece.soup;
    REQUIRE(soup.num_vertices() == n * 3);
    for (int i = 0; i < n; ++i) {
      const double a = 2 * sweep_pi * i / n;
      const Vec3 radial(std::cos(a), std::sin(a), 0);
      for (int j = 0; j < 3; ++j) {
        INFO("sample " << i << ", point " << j);
        const Vec3 q =
            sweep_turned(sweep_triangle.points[std::size_t(j)], 15 + 360.0 * i / n, -radial, Vec3(0, 0, 1));
        check_sweep_point(
            soup.positions[Index(3 * i + j)],
            path[std::size_t(i)].position + stretch * glm::dot(q, radial) * radial + Vec3(0, 0, q.z));
      }
    }
    // The last band joins the last ring to the first, point to point.
    REQUIRE(soup.num_faces() == n * 3);
    CHECK(sweep_face(soup, (n - 1) * 3) == std::vector<Index>{(n - 1) * 3, (n - 1) * 3 + 1, 1, 0});
  }
}

TEST_CASE("along an open arc the end frames follow their chords, the inner ones point to the centre",
          "[scene]") {
  constexpr int n = 5;
  constexpr double step = sweep_pi / 2 / (n - 1);
  std::vector<PathSample> path;
  for (int i = 0; i < n; ++i) path.push_back({Vec3(2 * std::cos(step * i), 2 * std::sin(step * i), 1)});
  for (const FrameKind frames : {FrameKind::frenet, FrameKind::minimal_torsion}) {
    INFO("mintorsion " << (frames == FrameKind::minimal_torsion));
    SweepOptions o;
    o.frames = frames;
    const PolygonSoup soup = sweep(path, {&sweep_triangle, 1}, o).piece.soup;
    for (int i = 0; i < n; ++i) {
      // An end sample faces along its one chord, whose normal points to the centre from the chord's middle.
      const double a = i == 0 ? step / 2 : i == n - 1 ? step * (n - 1.5) : step * i;
      const double stretch = i == 0 || i == n - 1 ? 1 : 1 / std::cos(step / 2);
      const Vec3 radial(std::cos(a), std::sin(a), 0);
      for (int j = 0; j < 3; ++j) {
        INFO("sample " << i << ", point " << j);
        const glm::dvec2 p = sweep_triangle.points[std::size_t(j)];
        check_sweep_point(soup.positions[Index(3 * i + j)],
                          path[std::size_t(i)].position - stretch * p.x * radial + p.y * Vec3(0, 0, 1));
      }
    }
  }
}

TEST_CASE("out of a plane, Frenet normals follow each bend, rotation-minimising ones do not turn about T",
          "[scene]") {
  // Up, then along +x, then along +y: bends in the xz and then the xy plane, each a quarter turn.
  const std::vector<Vec3> points = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}};
  const double h = 1 / std::sqrt(2.0);
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const std::vector<Vec3> tangents = {z, h * (x + z), h * (x + y), y};
  const std::vector<Vec3> bends = {Vec3(0.0), h * (x - z), h * (y - x), Vec3(0.0)};
  // Frenet: towards each bend, carried over the straight ends. Rotation-minimising: the first normal
  // turned with the first bend about y, then carried across the second corner by the double reflection.
  const std::vector<Vec3> frenet = {x, h * (x - z), h * (y - x), -x};
  const std::vector<Vec3> minimal = {x, h * (x - z), (y - x - 4.0 * z) / (3 * std::sqrt(2.0)),
                                     (-x - 2 * std::sqrt(2.0) * z) / 3.0};
  std::vector<PathSample> path;
  for (const Vec3& p : points) path.push_back({p});
  const CrossSection axes{{{1, 0}, {0, 1}}, false};
  for (const FrameKind frames : {FrameKind::frenet, FrameKind::minimal_torsion}) {
    INFO("mintorsion " << (frames == FrameKind::minimal_torsion));
    const std::vector<Frame> f = path_frames(points, false, frames);
    SweepOptions o;
    o.frames = frames;
    const PolygonSoup soup = sweep(path, {&axes, 1}, o).piece.soup;
    const std::vector<Vec3>& expected = frames == FrameKind::frenet ? frenet : minimal;
    // The same path in a sweep statement, `mintorsion` or not.
    const Scene scene = Scene::from_text(
        "point a (0 0 0) endpoint\npoint b (0 0 1) endpoint\npoint c (1 0 1) endpoint\npoint d (1 1 1) "
        "endpoint\npoint e1 (1 0 0) endpoint\npoint e2 (0 1 0) endpoint\npolyline ax (e1 e2) endpolyline\n"
        "polyline pth (a b c d) endpolyline\nsweep s crosssection ax endcrosssection path pth " +
            std::string(frames == FrameKind::frenet ? "" : "mintorsion") +
            " endpath endsweep\ninstance i s endinstance\n",
        "t.nome");
    for (std::size_t i = 0; i < points.size(); ++i) {
      INFO("sample " << i);
      CHECK(glm::length(f[i].tangent - tangents[i]) < 1e-12);
      CHECK(glm::length(f[i].normal - expected[i]) < 1e-12);
      CHECK(glm::length(f[i].binormal - glm::cross(tangents[i], expected[i])) < 1e-12);
      CHECK(std::abs(glm::dot(f[i].normal, f[i].tangent)) < 1e-12);
      CHECK(std::abs(glm::length(f[i].normal) - 1) < 1e-12);
      // The section's axes: N and B, stretched by sqrt(2) across a quarter-turn bend.
      const double stretch = glm::length(bends[i]) > 0 ? std::sqrt(2.0) : 1;
      for (int j = 0; j < 2; ++j) {
        const Vec3 q = j == 0 ? expected[i] : glm::cross(tangents[i], expected[i]);
        const Vec3 placed = points[i] + q + (stretch - 1) * glm::dot(q, bends[i]) * bends[i];
        check_sweep_point(soup.positions[Index(2 * i + j)], placed);
        check_sweep_point(test::vertex_position(scene, "i_v" + std::to_string(i) + "_" + std::to_string(j)),
                          placed);
      }
    }
  }
}

TEST_CASE("around a closed knotted path rotation-minimising frames spread their turn evenly and join exactly",
          "[scene]") {
  // A trefoil: no mirror symmetry, so its rotation-minimising frame comes back turned.
  constexpr int n = 48;
  std::vector<Vec3> points;
  std::vector<PathSample> path;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * sweep_pi * i / n;
    points.emplace_back(std::cos(a) + 2 * std::cos(2 * a), std::sin(a) - 2 * std::sin(2 * a),
                        std::sin(3 * a));
    path.push_back({points.back()});
  }
  const std::vector<Frame> f = path_frames(points, true, FrameKind::minimal_torsion);
  REQUIRE(f.size() == n + 1);
  const double turn = std::atan2(glm::dot(f[n].normal, f[0].binormal), glm::dot(f[n].normal, f[0].normal));
  REQUIRE(std::abs(turn) > 0.05);
  SweepOptions o;
  o.frames = FrameKind::minimal_torsion;
  o.is_path_closed = true;
  const SweepResult r = sweep(path, {&sweep_triangle, 1}, o);
  CHECK(r.warnings.empty());
  for (int i = 0; i < n; ++i) {
    // Undo the turn a little at each sample, all of it back at the start; mitre across the bend.
    const Vec3 in = glm::normalize(points[std::size_t(i)] - points[std::size_t((i + n - 1) % n)]);
    const Vec3 out = glm::normalize(points[std::size_t((i + 1) % n)] - points[std::size_t(i)]);
    const Vec3 bend = glm::normalize(out - in);
    const double stretch = 1 / std::sqrt((1 + glm::dot(in, out)) / 2);
    for (int j = 0; j < 3; ++j) {
      INFO("sample " << i << ", point " << j);
      const Vec3 q = sweep_turned(sweep_triangle.points[std::size_t(j)], -turn * 180 / sweep_pi * i / n,
                                  f[std::size_t(i)].normal, f[std::size_t(i)].binormal);
      check_sweep_point(r.piece.soup.positions[Index(3 * i + j)],
                        points[std::size_t(i)] + q + (stretch - 1) * glm::dot(q, bend) * bend);
    }
  }
  CHECK(sweep_face(r.piece.soup, (n - 1) * 3) == std::vector<Index>{(n - 1) * 3, (n - 1) * 3 + 1, 1, 0});
}

TEST_CASE("a B-spline path blends its control points' scale and turn with the curve's basis", "[scene]") {
  const std::string text =
      std::string(sweep_triangle_text) +
      "point a (0 0 0) endpoint\npoint b (0 0 1) endpoint\npoint c (0 0 2) endpoint\npoint d (0 0 3) "
      "endpoint\npoint e (0 0 4) endpoint\n"
      "controlpoint cc point c scale (3 2 0) rotate (0 0 60) endcontrolpoint\n"
      "bspline p order 3 (a b cc d e) segs 6 endbspline\n"
      "sweep s crosssection tri endcrosssection path p endpath endsweep\ninstance i s endinstance\n";
  const Scene s = Scene::from_text(text, "t.nome");
  for (int k = 0; k <= 6; ++k) {
    const double t = 2 + 3.0 * k / 6;
    const double z = sweep_de_boor({0, 1, 2, 3, 4}, 2, t);
    const double sx = sweep_de_boor({1, 1, 3, 1, 1}, 2, t), sy = sweep_de_boor({1, 1, 2, 1, 1}, 2, t);
    const double turn = sweep_de_boor({0, 0, 60, 0, 0}, 2, t);
    for (int j = 0; j < 3; ++j) {
      INFO("sample " << k << ", point " << j);
      const glm::dvec2 p = sweep_triangle.points[std::size_t(j)];
      check_sweep_point(test::vertex_position(s, "i_v" + std::to_string(k) + "_" + std::to_string(j)),
                        sweep_on_z(z, {sx * p.x, sy * p.y}, turn));
    }
  }
}

TEST_CASE("sweepmorph blends the sections between the control points that give them, keeps them outside",
          "[scene]") {
  const std::string text =
      std::string(sweep_triangle_text) +
      "point u0 (2 0 0) endpoint\npoint u1 (0 1 0) endpoint\npoint u2 (-3 1 0) endpoint\n"
      "polyline other (u0 u1 u2) isloop endpolyline\n" +
      sweep_straight_points(6) +
      "controlpoint k1 point z1 crosssection tri endcontrolpoint\n"
      "controlpoint k4 point z4 crosssection other endcontrolpoint\n"
      "polyline p (z0 k1 z2 z3 k4 z5) endpolyline\n"
      "sweepmorph m path p twist (50) endpath endsweepmorph\ninstance i m endinstance\n"
      "morphvisualizer mv sweep m index (2) endmorphvisualizer\ninstance j mv endinstance\n";
  const Scene s = Scene::from_text(text, "t.nome");
  const std::vector<glm::dvec2> other = {{2, 0}, {0, 1}, {-3, 1}};
  const std::vector<double> weight = {0, 0, 1.0 / 3, 2.0 / 3, 1, 1};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 3; ++j) {
      INFO("sample " << i << ", point " << j);
      const glm::dvec2 p = (1 - weight[std::size_t(i)]) * sweep_triangle.points[std::size_t(j)] +
                           weight[std::size_t(i)] * other[std::size_t(j)];
      check_sweep_point(test::vertex_position(s, "i_v" + std::to_string(i) + "_" + std::to_string(j)),
                        sweep_on_z(0.5 * i, p, 50.0 * i / 5));
      if (i == 2) check_sweep_point(test::vertex_position(s, "j_c" + std::to_string(j)), Vec3(p.x, p.y, 0));
    }
}

TEST_CASE("sweepmorph along a Bézier path blends its end control points' sections by sample", "[scene]") {
  const std::string text =
      std::string(sweep_triangle_text) +
      "point u0 (2 0 0) endpoint\npoint u1 (0 1 0) endpoint\npoint u2 (-3 1 0) endpoint\n"
      "polyline other (u0 u1 u2) isloop endpolyline\n"
      "point a (0 0 0) endpoint\npoint b (0 0 1) endpoint\npoint c (0 0 2) endpoint\n"
      "controlpoint ka point a crosssection tri endcontrolpoint\n"
      "controlpoint kc point c crosssection other endcontrolpoint\n"
      "beziercurve p (ka b kc) segs 4 endbeziercurve\n"
      "sweepmorph m path p endpath endsweepmorph\ninstance i m endinstance\n";
  const Scene s = Scene::from_text(text, "t.nome");
  const std::vector<glm::dvec2> other = {{2, 0}, {0, 1}, {-3, 1}};
  for (int k = 0; k <= 4; ++k)
    for (int j = 0; j < 3; ++j) {
      INFO("sample " << k << ", point " << j);
      const double w = k / 4.0;
      const glm::dvec2 p = (1 - w) * sweep_triangle.points[std::size_t(j)] + w * other[std::size_t(j)];
      check_sweep_point(test::vertex_position(s, "i_v" + std::to_string(k) + "_" + std::to_string(j)),
                        sweep_on_z(2 * w, p, 0));
    }
}

TEST_CASE("a Bézier path blends its control points' scale by the Bernstein weights, its ends' scales too",
          "[scene]") {
  // A straight path along +z with unevenly spaced points, so the frame is known (N = +y, B = -x); every
  // control point scales x and y differently, the end points too (a Bézier curve passes through them).
  const std::string text = std::string(sweep_triangle_text) +
                           "point a (0 0 0) endpoint\npoint b (0 0 0.5) endpoint\npoint c (0 0 2) endpoint\n"
                           "point d (0 0 3) endpoint\n"
                           "controlpoint ka point a scale (0.5 2 0) endcontrolpoint\n"
                           "controlpoint kb point b scale (3 1 0) endcontrolpoint\n"
                           "controlpoint kd point d scale (1.5 0.25 0) endcontrolpoint\n"
                           "beziercurve p (ka kb c kd) segs 6 endbeziercurve\n"
                           "sweep s crosssection tri endcrosssection path p endpath endsweep\n"
                           "instance i s endinstance\n";
  const Scene s = Scene::from_text(text, "t.nome");
  for (int k = 0; k <= 6; ++k) {
    const double t = k / 6.0;
    const double z = sweep_bernstein({0, 0.5, 2, 3}, t);
    const double sx = sweep_bernstein({0.5, 3, 1, 1.5}, t), sy = sweep_bernstein({2, 1, 1, 0.25}, t);
    for (int j = 0; j < 3; ++j) {
      INFO("sample " << k << ", point " << j);
      const glm::dvec2 q = sweep_triangle.points[std::size_t(j)];
      check_sweep_point(test::vertex_position(s, "i_v" + std::to_string(k) + "_" + std::to_string(j)),
                        sweep_on_z(z, {sx * q.x, sy * q.y}, 0));
    }
  }
}
