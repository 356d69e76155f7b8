// A slider that turns an instance inside out (a scale through zero, a mirror after a scale): its faces
// turn over, which the positions-only path must not skip. Oracle: the same text read fresh at each value.
#include <catch2/catch.hpp>

#include <string>

#include "scene/fresh_scene_oracle.hpp"

using namespace nome;

namespace {

// Every way an instance's handedness can follow slider m: a generator made again (the funnel), a
// generator whose vertices alone move (the sweep, its own scale or mirrored), a group's scale over a
// sweep, and a face whose vertices are copies of another instance's. Slider n turns over only pieces
// without a generator's grid: a face over points and a face over copied vertices.
std::string handedness_text(double m, double n) {
  return "bank b set m " + std::to_string(m) + " -2 2 0.5 set n " + std::to_string(n) +
         " -2 2 0.5 endbank\n" + test::swept_triangle_text +
         "point z1 (0 0 1) endpoint\n"
         "funnel fun (5 1 0.5 1) endfunnel\n"
         "group gs instance inner sw endinstance endgroup\n"
         "mesh patch face p (fixed_v0_0 fixed_v0_1 fixed_v1_1 fixed_v1_0) endface endmesh\n"
         "instance fixed sw translate (0 4 0) endinstance\n"
         "instance f fun scale ({expr $b_m} 1 1) translate (-4 0 0) endinstance\n"
         "instance w sw scale (1 {expr $b_m} 1) endinstance\n"
         "instance wm sw mirror (1 0 0 0) scale ({expr $b_m} 1 1) translate (4 0 0) endinstance\n"
         "instance g gs scale (1 1 {expr $b_m}) translate (8 0 0) endinstance\n"
         "instance c patch scale ({expr $b_m} 1 1) translate (0 -4 0) endinstance\n"
         "point q0 (0 -9 0) endpoint\npoint q1 (1 -9 0.5) endpoint\npoint q2 (1 -8 0) endpoint\n"
         "point q3 (0 -8 0.2) endpoint\nmesh quad face q (q0 q1 q2 q3) endface endmesh\n"
         "instance t quad scale (1 {expr $b_n} 1) endinstance\n"
         "instance cn patch scale (1 1 {expr $b_n}) translate (0 -6 0) endinstance\n";
}

}  // namespace

TEST_CASE("a slider that scales through zero turns faces over as a fresh reading does, both ways",
          "[scene]") {
  SceneDocument doc = SceneDocument::from_scene(scene::Scene::from_text(handedness_text(1, 1), "t.nome"));
  const std::size_t moves_before = doc.scene()->vertex_moves();
  for (const double m : {0.5, 0.0, -0.5, -1.0, -2.0, -0.5, 0.0, 0.5, 2.0, -1.0, 1.0}) {
    INFO("m = " << m);
    doc.set_parameter("b_m", m);
    test::check_same_as_fresh(doc, handedness_text(m, 1));
  }
  for (const double n : {0.5, -0.5, -2.0, 0.0, 1.0}) {
    INFO("n = " << n);
    doc.set_parameter("b_n", n);
    test::check_same_as_fresh(doc, handedness_text(1, n));
  }
  // The moves on one side of zero took the positions-only path: the checks above saw it.
  CHECK(doc.scene()->vertex_moves() > moves_before);
}
