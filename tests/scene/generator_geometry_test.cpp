// Every generator's vertices against its closed form, written out here from the language references (the
// 2016 report's funnel and tunnel; JIPCAD's reference for the others), with the faces' orientation: the
// expected positions never come from the kernel.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "nome/scene/generators.hpp"
#include "nome/scene/scene.hpp"
#include "support/mesh_measures.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

constexpr double geom_pi = 3.14159265358979323846;

double geom_rad(double degrees) {
  return degrees * geom_pi / 180;
}

using GeomExpected = std::vector<std::pair<std::string, Vec3>>;

// The piece has exactly the vertices the oracle lists, each (prefixed, as an instance names it) within
// 1e-9 of where the oracle puts it.
void geom_check_vertices(const Piece& piece, const GeomExpected& expected, const std::string& prefix = "") {
  REQUIRE(piece.soup.num_vertices() == expected.size());
  std::map<std::string, Vec3> by_name;
  for (Index v = 0; v < piece.soup.num_vertices(); ++v)
    by_name[piece.soup.vertex_names[v]] = piece.soup.positions[v];
  for (const auto& [name, p] : expected) {
    INFO(prefix + name << " expected at (" << p.x << ", " << p.y << ", " << p.z << ")");
    const auto it = by_name.find(prefix + name);
    REQUIRE(it != by_name.end());
    INFO("found at (" << it->second.x << ", " << it->second.y << ", " << it->second.z << ")");
    CHECK(glm::length(it->second - p) <= 1e-9 * (1 + glm::length(p)));
  }
}

// The one instance `i` of definition `g` written by `definition`, in a file of the given name.
Piece geom_instance(const std::string& definition, const std::string& file = "t.nome",
                    const SceneOptions& options = {}) {
  const Scene s = Scene::from_text(definition + "\ninstance i g endinstance\n", file, options);
  REQUIRE(s.instances().size() == 1);
  return s.instances()[0].geometry;
}

