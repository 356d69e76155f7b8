// Which side of each generator's faces is the front, in the successor's dialect: JIPCAD draws a face's
// corners in their order and Qt3D culls the clockwise side, so its front is the side from which the
// corners run counter-clockwise, as ours. Each expected side is worked out by hand from the vertex order of
// JIPCAD's generator (named in the test); the normals come from the faces' positions (right-hand rule).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "nome/scene/scene.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

constexpr double front_pi = 3.14159265358979323846;

// The one instance `i` of definition `g`, read in the successor's dialect.
Piece front_instance(const std::string& definition) {
  const Scene s =
      Scene::from_text(definition + "\ninstance i g endinstance\n", "t.nome", {.dialect = Dialect::jipcad});
  REQUIRE(s.instances().size() == 1);
  return s.instances()[0].geometry;
}

// Newell's normal of the polygon through `corners`, in their order.
Vec3 front_newell(const std::vector<Vec3>& corners) {
  Vec3 n(0);
  for (size_t k = 0; k < corners.size(); ++k) {
    const Vec3 a = corners[k], b = corners[(k + 1) % corners.size()];
    n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

std::vector<Vec3> front_corners(const PolygonSoup& soup, Index f) {
  std::vector<Vec3> corners;
  for (Index k = soup.face_offsets[f]; k < soup.face_offsets[f + 1]; ++k)
    corners.push_back(soup.positions[soup.face_vertices[k]]);
  return corners;
}

Vec3 front_centroid(const PolygonSoup& soup, Index f) {
  Vec3 c(0);
  for (const Vec3& p : front_corners(soup, f)) c += p;
  return c / double(soup.face_offsets[f + 1] - soup.face_offsets[f]);
}

Index front_face(const PolygonSoup& soup, const std::string& name) {
  for (Index f = 0; f < soup.num_faces(); ++f)
    if (soup.face_names[f] == name) return f;
  FAIL("no face " << name);
  return no_index;
}

Vec3 front_normal(const PolygonSoup& soup, const std::string& face) {
  return front_newell(front_corners(soup, front_face(soup, face)));
}

// (i, j) of a grid face named `i_f{i}_{j}`.
std::pair<int, int> front_grid_index(const std::string& name) {
  const size_t split = name.find('_', 3);
  return {std::stoi(name.substr(3, split - 3)), std::stoi(name.substr(split + 1))};
}

// Every face (from `first` to `end`) points away from the z axis.
void front_check_away_from_axis(const PolygonSoup& soup, Index first = 0, Index end = no_index) {
  for (Index f = first; f < std::min(end, soup.num_faces()); ++f) {
    INFO("face " << soup.face_names[f]);
    const Vec3 c = front_centroid(soup, f);
    CHECK(glm::dot(front_newell(front_corners(soup, f)), Vec3(c.x, c.y, 0)) > 0);
  }
}

// Every face of a surface around the origin points away from it.
void front_check_away_from_origin(const PolygonSoup& soup) {
  for (Index f = 0; f < soup.num_faces(); ++f) {
    INFO("face " << soup.face_names[f]);
    CHECK(glm::dot(front_newell(front_corners(soup, f)), front_centroid(soup, f)) > 0);
  }
}

// Every face of a tube around the circle of radius `major` in z = 0 points away from the circle.
void front_check_away_from_ring(const PolygonSoup& soup, double major) {
  for (Index f = 0; f < soup.num_faces(); ++f) {
    INFO("face " << soup.face_names[f]);
    const Vec3 c = front_centroid(soup, f);
    const Vec3 core = major * glm::normalize(Vec3(c.x, c.y, 0));
    CHECK(glm::dot(front_newell(front_corners(soup, f)), c - core) > 0);
  }
}

}  // namespace

// Sphere.cpp: quad (theta j, phi i), (j, i + 1), (j + 1, i + 1), (j + 1, i) with phi the angle from the north
// pole: d/dphi x d/dtheta = r^2 sin(phi) times the outward radius, outwards while sin(phi) > 0.
TEST_CASE("front side: a sphere's and an ellipsoid's faces point away from the centre", "[scene]") {
  front_check_away_from_origin(front_instance("sphere g (2 360 -60 90 8 5) endsphere").soup);
  front_check_away_from_origin(front_instance("sphere g (1 270 -90 45 6 4) endsphere").soup);
  front_check_away_from_origin(front_instance("ellipsoid g (2 1 360 -90 90 8 4) endellipsoid").soup);
}

// Past a pole JIPCAD's sweep goes on the same way, sin(phi) < 0: its faces there point inwards. Ours are
// turned over, so that the closed sphere is oriented one way, outwards as JIPCAD's first half.
TEST_CASE("front side: a sphere whose latitudes pass a pole faces out everywhere", "[scene]") {
  front_check_away_from_origin(front_instance("sphere g (1 180 0 360 10 10) endsphere").soup);
}

// Torus.cpp: the tube circle turns from the outward radius N towards B = T x N = -z at theta 0, and the quad
// (k + 1, next), (k + 1, i), (k, i), (k, next) turns from phi to theta: d/dphi x d/dtheta = (-z) x y = +x.
TEST_CASE("front side: a torus's faces point away from its tube's core, whole or partial", "[scene]") {
  front_check_away_from_ring(front_instance("torus g (3 1 360 0 360 8 6) endtorus").soup, 3);
  front_check_away_from_ring(front_instance("torus g (2 0.5 270 30 300 6 9) endtorus").soup, 2);
}

// TorusKnot.cpp: the same frame and quad as Torus.cpp's, so d/du x d/dt = B x T = N at u = 0, where the
// point lies N away from the curve.
TEST_CASE("front side: the (2,3) torus knot's tube faces away from its core curve", "[scene]") {
  // intro_files__Generators.nom's knot, thicker: symm 2 through the hole, turns 3 around z.
  const int segs = 120;
  const PolygonSoup soup = front_instance("torusknot g (2 3 2 0.5 0.2 8 120) endtorusknot").soup;
  REQUIRE(soup.num_faces() == 8 * segs);
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const std::string& name = soup.face_names[f];
    const double t = 2 * front_pi * (front_grid_index(name).first + 0.5) / segs;
    const double ring = 2 + 0.5 * std::cos(2 * t);
    const Vec3 core(ring * std::cos(3 * t), ring * std::sin(3 * t), 0.5 * std::sin(2 * t));
    INFO(name);
    CHECK(glm::dot(front_newell(front_corners(soup, f)), front_centroid(soup, f) - core) > 0);
  }
}

