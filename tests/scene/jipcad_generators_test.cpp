// JIPCAD's generators: topology, names and argument checks, on our own texts and on
// JIPCAD's example files where they parse.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/scene/generators/mobius_strip.hpp"
#include "nome/scene/scene.hpp"
#include "scene/scene_support.hpp"
#include "support/shared_examples.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

// `KEYWORD g ARGUMENTS endKEYWORD`, instantiated once.
Scene one_generator(const std::string& keyword, const std::string& arguments) {
  return Scene::from_text(keyword + " g " + arguments + " end" + keyword + "\ninstance i g endinstance\n",
                          "t.nome");
}

TopologyReport topology(const Scene& s) {
  return topology_report(build_mesh(s.combined_soup()));
}

bool is_closed_surface(const TopologyReport& r, long long chi) {
  return r.components.size() == 1 && r.borders == 0 && r.chi == chi && r.orientable && r.mobius_edges == 0;
}

}  // namespace

TEST_CASE("a whole sphere is one closed surface of chi 2 with single poles", "[scene]") {
  const Scene s = one_generator("sphere", "(2 360 -90 90 12 6)");
  const PolygonSoup soup = s.combined_soup();
  CHECK(soup.num_vertices() == 12 * 5 + 2);
  CHECK(is_closed_surface(topology(s), 2));
  CHECK(test::vertex_position(s, "i_north").z == Approx(2));
  CHECK(test::vertex_position(s, "i_v3_2").x ==
        Approx(2 * std::cos(0.5235987755982988) * std::cos(1.5707963267948966)).margin(1e-12));
}

TEST_CASE("the snowman tutorial's sphere (1 180 0 360 10 10) is a whole unit sphere", "[scene]") {
  // The meridian circle phi 0..360 turned half a turn, as JIPCAD's Sphere.cpp sweeps it.
  const Scene s = one_generator("sphere", "(1 180 0 360 10 10)");
  REQUIRE(s.dialect().dialect == Dialect::jipcad);
  const PolygonSoup soup = s.combined_soup();
  // Rings at latitudes 0, +-36, +-72 of 20 vertices each, and the two poles the arc passes.
  CHECK(soup.num_vertices() == 5 * 20 + 2);
  for (const Vec3& p : soup.positions) CHECK(glm::length(p) == Approx(1).margin(1e-12));
  CHECK(test::vertex_position(s, "i_north") == Vec3(0, 0, 1));
  CHECK(test::vertex_position(s, "i_south") == Vec3(0, 0, -1));
  // Covering: every direction is within 25 degrees of a vertex (half a sphere's vertices leave directions
  // 90 degrees away).
  std::mt19937 random{42};
  std::normal_distribution<double> normal;
  double farthest = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 d = glm::normalize(Vec3(normal(random), normal(random), normal(random)));
    double nearest = 4;
    for (const Vec3& p : soup.positions)
      nearest = std::min(nearest, std::acos(std::clamp(glm::dot(d, p), -1.0, 1.0)));
    farthest = std::max(farthest, nearest);
  }
  CHECK(farthest < 25 * 3.141592653589793 / 180);
  CHECK(is_closed_surface(topology(s), 2));
  // The step-by-step text's (1 360 0 180 10 10) covers the upper hemisphere twice: it is made once.
  const Scene twice = one_generator("sphere", "(1 360 0 180 10 10)");
  for (const Vec3& p : twice.combined_soup().positions) CHECK(p.z >= 0);
  const TopologyReport hemisphere = topology(twice);
  CHECK(hemisphere.chi == 1);
  CHECK(hemisphere.borders == 1);
  CHECK(hemisphere.orientable);
  // The 2016 dialect keeps its latitudes in [-90, 90].
  CHECK_THROWS_WITH(Scene::from_text("sphere s (1 180 0 360 10 10) endsphere\ninstance i s endinstance\n",
                                     "t.nome", {.dialect = Dialect::report2016}),
                    Catch::Contains("t.nome:1:19: phi_max must be in [-90, 90], found 360"));
}

TEST_CASE("a sphere cut at the tropics and sliced is a disk-like patch", "[scene]") {
  const TopologyReport r = topology(one_generator("sphere", "(1 270 -30 60 9 4)"));
  CHECK(r.chi == 1);
  CHECK(r.borders == 1);
  CHECK(r.orientable);
}

TEST_CASE("an ellipsoid is closed with chi 2 and its own polar radius", "[scene]") {
  const Scene s = one_generator("ellipsoid", "(2 0.5 360 -90 90 8 5)");
  CHECK(is_closed_surface(topology(s), 2));
  CHECK(test::vertex_position(s, "i_south").z == Approx(-0.5));
  CHECK(test::vertex_position(s, "i_v0_2").x ==
        Approx(2 * std::cos(-0.6283185307179586 * 0.5)).epsilon(1e-9));
}