// Newell's normal of face f (any polygon, planar or not).
Vec3 geom_normal(const PolygonSoup& soup, Index f) {
  Vec3 n(0);
  const Index first = soup.face_offsets[f], end = soup.face_offsets[f + 1];
  for (Index c = first; c < end; ++c) {
    const Vec3 a = soup.positions[soup.face_vertices[c]];
    const Vec3 b = soup.positions[soup.face_vertices[c + 1 == end ? first : c + 1]];
    n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

Index geom_face(const PolygonSoup& soup, const std::string& name) {
  for (Index f = 0; f < soup.num_faces(); ++f)
    if (soup.face_names[f] == name) return f;
  FAIL("no face " << name);
  return no_index;
}

// The corner names of face f, in order.
std::vector<std::string> geom_corners(const PolygonSoup& soup, Index f) {
  std::vector<std::string> names;
  for (Index k = soup.face_offsets[f]; k < soup.face_offsets[f + 1]; ++k)
    names.push_back(soup.vertex_names[soup.face_vertices[k]]);
  return names;
}

// The same cyclic sequence, from any start.
bool geom_same_cycle(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  if (a.size() != b.size()) return false;
  for (size_t s = 0; s < a.size(); ++s) {
    bool is_same = true;
    for (size_t k = 0; k < a.size() && is_same; ++k) is_same = a[(s + k) % a.size()] == b[k];
    if (is_same) return true;
  }
  return false;
}

// A circle of n vertices NAME0.. of radius r at height z, vertex k at 360 k / n degrees from +x.
void geom_add_ring(GeomExpected& out, const std::string& prefix, int n, double r, double z) {
  for (int k = 0; k < n; ++k)
    out.push_back({prefix + std::to_string(k),
                   {r * std::cos(2 * geom_pi * k / n), r * std::sin(2 * geom_pi * k / n), z}});
}

// Every face's normal points away from the z axis.
void geom_check_faces_face_away_from_axis(const PolygonSoup& soup, Index first = 0, Index end = no_index) {
  for (Index f = first; f < std::min(end, soup.num_faces()); ++f) {
    INFO("face " << soup.face_names[f]);
    const Vec3 c = test::face_centre(soup, f);
    CHECK(glm::dot(geom_normal(soup, f), Vec3(c.x, c.y, 0)) > 0);
  }
}

}  // namespace

TEST_CASE("funnel (n ro ratio h): the report's base and high circles, faces between them", "[scene]") {
  const Piece p = geom_instance("funnel g (6 1.5 0.4 2) endfunnel");
  GeomExpected expected;
  geom_add_ring(expected, "bc", 6, 1.5, 0);
  geom_add_ring(expected, "hc", 6, 1.5 * 1.4, 2);
  geom_check_vertices(p, expected, "i_");
  REQUIRE(p.soup.num_faces() == 6);
  for (int k = 0; k < 6; ++k) {
    const std::string a = std::to_string(k), b = std::to_string((k + 1) % 6);
    const Index f = geom_face(p.soup, "i_f" + a);
    CHECK(geom_same_cycle(geom_corners(p.soup, f), {"i_bc" + a, "i_bc" + b, "i_hc" + b, "i_hc" + a}));
  }
  geom_check_faces_face_away_from_axis(p.soup);
  // A negative ratio narrows the high circle.
  GeomExpected narrow;
  geom_add_ring(narrow, "bc", 4, 2, 0);
  geom_add_ring(narrow, "hc", 4, 2 * 0.75, -1);
  geom_check_vertices(geom_instance("funnel g (4 2 -0.25 -1) endfunnel"), narrow, "i_");
}

TEST_CASE("tunnel: the low circle mirrors the high one, or takes ratio_low and h_low", "[scene]") {
  GeomExpected symmetric;
  geom_add_ring(symmetric, "bc", 5, 1, 0);
  geom_add_ring(symmetric, "hc", 5, 1.5, 2);
  geom_add_ring(symmetric, "lc", 5, 1.5, -2);
  const Piece s = geom_instance("tunnel g (5 1 0.5 2) endtunnel");
  geom_check_vertices(s, symmetric, "i_");
  CHECK(s.soup.num_faces() == 10);
  geom_check_faces_face_away_from_axis(s.soup);

  GeomExpected lopsided;
  geom_add_ring(lopsided, "bc", 5, 1, 0);
  geom_add_ring(lopsided, "hc", 5, 1.5, 2);
  geom_add_ring(lopsided, "lc", 5, 1.25, -0.75);
  const Piece l = geom_instance("tunnel g (5 1 0.5 2 0.25 0.75) endfunnel");
  geom_check_vertices(l, lopsided, "i_");
  geom_check_faces_face_away_from_axis(l.soup);
  // The lower funnel's faces join the low circle to the base circle.
  const Index lf = geom_face(l.soup, "i_lf1");
  CHECK(geom_same_cycle(geom_corners(l.soup, lf), {"i_lc1", "i_lc2", "i_bc2", "i_bc1"}));
}

TEST_CASE("circle (n r) is a loop of n vertices on the circle of radius r, in order", "[scene]") {
  const Piece p = geom_instance("circle g (7 2.5) endcircle");
  GeomExpected expected;
  geom_add_ring(expected, "c", 7, 2.5, 0);
  geom_check_vertices(p, expected, "i_");
  REQUIRE(p.rims.size() == 1);
  CHECK(p.rims[0].is_loop);
  REQUIRE(p.rims[0].vertices.size() == 7);
  for (Index k = 0; k < 7; ++k)
    CHECK(p.soup.vertex_names[p.rims[0].vertices[k]] == "i_c" + std::to_string(k));
  // In the report's dialect the count comes first even when the radius is a whole number too.
  GeomExpected whole_radius;
  geom_add_ring(whole_radius, "c", 8, 3, 0);
  geom_check_vertices(geom_instance("circle g (8 3) endcircle"), whole_radius, "i_");
}

TEST_CASE("cylinder: circles of its radius at 0 and its height, caps facing out", "[scene]") {
  const Piece whole = geom_instance("cylinder g (1.5 2 360 6 topcap botcap) endcylinder");
  GeomExpected expected;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 2; ++j)
      expected.push_back({"v" + std::to_string(i) + "_" + std::to_string(j),
                          {1.5 * std::cos(geom_rad(60 * i)), 1.5 * std::sin(geom_rad(60 * i)), 2.0 * j}});
  geom_check_vertices(whole, expected, "i_");
  REQUIRE(whole.soup.num_faces() == 8);
  geom_check_faces_face_away_from_axis(whole.soup, 0, 6);
  const Index bottom = geom_face(whole.soup, "i_botcap"), top = geom_face(whole.soup, "i_topcap");
  CHECK(geom_normal(whole.soup, bottom).z < 0);
  CHECK(geom_normal(whole.soup, top).z > 0);
  CHECK(geom_corners(whole.soup, top).size() == 6);

  // A wedge of 270 degrees in 3 segments: four columns 90 degrees apart, pies through the axis.
  const Piece wedge = geom_instance("cylinder g (2 0.5 270 3 botcap topcap) endcylinder");
  GeomExpected wedge_expected{{"bottom", {0, 0, 0}}, {"top", {0, 0, 0.5}}};
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j < 2; ++j)
      wedge_expected.push_back({"v" + std::to_string(i) + "_" + std::to_string(j),
                                {2 * std::cos(geom_rad(90 * i)), 2 * std::sin(geom_rad(90 * i)), 0.5 * j}});
  geom_check_vertices(wedge, wedge_expected, "i_");
  geom_check_faces_face_away_from_axis(wedge.soup, 0, 3);
  CHECK(geom_normal(wedge.soup, geom_face(wedge.soup, "i_botcap")).z < 0);
  CHECK(geom_normal(wedge.soup, geom_face(wedge.soup, "i_topcap")).z > 0);
  CHECK(geom_corners(wedge.soup, geom_face(wedge.soup, "i_topcap")).size() == 5);

  // One cap, either one: the one named, at its own end.
  for (const char* cap : {"botcap", "topcap"}) {
    INFO(cap);
    const Piece one = geom_instance("cylinder g (1 3 360 5 " + std::string(cap) + ") endcylinder");
    REQUIRE(one.soup.num_faces() == 6);
    CHECK(one.soup.face_names[5] == "i_" + std::string(cap));
    const double z = std::string(cap) == "topcap" ? 3 : 0;
    for (const std::string& corner : geom_corners(one.soup, 5)) CHECK(corner.back() == (z > 0 ? '1' : '0'));
    CHECK(test::face_centre(one.soup, 5).z == Approx(z));
  }
}