// Cylinder.cpp: mantle quad (top next, top c, bottom c, bottom next), counter-clockwise from outside; the
// bottom cap runs backwards around z (down), the top one forwards (up). Cone.cpp: (next, apex, this), out.
TEST_CASE("front side: cylinder and cone mantles face out, bottom caps down, top caps up", "[scene]") {
  const PolygonSoup can = front_instance("cylinder g (1 2 360 8 botcap topcap) endcylinder").soup;
  front_check_away_from_axis(can, 0, 8);
  CHECK(front_normal(can, "i_botcap").z < 0);
  CHECK(front_normal(can, "i_topcap").z > 0);
  const PolygonSoup cone = front_instance("cone g (1 2 0.5 360 8 botcap topcap) endcone").soup;
  front_check_away_from_axis(cone, 0, 8);
  CHECK(front_normal(cone, "i_botcap").z < 0);
  CHECK(front_normal(cone, "i_topcap").z > 0);
  const PolygonSoup pointed = front_instance("cone g (1 2 1 270 6 botcap) endcone").soup;
  front_check_away_from_axis(pointed, 0, 6);
  CHECK(front_normal(pointed, "i_botcap").z < 0);
}

// JIPCAD's reference gives the disk no side; ours faces +z, as the top cap of a cylinder.
TEST_CASE("front side: a disk faces +z", "[scene]") {
  const PolygonSoup soup = front_instance("disk g (1 300 5) enddisk").soup;
  REQUIRE(soup.num_faces() == 5);
  for (Index f = 0; f < soup.num_faces(); ++f) CHECK(front_newell(front_corners(soup, f)).z > 0);
}

