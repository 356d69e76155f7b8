// A slider that a colour reads: the faces it colours take the new colour, whichever path the slider's
// move takes. Oracle: the same text read fresh at each value.
#include <catch2/catch.hpp>

#include <string>

#include "scene/fresh_scene_oracle.hpp"

using namespace nome;

namespace {

// Colours that read the slider given by an instance (to a generator made again, a sweep whose vertices
// alone could move, a group, a face over copied vertices) and by a face's own surface; a sweep whose
// positions alone read it; and a sweep whose positions and colour both do.
std::string colored_text(double c) {
  return "bank b set c " + std::to_string(c) + " 0 1 0.25 endbank\n" + test::swept_triangle_text +
         "point z1 (0 {expr $b_c} 1) endpoint\n"
         "surface col color ({expr $b_c} 0.5 {expr 1 - $b_c}) endsurface\n"
         "surface own color (0.2 {expr $b_c} 0.9) endsurface\n"
         "surface still color (0.1 0.2 0.3) endsurface\n"
         "funnel fun (5 1 0.5 1) endfunnel\n"
         "point q0 (0 -9 0) endpoint\npoint q1 (1 -9 0) endpoint\npoint q2 (1 -8 0) endpoint\n"
         "group gs instance inner sw endinstance endgroup\n"
         "mesh patch face p (fixed_v0_0 fixed_v0_1 fixed_v1_1 fixed_v1_0) endface endmesh\n"
         "mesh owned face o (fixed_v1_0 fixed_v1_1 fixed_v2_1 fixed_v2_0) surface own endface endmesh\n"
         "mesh plain face n (q0 q1 q2) surface own endface endmesh\n"
         "instance fixed sw translate (0 4 0) endinstance\n"
         "instance f fun surface col endinstance\n"
         "instance w sw translate (4 0 0) surface col endinstance\n"
         "instance g gs translate (8 0 0) surface col endinstance\n"
         "instance c patch translate (0 -4 0) surface col endinstance\n"
         "instance o owned translate (0 -6 0) endinstance\n"
         "instance n plain endinstance\n"
         "instance moving sw translate (-4 0 0) surface still endinstance\n";
}

}  // namespace

TEST_CASE("a slider that a colour reads recolours the faces as a fresh reading does", "[scene]") {
  SceneDocument doc = SceneDocument::from_scene(scene::Scene::from_text(colored_text(0), "t.nome"));
  const std::size_t moves_before = doc.scene()->vertex_moves();
  for (const double c : {0.25, 0.5, 1.0, 0.5, 0.0, 0.75}) {
    INFO("c = " << c);
    doc.set_parameter("b_c", c);
    test::check_same_as_fresh(doc, colored_text(c));
  }
  // The sweep whose colour stays took the positions-only path: the checks above saw it.
  CHECK(doc.scene()->vertex_moves() > moves_before);
}