TEST_CASE("cone: base radius at 0, cut at hgt_max of its height with the radius shrunk to match", "[scene]") {
  // Radius 2, height 3, cut at 0.25 of the height: the top circle at z = 0.75 has radius 1.5.
  const Piece cut = geom_instance("cone g (2 3 0.25 360 8 botcap topcap) endcone");
  GeomExpected expected;
  for (int i = 0; i < 8; ++i) {
    const double a = geom_rad(45 * i);
    expected.push_back({"v" + std::to_string(i) + "_0", {2 * std::cos(a), 2 * std::sin(a), 0}});
    expected.push_back({"v" + std::to_string(i) + "_1", {1.5 * std::cos(a), 1.5 * std::sin(a), 0.75}});
  }
  geom_check_vertices(cut, expected, "i_");
  geom_check_faces_face_away_from_axis(cut.soup, 0, 8);
  CHECK(geom_normal(cut.soup, geom_face(cut.soup, "i_topcap")).z > 0);

  GeomExpected pointed{{"apex", {0, 0, 3}}};
  for (int i = 0; i < 5; ++i)
    pointed.push_back(
        {"v" + std::to_string(i) + "_0", {std::cos(geom_rad(72 * i)), std::sin(geom_rad(72 * i)), 0}});
  const Piece apex = geom_instance("cone g (1 3 1 360 5 botcap) endcone");
  geom_check_vertices(apex, pointed, "i_");
  geom_check_faces_face_away_from_axis(apex.soup, 0, 5);
}