TEST_CASE("a capped cylinder is closed with chi 2, without caps it is an annulus", "[scene]") {
  CHECK(is_closed_surface(topology(one_generator("cylinder", "(1 2 360 8 botcap topcap)")), 2));
  const TopologyReport open = topology(one_generator("cylinder", "(1 2 360 8)"));
  CHECK(open.chi == 0);
  CHECK(open.borders == 2);
  const TopologyReport one_cap = topology(one_generator("cylinder", "(1 2 360 8 topcap)"));
  CHECK(one_cap.chi == 1);
  CHECK(one_cap.borders == 1);
}

TEST_CASE("the wedge of a cylinder with caps, as arts_expo__blooming_flower.nom writes it", "[scene]") {
  const Scene s = one_generator("cylinder", "(2.5 0.1 340 20 topcap botcap)");
  const TopologyReport r = topology(s);
  CHECK(r.chi == 1);  // mantle and two pies: one disk, its border around the cut
  CHECK(r.borders == 1);
  CHECK(r.orientable);
  CHECK(test::vertex_position(s, "i_top").z == Approx(0.1));
}

TEST_CASE("a cone to its apex with a base is closed, a truncated one with both caps too", "[scene]") {
  const Scene s = one_generator("cone", "(1 3 1 360 7 botcap)");
  CHECK(is_closed_surface(topology(s), 2));
  CHECK(test::vertex_position(s, "i_apex").z == Approx(3));
  CHECK(is_closed_surface(topology(one_generator("cone", "(1 3 0.5 360 7 botcap topcap)")), 2));
}

TEST_CASE("a whole disk is one disk, a wedge too", "[scene]") {
  for (const char* arguments : {"(1 360 9)", "(1 90 3)"}) {
    const TopologyReport r = topology(one_generator("disk", arguments));
    CHECK(r.chi == 1);
    CHECK(r.borders == 1);
  }
}

TEST_CASE("a full torus is closed with chi 0, a half torus has two borders", "[scene]") {
  CHECK(is_closed_surface(topology(one_generator("torus", "(12 4 360 0 360 12 12)")), 0));
  // intro_files__hw1.nom's half torus.
  const TopologyReport half = topology(one_generator("torus", "(5 0.2 180 0 360 60 5)"));
  CHECK(half.chi == 0);
  CHECK(half.borders == 2);
  CHECK(half.orientable);
  // intro_files__Generators.nom's: cut both ways, a disk.
  const TopologyReport cut = topology(one_generator("torus", "(2 0.5 270 0 240 9 15)"));
  CHECK(cut.chi == 1);
  CHECK(cut.borders == 1);
}

TEST_CASE("the older six-argument torus of geom__olympictorus.nom: segs_phi first, phi from 0", "[scene]") {
  const Scene s = one_generator("torus", "(40 7 0.5 360 360 30)");
  CHECK(s.combined_soup().num_vertices() == 40 * 30);
  CHECK(is_closed_surface(topology(s), 0));
  CHECK(test::vertex_position(s, "i_v0_0").x == Approx(7.5));
}

TEST_CASE("a torus knot is a closed orientable tube of chi 0", "[scene]") {
  // geom__trefoil.nom's trefoil and geom__torusknot.nom's (1, 1) knot, with the sliders' values.
  for (const char* arguments : {"(3 2 3 2 0.5 10 120)", "(1 1 10 1 1 30 30)", "(-2 5 2 0.5 0.1 6 80)"}) {
    INFO(arguments);
    const Scene s = one_generator("torusknot", arguments);
    CHECK(is_closed_surface(topology(s), 0));
  }
}

TEST_CASE("a torus knot of tube radius 0 is its curve, a closed rim line", "[scene]") {
  const Scene s = one_generator("torusknot", "(3 2 3 2 0 10 120)");
  REQUIRE(s.instances().size() == 1);
  const Piece& piece = s.instances()[0].geometry;
  CHECK(piece.soup.num_faces() == 0);
  REQUIRE(piece.rims.size() == 1);
  CHECK(piece.rims[0].is_loop);
  CHECK(piece.rims[0].vertices.size() == 120);
}