// Funnel.cpp: (high next, high i, base i, base next); Tunnel.cpp: (high i, middle i, middle next, high next)
// and (middle i, low i, low next, middle next): counter-clockwise from outside, all of them.
TEST_CASE("front side: the successor's funnel and both halves of its tunnel face out", "[scene]") {
  const PolygonSoup funnel = front_instance("funnel g (1 0.5 1 8) endfunnel").soup;
  REQUIRE(funnel.num_faces() == 8);
  front_check_away_from_axis(funnel);
  const PolygonSoup narrowing = front_instance("funnel g (2 -0.5 1.5 6) endfunnel").soup;
  front_check_away_from_axis(narrowing);
  const PolygonSoup tunnel = front_instance("tunnel g (1 0.5 1 8) endtunnel").soup;
  REQUIRE(tunnel.num_faces() == 16);
  front_check_away_from_axis(tunnel);
}

// MobiusStrip.cpp: quad (u, v), (u + 1, v), (u + 1, v + 1), (u, v + 1) with v across the band from its inner
// edge: at u = 0, d/du x d/dv = y x x = -z.
TEST_CASE("front side: the successor's mobiusstrip faces -z where it starts", "[scene]") {
  CHECK(front_normal(front_instance("mobiusstrip g (1 1 0 12) endmobiusstrip").soup, "i_f0_0").z < 0);
  const PolygonSoup cut = front_instance("mobiusstrip g (1 2 1 12) endmobiusstrip").soup;
  CHECK(front_normal(cut, "i_f0_0").z < 0);
  CHECK(front_normal(cut, "i_f0_1").z < 0);
}

// Dupin.cpp: triangles (i, j), (i + 1, j), (i, j + 1) and (i, j + 1), (i + 1, j), (i + 1, j + 1), d/du x
// d/dv: away from the centre of the v circle, for the ring cyclide of
// param_surf__genParametricSurfExample.nom.
TEST_CASE("front side: a Dupin cyclide's faces point away from its tube's core", "[scene]") {
  auto cyclide = [](double u, double v) {
    const double a = 1, b = 0.98, c = 0.2, d = 0.5, den = a - c * std::cos(u) * std::cos(v);
    return Vec3((d * (c - a * std::cos(u) * std::cos(v)) + b * b * std::cos(u)) / den,
                b * std::sin(u) * (a - d * std::cos(v)) / den, b * std::sin(v) * (c * std::cos(u) - d) / den);
  };
  const int segs = 24;
  const PolygonSoup soup = front_instance("dupin g (1 0.98 0.2 0.5 2 2 24) enddupin").soup;
  REQUIRE(soup.num_faces() == segs * segs);
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const std::string& name = soup.face_names[f];
    const double u = 2 * front_pi * (front_grid_index(name).first + 0.5) / segs;
    const Vec3 core = 0.5 * (cyclide(u, 0) + cyclide(u, front_pi));
    INFO(name);
    CHECK(glm::dot(front_newell(front_corners(soup, f)), front_centroid(soup, f) - core) > 0);
  }
}

// Hyperboloid.cpp: triangles (i, z), (i + 1, z), (i, z + 1) and (i, z + 1), (i + 1, z), (i + 1, z + 1),
// d/dtheta x d/dz: away from the axis, on one sheet and on both of two.
TEST_CASE("front side: the successor's hyperboloids face away from their axis", "[scene]") {
  front_check_away_from_axis(front_instance("hyperboloid g (12 1 1 3 0 2) endhyperboloid").soup);
  front_check_away_from_axis(front_instance("hyperboloid g (12 1 2 3 1 2) endhyperboloid").soup);
  front_check_away_from_axis(front_instance("hyperboloid g (8 1.5 1 2 0 1) endhyperboloid").soup);
}