TEST_CASE("disk: a fan of theta_segs triangles from the centre, facing +z", "[scene]") {
  const Piece wedge = geom_instance("disk g (2 270 3) enddisk");
  GeomExpected expected{{"centre", {0, 0, 0}}};
  for (int i = 0; i <= 3; ++i)
    expected.push_back({"v" + std::to_string(i) + "_0",
                        {2 * std::cos(geom_rad(90 * i)), 2 * std::sin(geom_rad(90 * i)), 0}});
  geom_check_vertices(wedge, expected, "i_");
  REQUIRE(wedge.soup.num_faces() == 3);
  for (Index f = 0; f < 3; ++f) CHECK(geom_normal(wedge.soup, f).z > 0);

  GeomExpected whole_expected{{"centre", {0, 0, 0}}};
  for (int i = 0; i < 5; ++i)
    whole_expected.push_back({"v" + std::to_string(i) + "_0",
                              {0.5 * std::cos(geom_rad(72 * i)), 0.5 * std::sin(geom_rad(72 * i)), 0}});
  const Piece whole = geom_instance("disk g (0.5 360 5) enddisk");
  geom_check_vertices(whole, whole_expected, "i_");
  REQUIRE(whole.soup.num_faces() == 5);
  for (Index f = 0; f < 5; ++f) CHECK(geom_normal(whole.soup, f).z > 0);
}

TEST_CASE("sphere: a globe of latitude and longitude lines, poles single, faces outwards", "[scene]") {
  SphereParams p;
  p.radius = p.radius_z = 2;
  p.longitude_segs = 6;
  p.latitude_segs = 4;
  GeomExpected expected{{"south", {0, 0, -2}}, {"north", {0, 0, 2}}};
  for (int i = 0; i < 6; ++i)
    for (int j = 1; j < 4; ++j) {
      const double lon = geom_rad(60 * i), lat = geom_rad(-90 + 45 * j);
      expected.push_back(
          {"v" + std::to_string(i) + "_" + std::to_string(j),
           {2 * std::cos(lat) * std::cos(lon), 2 * std::cos(lat) * std::sin(lon), 2 * std::sin(lat)}});
    }
  const Piece globe = sphere(p);
  geom_check_vertices(globe, expected);
  REQUIRE(globe.soup.num_faces() == 24);
  for (Index f = 0; f < globe.soup.num_faces(); ++f)
    CHECK(glm::dot(geom_normal(globe.soup, f), test::face_centre(globe.soup, f)) > 0);

  // Cut to longitudes [0, 270] and latitudes [-30, 60]: no pole, every sample its own vertex.
  SphereParams cut = p;
  cut.longitude_max = 270;
  cut.latitude_min = -30;
  cut.latitude_max = 60;
  cut.longitude_segs = 3;
  cut.latitude_segs = 3;
  GeomExpected cut_expected;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) {
      const double lon = geom_rad(90 * i), lat = geom_rad(-30 + 30 * j);
      cut_expected.push_back(
          {"v" + std::to_string(i) + "_" + std::to_string(j),
           {2 * std::cos(lat) * std::cos(lon), 2 * std::cos(lat) * std::sin(lon), 2 * std::sin(lat)}});
    }
  const Piece patch = sphere(cut);
  geom_check_vertices(patch, cut_expected);
  for (Index f = 0; f < patch.soup.num_faces(); ++f)
    CHECK(glm::dot(geom_normal(patch.soup, f), test::face_centre(patch.soup, f)) > 0);
}