TEST_CASE("a generator's bad value is a located error", "[scene]") {
  using test::scene_errors;
  CHECK(scene_errors("sphere s (1 360 -90 90 2 30) endsphere\ninstance i s endinstance\n") ==
        std::vector<std::string>{"t.nome:1:24: theta_segs must be a whole number in [3, 100000], found 2"});
  CHECK(scene_errors("torus t (2 1 400 0 360 8 8) endtorus\ninstance i t endinstance\n") ==
        std::vector<std::string>{"t.nome:1:14: theta_max must be in (0, 360] degrees, found 400"});
  CHECK(scene_errors("torusknot k (2 4 3 1 0.2 8 40) endtorusknot\ninstance i k endinstance\n").size() == 1);
  CHECK(scene_errors("cylinder c (1 2 360 8 lid) endcylinder\n") ==
        std::vector<std::string>{"t.nome:1:23: expected a number or '{expr ...}', found 'lid'"});
  CHECK(scene_errors("sphere s (1 360 -90 -90 8 4) endsphere\ninstance i s endinstance\n") ==
        std::vector<std::string>{"t.nome:1:21: phi_max must be above phi_min"});
}

TEST_CASE("geom__standard_sphere.nom is closed with chi 2", "[scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const Scene s = test::load_scene_file(test::shared_examples_dir("jipcad") + "geom__standard_sphere.nom");
  CHECK(is_closed_surface(topology(s), 2));
}

TEST_CASE("geom__torusknot.nom's statements: a closed orientable tube of chi 0, slider-driven", "[scene]") {
  // The file's bank is written with JIPCAD's `list` and `$bank.name` (the successor's dialect); these
  // are its statements in the 2016 spelling.
  const Scene s = Scene::from_text(
      "bank knot_slider\n set symm 1 -5 5 1\n set turns 1 -5 5 1\n set maj_rad 10 0 100 1\n"
      " set min_rad 1 0 100 1\n set tube_rad 1 0 2 0.05\n set circ_segs 30 10 100 5\n"
      " set sweep_segs 30 10 100 5\nendbank\n"
      "torusknot knot ({expr $knot_slider_symm} {expr $knot_slider_turns} {expr $knot_slider_maj_rad} "
      "{expr $knot_slider_min_rad} {expr $knot_slider_tube_rad} {expr $knot_slider_circ_segs} "
      "{expr $knot_slider_sweep_segs}) endtorusknot\n"
      "instance knot1 knot scale (10 10 10) endinstance\n",
      "t.nome");
  CHECK(s.combined_soup().num_vertices() == 30 * 30);
  CHECK(is_closed_surface(topology(s), 0));
}

TEST_CASE("gencartesiansurf: the height field of param_surf__genCartesianSurfExample.nom", "[scene]") {
  const Scene s = one_generator("gencartesiansurf", "func [(7*x*y)/exp((x^2)+(y^2))] (-2 2 -2 2 40 40)");
  const PolygonSoup soup = s.combined_soup();
  CHECK(soup.num_vertices() == 41 * 41);
  const TopologyReport r = topology(s);
  CHECK(r.chi == 1);
  CHECK(r.borders == 1);
  const Vec3 p = test::vertex_position(s, "i_v30_25");  // x = 1, y = 0.5
  CHECK(p.z == Approx(7 * 1 * 0.5 / std::exp(1.25)));
}

TEST_CASE("function strings read what JIPCAD's files write inside the brackets", "[scene]") {
  // The commented-out examples of param_surf__*.nom: implied products, if, and, cosh.
  for (const char* f :
       {"[sin(10(x^2+y^2))/10]", "[sin(5x)*cos(5y)/5]", "[if((x^2+y^2>0.05)and(x+y>-1),x^8+y^30,1)]",
        "[if(x>1,x^2,if(x>-1,x,-x))]", "[-0.4*cosh(x)*cos(y)]"}) {
    INFO(f);
    CHECK(test::scene_errors(std::string("gencartesiansurf g func ") + f +
                             " (-1 1 -1 1 4 4) endgencartesiansurf\ninstance i g endinstance\n")
              .empty());
  }
  const Scene s =
      one_generator("gencartesiansurf", "func [5x + if(y > 0 and x < 0, 100, 2y)] (-1 1 -1 1 2 2)");
  CHECK(test::vertex_position(s, "i_v0_2").z == Approx(-5 + 100));  // x = -1, y = 1
  CHECK(test::vertex_position(s, "i_v2_0").z == Approx(5 - 2));     // x = 1, y = -1
}

