#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "app/viewer_support.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/query/border_lookup.hpp"
#include "support/shared_examples.hpp"

using namespace nome;
using nome::test::run_window;
using nome::test::write_script;

// The viewer's sessions in this process, on the null renderer: scripts, picks, edits, saves and prompts.
namespace {

using nome::test::assets;

using nome::test::obj_vertex;

using nome::test::click_line;

}  // namespace

TEST_CASE("a bad script is refused before the window does anything", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_bad_script");
  const std::string script = write_script(dir, "click 10\n");
  const auto r = run_window(assets + "cube.obj --script " + script);
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("script.txt:1:9: expected 'click X Y"));
}

TEST_CASE("border modes select a whole loop from one click and a segment from three", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_border");
  const Mesh mesh = build_mesh(read_polygons(assets + "mobius_band.obj"));
  const auto projection = nome::test::viewer_projection(mesh, 20.0, 35.0);
  const BorderLookup borders(mesh);
  // Clickable border vertices, in loop order.
  std::vector<std::pair<Index, glm::dvec2>> clickable;
  for (Index v : mesh.loop_vertices(0))
    if (const auto p = nome::test::vertex_click(mesh, projection, v)) clickable.emplace_back(v, *p);
  REQUIRE(clickable.size() >= 8);
  const auto [a, pa] = clickable[0];
  const auto [b, pb] = clickable[clickable.size() / 2];
  const auto [s, ps] = clickable[clickable.size() / 4];
  const auto expected = borders.segment(a, b, s);
  REQUIRE(expected);
  const std::string script =
      write_script(dir, "view 20 35\nmode border\n" + click_line(pa) + "mode border-partial\n" +
                            click_line(pa) + click_line(pa) + click_line(pb) + click_line(ps) + "quit\n");
  const auto r = run_window(assets + "mobius_band.obj --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("border of " + std::to_string(mesh.loop_vertices(0).size()) +
                                    " vertices selected, from " + obj_vertex(a)));
  CHECK_THAT(r.err, Catch::Contains("border deselected"));
  CHECK_THAT(r.err, Catch::Contains("partial border of " + std::to_string(expected->size()) +
                                    " vertices selected, from " + obj_vertex(a)));
}