TEST_CASE("ellipsoid (radius_x radius_y long_max latt_min latt_max segs_long segs_latt)", "[scene]") {
  const Piece p = geom_instance("ellipsoid g (3 0.5 180 -60 90 4 5) endellipsoid");
  GeomExpected expected{{"north", {0, 0, 0.5}}};
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j < 5; ++j) {
      const double lon = geom_rad(45 * i), lat = geom_rad(-60 + 30 * j);
      expected.push_back(
          {"v" + std::to_string(i) + "_" + std::to_string(j),
           {3 * std::cos(lat) * std::cos(lon), 3 * std::cos(lat) * std::sin(lon), 0.5 * std::sin(lat)}});
    }
  geom_check_vertices(p, expected, "i_");
}

TEST_CASE("torus: the minor circle from phi_min to phi_max swept theta_max around z", "[scene]") {
  auto torus_point = [](double major, double minor, double theta, double phi) {
    const double ring = major + minor * std::cos(geom_rad(phi));
    return Vec3(ring * std::cos(geom_rad(theta)), ring * std::sin(geom_rad(theta)),
                minor * std::sin(geom_rad(phi)));
  };
  GeomExpected whole;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 6; ++j)
      whole.push_back({"v" + std::to_string(i) + "_" + std::to_string(j), torus_point(3, 1, 45 * i, 60 * j)});
  const Piece ring = geom_instance("torus g (3 1 360 0 360 8 6) endtorus");
  geom_check_vertices(ring, whole, "i_");
  REQUIRE(ring.soup.num_faces() == 48);
  for (Index f = 0; f < ring.soup.num_faces(); ++f) {
    // Away from the centre of the tube's circle under the face.
    const Vec3 c = test::face_centre(ring.soup, f);
    const Vec3 axis = 3.0 * glm::normalize(Vec3(c.x, c.y, 0));
    CHECK(glm::dot(geom_normal(ring.soup, f), c - axis) > 0);
  }
  // The older six arguments (segs_phi rad_maj rad_min theta_max phi_max segs_theta): the same torus.
  geom_check_vertices(geom_instance("torus g (6 3 1 360 360 8) endtorus"), whole, "i_");

  // A half torus of a band of the tube: theta in [0, 180] in 4, phi in [30, 270] in 4.
  GeomExpected part;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j)
      part.push_back(
          {"v" + std::to_string(i) + "_" + std::to_string(j), torus_point(2, 0.5, 45 * i, 30 + 60 * j)});
  geom_check_vertices(geom_instance("torus g (2 0.5 180 30 270 4 4) endtorus"), part, "i_");
}