TEST_CASE("a function string that is not one is a located error", "[scene]") {
  using test::scene_errors;
  CHECK(scene_errors("gencartesiansurf g func [x+*y] (-1 1 -1 1 2 2) endgencartesiansurf\n"
                     "instance i g endinstance\n") ==
        std::vector<std::string>{"t.nome:1:25: in the function [x+*y], at character 3: expected a number, a "
                                 "variable, a function or '(', found '*'"});
  CHECK(scene_errors("gencartesiansurf g func [z] (-1 1 -1 1 2 2) endgencartesiansurf\n"
                     "instance i g endinstance\n") ==
        std::vector<std::string>{"t.nome:1:25: in the function [z], at character 1: expected a variable (x, "
                                 "y), pi or a function, found 'z'"});
  CHECK(scene_errors("gencartesiansurf g func [1/x] (-1 1 -1 1 2 2) endgencartesiansurf\n"
                     "instance i g endinstance\n") ==
        std::vector<std::string>{"t.nome:1:25: the function of 'g' has no finite value at x = 0, y = -1"});
}

TEST_CASE("a parametric Möbius band, u over a full turn, becomes one-sided after merging", "[scene]") {
  const Scene s =
      one_generator("genparametricsurf",
                    "funcX [(1+v*cos(u/2))*cos(u)] funcY [(1+v*cos(u/2))*sin(u)] funcZ [v*sin(u/2)] "
                    "({expr 0} {expr 2*pi} -0.3 0.3 24 3)");
  CHECK(topology(s).orientable);  // a strip of 24 x 3 quads, its ends apart
  Pipeline pipeline;
  pipeline.set_input(PipelineInput{s.combined_soup(), {}, Joining::manifold});
  PipelineSettings settings;
  settings.stage = Stage::merged;
  settings.should_merge = true;
  const TopologyReport merged = topology_report(pipeline.run(settings));
  CHECK(merged.components.size() == 1);
  CHECK_FALSE(merged.orientable);
  CHECK(merged.borders == 1);
  CHECK(merged.chi == 0);
}

TEST_CASE("param_surf__genParametricSurfExample.nom's Dupin cyclide closes after merging", "[scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const Scene s =
      test::load_scene_file(test::shared_examples_dir("jipcad") + "param_surf__genParametricSurfExample.nom");
  Pipeline pipeline;
  pipeline.set_input(PipelineInput{s.combined_soup(), {}, Joining::manifold});
  PipelineSettings settings;
  settings.stage = Stage::merged;
  settings.should_merge = true;
  const TopologyReport merged = topology_report(pipeline.run(settings));
  CHECK(merged.borders == 0);
  CHECK(merged.chi == 0);
  CHECK(merged.orientable);
}

TEST_CASE("genimplicitsurf: a sphere, a torus and a cylinder cut by the box, all 2-manifolds", "[scene]") {
  const Scene ball =
      one_generator("genimplicitsurf", "func [x^2+y^2+z^2-1] (-1.5 1.5 -1.5 1.5 -1.5 1.5 9 10 11)");
  CHECK(is_closed_surface(topology(ball), 2));
  // Every face points away from the centre (towards f > 0).
  const PolygonSoup soup = ball.combined_soup();
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const Index* corners = &soup.face_vertices[soup.face_offsets[f]];
    const Vec3 a = soup.positions[corners[0]], b = soup.positions[corners[1]], c = soup.positions[corners[2]];
    CHECK(glm::dot(glm::cross(b - a, c - a), a + b + c) > 0);
  }
  const Scene ring = one_generator(
      "genimplicitsurf", "func [(sqrt(x^2+y^2)-1)^2+z^2-0.16] (-1.6 1.6 -1.6 1.6 -0.6 0.6 16 16 6)");
  CHECK(is_closed_surface(topology(ring), 0));
  const TopologyReport tube =
      topology(one_generator("genimplicitsurf", "func [x^2+y^2-1] (-2 2 -2 2 -1 1 7 7 3)"));
  CHECK(tube.chi == 0);
  CHECK(tube.borders == 2);
  CHECK(tube.orientable);
}

TEST_CASE("a sample exactly on the surface gives no pinched vertex", "[scene]") {
  // x^2+y^2+z^2-1 is 0 at the samples (+-1, 0, 0), ... of this grid: they count as outside.
  const Scene s = one_generator("genimplicitsurf", "func [x^2+y^2+z^2-1] (-2 2 -2 2 -2 2 4 4 4)");
  CHECK(is_closed_surface(topology(s), 2));
}

TEST_CASE("param_surf__genImplicitSurfExample.nom's Goursat tangle is a closed orientable surface",
          "[scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const Scene s =
      test::load_scene_file(test::shared_examples_dir("jipcad") + "param_surf__genImplicitSurfExample.nom");
  const TopologyReport r = topology(s);
  CHECK(r.borders == 0);
  CHECK(r.orientable);
  CHECK(r.components.size() >= 1);
}