// GenCartesianSurf.cpp: quad (x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1): up.
TEST_CASE("front side: gencartesiansurf faces up", "[scene]") {
  const PolygonSoup soup =
      front_instance("gencartesiansurf g func [x*y-x^2] (-1 1 -1 1 4 3) endgencartesiansurf").soup;
  REQUIRE(soup.num_faces() == 12);
  for (Index f = 0; f < soup.num_faces(); ++f) CHECK(front_newell(front_corners(soup, f)).z > 0);
}

// GenParametricSurf.cpp: quad (u, v), (u + 1, v), (u + 1, v + 1), (u, v + 1), its normal d/du x d/dv. The
// expected normal of each face is that quad's, on the closed form.
TEST_CASE("front side: genparametricsurf turns from u to v, as JIPCAD's", "[scene]") {
  // param_surf__genParametricSurfExample.nom's torus knot (2,3), coarser: a sheet from the origin out to the
  // knot, whose front is its underside in JIPCAD as here.
  auto knot_sheet = [](double u, double v) {
    return Vec3(std::sin(v) * (2 + std::cos(3 * u)) * std::cos(2 * u),
                std::sin(v) * (2 + std::cos(3 * u)) * std::sin(2 * u),
                std::sin(v) * std::cos(v) * std::sin(3 * u));
  };
  const int u_segs = 24, v_segs = 6;
  const PolygonSoup sheet = front_instance(
                                "genparametricsurf g funcX [sin(v)*(2+cos(3*u))*cos(2*u)] "
                                "funcY [sin(v)*(2+cos(3*u))*sin(2*u)] funcZ [sin(v)*cos(v)*(sin(3*u))] "
                                "(0 6.28318 0 1.0472 24 6) endgenparametricsurf")
                                .soup;
  REQUIRE(sheet.num_faces() == u_segs * v_segs);
  for (Index f = 0; f < sheet.num_faces(); ++f) {
    const auto [i, j] = front_grid_index(sheet.face_names[f]);
    auto at = [&](int di, int dj) {
      return knot_sheet(6.28318 * (i + di) / u_segs, 1.0472 * (j + dj) / v_segs);
    };
    const Vec3 jipcad = front_newell({at(0, 0), at(1, 0), at(1, 1), at(0, 1)});
    INFO(sheet.face_names[f]);
    CHECK(jipcad.z < 0);
    CHECK(glm::dot(front_newell(front_corners(sheet, f)), jipcad) > 0);
  }
  // A torus written as a parametric surface, u around z and v around the tube: away from the tube's core.
  front_check_away_from_ring(front_instance("genparametricsurf g funcX [(2+cos(v))*cos(u)] "
                                            "funcY [(2+cos(v))*sin(u)] funcZ [sin(v)] "
                                            "(0 6.28318 0 6.28318 12 8) endgenparametricsurf")
                                 .soup,
                             2);
}

// GenImplicitSurf.cpp: marching cubes with f <= 0 inside, each of Bourke's triangles reversed: towards f > 0.
TEST_CASE("front side: genimplicitsurf faces where f > 0", "[scene]") {
  const PolygonSoup plane =
      front_instance("genimplicitsurf g func [z-0.3] (-1 1 -1 1 -1 1 4 4 4) endgenimplicitsurf").soup;
  REQUIRE(plane.num_faces() > 0);
  for (Index f = 0; f < plane.num_faces(); ++f) CHECK(front_newell(front_corners(plane, f)).z > 0);
  front_check_away_from_origin(
      front_instance(
          "genimplicitsurf g func [x^2+y^2+z^2-1] (-1.5 1.5 -1.5 1.5 -1.5 1.5 7 8 9) endgenimplicitsurf")
          .soup);
}