TEST_CASE("torus knot: its curve on the torus winding symm times through the hole, turns around z",
          "[scene]") {
  // (p, q) = (symm, turns): c(t) = ((R + r cos pt) cos qt, (R + r cos pt) sin qt, r sin pt).
  struct Knot {
    int p, q;
    double major, minor;
    Vec3 at(double t) const {
      const double ring = major + minor * std::cos(p * t);
      return {ring * std::cos(q * t), ring * std::sin(q * t), minor * std::sin(p * t)};
    }
    Vec3 tangent(double t) const {
      const double ring = major + minor * std::cos(p * t), dring = -minor * p * std::sin(p * t);
      return {dring * std::cos(q * t) - ring * q * std::sin(q * t),
              dring * std::sin(q * t) + ring * q * std::cos(q * t), minor * p * std::cos(p * t)};
    }
  };
  for (const Knot k : {Knot{3, 2, 3, 1.5}, Knot{-2, 5, 2, 0.5}, Knot{2, 3, 2.5, 1}}) {
    INFO("symm " << k.p << ", turns " << k.q);
    const std::string args = std::to_string(k.p) + " " + std::to_string(k.q) + " " + std::to_string(k.major) +
                             " " + std::to_string(k.minor);
    GeomExpected curve;
    for (int i = 0; i < 30; ++i) curve.push_back({"v" + std::to_string(i), k.at(2 * geom_pi * i / 30)});
    const Piece line = geom_instance("torusknot g (" + args + " 0 6 30) endtorusknot");
    geom_check_vertices(line, curve, "i_");
    REQUIRE(line.rims.size() == 1);
    CHECK(line.rims[0].is_loop);

    // The tube: each ring of circle_segs vertices tube_radius from its curve point, square to the curve.
    const Piece tube = geom_instance("torusknot g (" + args + " 0.25 5 30) endtorusknot");
    REQUIRE(tube.soup.num_vertices() == 150);
    std::map<std::string, Vec3> by_name;
    for (Index v = 0; v < tube.soup.num_vertices(); ++v)
      by_name[tube.soup.vertex_names[v]] = tube.soup.positions[v];
    for (int i = 0; i < 30; ++i) {
      const double t = 2 * geom_pi * i / 30;
      const Vec3 tangent = glm::normalize(k.tangent(t));
      for (int j = 0; j < 5; ++j) {
        const Vec3 d = by_name.at("i_v" + std::to_string(i) + "_" + std::to_string(j)) - k.at(t);
        CHECK(glm::length(d) == Approx(0.25).epsilon(1e-9));
        CHECK(std::abs(glm::dot(d, tangent)) < 1e-9);
      }
    }
    // Faces point away from the curve.
    for (Index f = 0; f < tube.soup.num_faces(); ++f) {
      const std::string& name = tube.soup.face_names[f];
      const int i = std::stoi(name.substr(3, name.find('_', 3) - 3));
      const Vec3 middle = 0.5 * (k.at(2 * geom_pi * i / 30) + k.at(2 * geom_pi * (i + 1) / 30));
      INFO(name);
      CHECK(glm::dot(geom_normal(tube.soup, f), test::face_centre(tube.soup, f) - middle) > 0);
    }
  }
}

TEST_CASE("helix: radius, rise per radian and theta_max in degrees over segs segments", "[scene]") {
  GeomExpected expected;
  for (int i = 0; i <= 12; ++i) {
    const double a = geom_rad(450.0 * i / 12);
    expected.push_back({"v" + std::to_string(i), {2 * std::cos(a), 2 * std::sin(a), 0.5 * a}});
  }
  const Piece h = geom_instance("helix g (2 0.5 450 12) endhelix");
  geom_check_vertices(h, expected, "i_");
  REQUIRE(h.rims.size() == 1);
  CHECK_FALSE(h.rims[0].is_loop);
  REQUIRE(h.rims[0].vertices.size() == 13);
  for (Index k = 0; k < 13; ++k)
    CHECK(h.soup.vertex_names[h.rims[0].vertices[k]] == "i_v" + std::to_string(k));
  // A negative angle turns the other way, a negative rise goes down.
  GeomExpected backwards;
  for (int i = 0; i <= 4; ++i) {
    const double a = geom_rad(-360.0 * i / 4);
    backwards.push_back({"v" + std::to_string(i), {std::cos(a), std::sin(a), -0.25 * a}});
  }
  geom_check_vertices(geom_instance("helix g (1 -0.25 -360 4) endhelix"), backwards, "i_");
}

TEST_CASE("spiral: an Archimedean spiral from the origin, rate more radius per turn", "[scene]") {
  GeomExpected expected;
  for (int i = 0; i <= 10; ++i) {
    const double degrees = 900.0 * i / 10;
    const double r = 1.5 * degrees / 360;
    expected.push_back(
        {"v" + std::to_string(i), {r * std::cos(geom_rad(degrees)), r * std::sin(geom_rad(degrees)), 0}});
  }
  const Piece s = geom_instance("spiral g (1.5 900 10) endspiral");
  geom_check_vertices(s, expected, "i_");
  REQUIRE(s.rims.size() == 1);
  CHECK_FALSE(s.rims[0].is_loop);
  CHECK(s.rims[0].vertices.size() == 11);
}