TEST_CASE("helix and spiral are open rim lines", "[scene]") {
  const Scene h = one_generator("helix", "(2 0.5 720 48)");
  REQUIRE(h.instances().size() == 1);
  const Piece& helix = h.instances()[0].geometry;
  REQUIRE(helix.rims.size() == 1);
  CHECK_FALSE(helix.rims[0].is_loop);
  CHECK(helix.rims[0].vertices.size() == 49);
  CHECK(helix.soup.num_faces() == 0);
  CHECK(test::vertex_position(h, "i_v48").z == Approx(0.5 * 4 * 3.141592653589793));
  CHECK(test::vertex_position(h, "i_v6").y == Approx(2));  // a quarter turn
  const Scene s = one_generator("spiral", "(1 720 8)");
  CHECK(test::vertex_position(s, "i_v0") == Vec3(0, 0, 0));
  CHECK(test::vertex_position(s, "i_v8").x == Approx(2));  // two turns, radius 1 more per turn
}

TEST_CASE("hyperboloids: one sheet an annulus, two sheets two disks, the 2016 paraboloid a disk", "[scene]") {
  // The successor's (segs a b c sheet theta): 12 around, rows at z = -3..3, a whole turn.
  const TopologyReport one = topology(one_generator("hyperboloid", "(12 1 1 3 0 2)"));
  CHECK(one.chi == 0);
  CHECK(one.borders == 2);
  CHECK(one.orientable);
  const Scene two = one_generator("hyperboloid", "(12 1 2 3 1 2)");
  const TopologyReport r = topology(two);
  CHECK(r.components.size() == 2);
  CHECK(r.chi == 2);
  CHECK(r.borders == 2);
  CHECK(test::vertex_position(two, "i_bottom_apex") == Vec3(0, 0, -1));
  // NOME3's order, which only the 2016 dialect reads, has the paraboloid.
  const Scene bowl_scene =
      Scene::from_text("hyperboloid g (1 1 1 6 12 1) endhyperboloid\ninstance i g endinstance\n", "t.nome",
                       {.dialect = Dialect::report2016});
  const TopologyReport bowl = topology(bowl_scene);
  CHECK(bowl.chi == 1);
  CHECK(bowl.borders == 1);
}

TEST_CASE("a whole Dupin cyclide is closed with chi 0, a quarter is a disk", "[scene]") {
  // The ring cyclide of param_surf__genParametricSurfExample.nom, as a generator: b^2 = a^2 - c^2.
  CHECK(is_closed_surface(topology(one_generator("dupin", "(1 0.98 0.2 0.5 2 2 24)")), 0));
  const TopologyReport quarter = topology(one_generator("dupin", "(1 0.98 0.2 0.5 1 1 8)"));
  CHECK(quarter.chi == 1);
  CHECK(quarter.borders == 1);
  CHECK(
      test::scene_errors("dupin d (1 0.98 1.5 0.5 2 2 8) enddupin\ninstance i d endinstance\n") ==
      std::vector<std::string>{"t.nome:1:17: |c| must be below a (the cyclide would pass through infinity)"});
}

TEST_CASE("JIPCAD's mobiusstrip: radius is the width, cuts make parallel bands", "[scene]") {
  // geom__mobius_strip.nom's values: width 1, one twist, no cut.
  const Scene s = one_generator("mobiusstrip", "(1 1 0 100)");
  const TopologyReport band = topology(s);
  CHECK(band.components.size() == 1);
  CHECK_FALSE(band.orientable);
  CHECK(band.borders == 1);
  CHECK(glm::length(test::vertex_position(s, "i_v0_0") - test::vertex_position(s, "i_v0_1")) == Approx(1));
  // One cut along the middle (a gap between two bands) of a Möbius band: one long two-sided band.
  const TopologyReport cut = topology_report(build_mesh(cut_mobius_strip({1, 1, 1, 40}).soup));
  CHECK(cut.components.size() == 1);
  CHECK(cut.orientable);
  CHECK(cut.borders == 2);
  // Two cuts: the middle band stays one-sided, the outer two join into one two-sided band.
  const TopologyReport thirds = topology_report(build_mesh(cut_mobius_strip({1, 1, 2, 40}).soup));
  CHECK(thirds.components.size() == 2);
  CHECK_FALSE(thirds.orientable);
  const TopologyReport two_cuts = topology_report(build_mesh(cut_mobius_strip({1.5, 2, 2, 40}).soup));
  CHECK(two_cuts.components.size() == 3);
  CHECK(two_cuts.orientable);
}