TEST_CASE("the merge action shows the merged stage, which export writes", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_merge");
  // Two unit squares side by side, each with its own copy of the shared edge.
  std::ofstream(dir + "/pieces.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                        "v 1 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\n"
                                        "f 1 2 3 4\nf 5 6 7 8\n";
  const std::string script =
      write_script(dir, "export " + dir + "/before.obj\naction merge\nexport " + dir + "/after.obj\nquit\n");
  const auto r = run_window(dir + "/pieces.obj --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(build_mesh(read_polygons(dir + "/before.obj")).num_vertices() == 8);
  const Mesh merged = build_mesh(read_polygons(dir + "/after.obj"));
  CHECK(merged.num_vertices() == 6);
  CHECK(merged.num_components() == 1);
  CHECK_THAT(r.err, Catch::Contains("merged 1 edge pairs"));
}

TEST_CASE("a session deletes a face, undoes and redoes it, then fills the hole and accepts", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_edit");
  const Mesh cube = build_mesh(read_polygons(assets + "cube.obj"));
  const auto projection = nome::test::viewer_projection(cube, 30.0, 25.0);
  // A face in full view, clicked at its centre.
  Index face = no_index;
  glm::dvec2 face_click(0.0);
  for (Index f = 0; f < cube.num_faces() && face == no_index; ++f) {
    if (const auto pixel = nome::test::face_click(cube, projection, f)) {
      face = f;
      face_click = *pixel;
    }
  }
  REQUIRE(face != no_index);
  // Three corners of the hole, clicked on the cube without that face.
  PolygonSoup holed = read_polygons(assets + "cube.obj");
  PolygonSoup without;
  without.positions = holed.positions;
  for (Index f = 0; f < holed.num_faces(); ++f)
    if (f != face)
      without.add_face(std::span(holed.face_vertices.data() + holed.face_offsets[f],
                                 holed.face_offsets[f + 1] - holed.face_offsets[f]));
  const Mesh open_cube = build_mesh(without);
  std::string corner_clicks;
  int corners = 0;
  for (Index v : cube.face_vertices(face)) {
    if (corners == 3) break;
    if (const auto p = nome::test::vertex_click(open_cube, projection, v)) {
      corner_clicks += click_line(*p);
      ++corners;
    }
  }
  REQUIRE(corners == 3);
  const std::string script = write_script(
      dir, "view 30 25\nmode face\n" + click_line(face_click) + "action delete\nexport " + dir +
               "/deleted.obj\naction undo\nexport " + dir + "/undone.obj\naction redo\nmode vertex\n" +
               corner_clicks + "action add-polygon\naction accept\nexport " + dir + "/filled.obj\nquit\n");
  const auto r = run_window(assets + "cube.obj --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(build_mesh(read_polygons(dir + "/deleted.obj")).num_faces() == 5);
  CHECK(build_mesh(read_polygons(dir + "/undone.obj")).num_faces() == 6);
  const Mesh filled = build_mesh(read_polygons(dir + "/filled.obj"));
  CHECK(filled.num_faces() == 6);
  CHECK(filled.face_degree(5) == 3);
  CHECK_THAT(r.err, Catch::Contains("accept: "));
}

TEST_CASE("subdiv and offset show the later stages, which export writes: the Möbius band becomes a torus",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_offset");
  const std::string script =
      write_script(dir, "subdiv 2\nexport " + dir + "/smooth.obj\noffset 0.05\nexport " + dir +
                            "/solid.obj\noffset 0\nsubdiv 1\nexport " + dir + "/once.obj\nquit\n");
  const auto r = run_window(assets + "mobius_band.obj --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const Mesh band = build_mesh(read_polygons(assets + "mobius_band.obj"));
  const Mesh smooth = build_mesh(read_polygons(dir + "/smooth.obj"));
  CHECK(smooth.num_faces() == 16 * band.num_faces());
  const TopologyReport smooth_report = topology_report(smooth);
  CHECK_FALSE(smooth_report.orientable);
  CHECK(smooth_report.borders == 1);
  const TopologyReport solid = topology_report(build_mesh(read_polygons(dir + "/solid.obj")));
  CHECK(solid.orientable);
  CHECK(solid.borders == 0);
  CHECK(solid.chi == 0);
  // `offset 0` goes back to the subdivided stage, which follows the level.
  CHECK(build_mesh(read_polygons(dir + "/once.obj")).num_faces() == 4 * band.num_faces());
}

TEST_CASE("a computed stage picks faces but refuses edits, and a bad level is refused", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_derived_pick");
  const std::string script = write_script(dir,
                                          "view 30 25\nsubdiv 1\nmode face\nclick 640 400\naction delete\n"
                                          "subdiv 7\nexport " +
                                              dir + "/cube.obj\nquit\n");
  const auto r = run_window(assets + "cube.obj --script " + script);
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("selected in the subdivided stage"));
  CHECK_THAT(r.err, Catch::Contains("delete: the subdivided stage is computed from the scene; switch to the "
                                    "scene or merged stage to edit"));
  CHECK_THAT(r.err, Catch::Contains("subdiv: expected a level from 0 to 6"));
  // Nothing was deleted and the level stayed at 1.
  CHECK(build_mesh(read_polygons(dir + "/cube.obj")).num_faces() == 24);
}

TEST_CASE("a double-click moves the orbit centre onto the surface, and a dropped file replaces the open one",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_drop");
  const std::string script = write_script(dir, "view 30 25\ndouble-click 640 400\ndrop " + assets +
                                                   "tetrahedron.obj\nexport " + dir + "/dropped.obj\nquit\n");
  const auto r = run_window(assets + "cube.obj --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  // The cube spans [-1, 1]^3: the centre lies on one of its faces.
  const auto at = r.err.find("orbit centre at (");
  REQUIRE(at != std::string::npos);
  double x = 0, y = 0, z = 0;
  REQUIRE(std::sscanf(r.err.c_str() + at, "orbit centre at (%lf, %lf, %lf)", &x, &y, &z) == 3);
  CHECK(std::max({std::abs(x), std::abs(y), std::abs(z)}) == Approx(1.0).epsilon(1e-6));
  CHECK_THAT(r.err, Catch::Contains("opened " + assets + "tetrahedron.obj"));
  CHECK(build_mesh(read_polygons(dir + "/dropped.obj")).num_faces() == 4);
}

TEST_CASE("a file dropped on a scene with unsaved changes waits for the answer: cancel keeps, discard opens",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_drop_modified");
  const std::string cube = assets + "cube.obj";
  const std::string script =
      write_script(dir, "set fp_n 6\ndrop " + cube + "\nprompt cancel\nexport " + dir + "/kept.obj\ndrop " +
                            cube + "\nprompt discard\nexport " + dir + "/dropped.obj\nquit\n");
  const auto r = run_window(assets + "funnel_cube.nome --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("open cube.obj: funnel_cube.nome has unsaved changes"));
  CHECK(build_mesh(read_polygons(dir + "/kept.obj")).num_faces() == 36);  // six funnels of six quads
  CHECK(build_mesh(read_polygons(dir + "/dropped.obj")).num_faces() == 6);
}

TEST_CASE("an .anom file given after its scene, or dropped on it, applies to the open scene", "[app]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  const std::string original = nome::test::shared_examples_dir("original");
  const std::string dir = nome::test::private_scratch_dir("viewer_anom");
  const std::string script =
      write_script(dir, "export " + dir + "/given.obj\ndrop " + original + "kleinbottle_s1.anom\n" +
                            "export " + dir + "/dropped.obj\nquit\n");
  const auto r =
      run_window(original + "kleinbottle.nom " + original + "kleinbottle_s1.anom --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("applied " + original + "kleinbottle_s1.anom to kleinbottle.nom"));
  CHECK(read_polygons(dir + "/given.obj").num_faces() == 88);
  CHECK(read_polygons(dir + "/dropped.obj").num_faces() == 88);

  // Alone, it has no scene to apply to.
  const auto alone = nome::test::run_nome(original + "kleinbottle_s1.anom");
  CHECK(alone.status == 2);
  CHECK_THAT(alone.err, Catch::Contains("give the .nome file before it"));
}

TEST_CASE("the viewer opens a file at the stage its subdivision block asks for", "[app]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const std::string dir = nome::test::private_scratch_dir("viewer_stage_block");
  const std::string script = write_script(dir, "export " + dir + "/shown.obj\nquit\n");
  const auto r = run_window(nome::test::shared_examples_dir("jipcad") +
                            "intro_files__hello_cube.nom --script " + script);
  INFO(r.err);
  REQUIRE(r.status == 0);
  // JIPCAD's hello cube: six faces merged into a cube, its block's level 2; the log says why it is merged.
  CHECK_THAT(r.err, Catch::Contains("subdividing the merged mesh: the successor's dialect welds"));
  const TopologyReport shown = topology_report(build_mesh(read_polygons(dir + "/shown.obj")));
  CHECK(shown.faces == 96);
  CHECK(shown.borders == 0);
  CHECK(shown.chi == 2);
}