TEST_CASE("hyperboloid of one sheet, paraboloid and two sheets by their formulas", "[scene]") {
  HyperboloidParams p;
  p.a = 1.5;
  p.c = 0.5;
  p.u_max = 1.2;
  p.u_segs = 4;
  p.v_segs = 6;
  GeomExpected one;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j <= 4; ++j) {
      const double u = -1.2 + 2.4 * j / 4, v = 2 * geom_pi * i / 6;
      one.push_back(
          {"v" + std::to_string(i) + "_" + std::to_string(j),
           {1.5 * std::cosh(u) * std::cos(v), 1.5 * std::cosh(u) * std::sin(v), 0.5 * std::sinh(u)}});
    }
  const Piece sheet = hyperboloid(p);
  geom_check_vertices(sheet, one);
  geom_check_faces_face_away_from_axis(sheet.soup);

  p.sheet = HyperboloidSheet::paraboloid;
  GeomExpected bowl{{"apex", {0, 0, 0}}};
  for (int i = 0; i < 6; ++i)
    for (int j = 1; j <= 4; ++j) {
      const double u = 1.2 * j / 4, v = 2 * geom_pi * i / 6;
      bowl.push_back({"v" + std::to_string(i) + "_" + std::to_string(j),
                      {1.5 * u * std::cos(v), 1.5 * u * std::sin(v), 0.5 * u * u}});
    }
  const Piece paraboloid = hyperboloid(p);
  geom_check_vertices(paraboloid, bowl);
  // A bowl's faces point away from its inside: down.
  for (Index f = 0; f < paraboloid.soup.num_faces(); ++f) CHECK(geom_normal(paraboloid.soup, f).z < 0);

  p.sheet = HyperboloidSheet::two;
  GeomExpected two{{"top_apex", {0, 0, 0.5}}, {"bottom_apex", {0, 0, -0.5}}};
  for (const double side : {1.0, -1.0})
    for (int i = 0; i < 6; ++i)
      for (int j = 1; j <= 4; ++j) {
        const double u = 1.2 * j / 4, v = 2 * geom_pi * i / 6;
        two.push_back({(side > 0 ? "top_v" : "bottom_v") + std::to_string(i) + "_" + std::to_string(j),
                       {1.5 * std::sinh(u) * std::cos(v), 1.5 * std::sinh(u) * std::sin(v),
                        side * 0.5 * std::cosh(u)}});
      }
  const Piece sheets = hyperboloid(p);
  geom_check_vertices(sheets, two);
  // The two sheets are mirror images, faces included: a face's normal mirrors its twin's.
  REQUIRE(sheets.soup.num_faces() % 2 == 0);
  const Index half = sheets.soup.num_faces() / 2;
  for (Index f = 0; f < half; ++f) {
    const Vec3 top = geom_normal(sheets.soup, f), bottom = geom_normal(sheets.soup, f + half);
    CHECK(top.z < 0);  // away from the inside of the upper bowl
    CHECK(glm::length(Vec3(top.x, top.y, -top.z) - bottom) < 1e-9);
  }
}

TEST_CASE("dupin (a b c d u v segs): the cyclide's formula over u and v given in multiples of pi",
          "[scene]") {
  auto cyclide = [](double a, double b, double c, double d, double u, double v) {
    const double den = a - c * std::cos(u) * std::cos(v);
    return Vec3((d * (c - a * std::cos(u) * std::cos(v)) + b * b * std::cos(u)) / den,
                b * std::sin(u) * (a - d * std::cos(v)) / den, b * std::sin(v) * (c * std::cos(u) - d) / den);
  };
  GeomExpected whole;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      whole.push_back({"v" + std::to_string(i) + "_" + std::to_string(j),
                       cyclide(1, 0.98, 0.2, 0.5, 2 * geom_pi * i / 6, 2 * geom_pi * j / 6)});
  geom_check_vertices(geom_instance("dupin g (1 0.98 0.2 0.5 2 2 6) enddupin"), whole, "i_");

  // Half a turn of u, a quarter of v, other constants: every sample its own vertex.
  GeomExpected part;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j)
      part.push_back({"v" + std::to_string(i) + "_" + std::to_string(j),
                      cyclide(2, 1.5, 0.6, 0.3, geom_pi * i / 4, 0.5 * geom_pi * j / 4)});
  geom_check_vertices(geom_instance("dupin g (2 1.5 0.6 0.3 1 0.5 4) enddupin"), part, "i_");
}

TEST_CASE("mobius strip (radius twists cuts segs): a band half as wide as its radius, half-twisted",
          "[scene]") {
  // Ring i at 360 i / segs degrees; across it, from -radius/4 to radius/4 in cuts steps, along the radial
  // direction turned by twists * 180 i / segs degrees up towards +z.
  auto strip = [](double radius, int twists, int cuts, int segs) {
    GeomExpected out;
    for (int i = 0; i < segs; ++i) {
      const double around = 2 * geom_pi * i / segs, turn = geom_pi * twists * i / segs;
      const Vec3 radial(std::cos(around), std::sin(around), 0);
      const Vec3 across = std::cos(turn) * radial + Vec3(0, 0, std::sin(turn));
      for (int j = 0; j <= cuts; ++j)
        out.push_back({"v" + std::to_string(i) + "_" + std::to_string(j),
                       radius * radial + (-radius / 4 + radius / 2 * j / cuts) * across});
    }
    return out;
  };
  const Piece band = geom_instance("mobiusstrip g (2 1 2 8) endmobiusstrip");
  geom_check_vertices(band, strip(2, 1, 2, 8), "i_");
  // The last ring of faces meets ring 0 turned over: v7_j joins v0_{cuts - j}.
  CHECK(geom_same_cycle(geom_corners(band.soup, geom_face(band.soup, "i_f7_0")),
                        {"i_v7_0", "i_v0_2", "i_v0_1", "i_v7_1"}));
  CHECK(geom_same_cycle(geom_corners(band.soup, geom_face(band.soup, "i_f3_1")),
                        {"i_v3_1", "i_v4_1", "i_v4_2", "i_v3_2"}));
  // Two half twists: the band comes back as it left.
  const Piece twice = geom_instance("mobiusstrip g (1 2 1 6) endmobiusstrip");
  geom_check_vertices(twice, strip(1, 2, 1, 6), "i_");
  CHECK(geom_same_cycle(geom_corners(twice.soup, geom_face(twice.soup, "i_f5_0")),
                        {"i_v5_0", "i_v0_0", "i_v0_1", "i_v5_1"}));
}

TEST_CASE("JIPCAD's uncut mobiusstrip: radius is the width across the unit circle", "[scene]") {
  GeomExpected expected;
  for (int i = 0; i < 12; ++i) {
    const double around = 2 * geom_pi * i / 12, turn = geom_pi * 3 * i / 12;
    const Vec3 radial(std::cos(around), std::sin(around), 0);
    const Vec3 across = std::cos(turn) * radial + Vec3(0, 0, std::sin(turn));
    expected.push_back({"v" + std::to_string(i) + "_0", radial - 0.35 * across});
    expected.push_back({"v" + std::to_string(i) + "_1", radial + 0.35 * across});
  }
  const Piece band = geom_instance("mobiusstrip g (0.7 3 0 12) endmobiusstrip");
  geom_check_vertices(band, expected, "i_");
  CHECK(geom_same_cycle(geom_corners(band.soup, geom_face(band.soup, "i_f11_0")),
                        {"i_v11_0", "i_v0_1", "i_v0_0", "i_v11_1"}));
}
