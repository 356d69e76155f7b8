// The successor's stage blocks (subdivision, offset) and render statements, and JIPCAD's hello_cube
// through the pipeline with the levels its subdivision block asks for.
#include <catch2/catch.hpp>

#include "nome/io/read_scene.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/scene/save_nome.hpp"
#include "support/shared_examples.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

constexpr const char* square =
    "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (1 1 0) endpoint point d (0 1 0) endpoint\n"
    "mesh m face f (a b c d) endface endmesh\n";

}  // namespace

TEST_CASE("stage blocks place their instances and set the pipeline's levels and offset", "[scene]") {
  const Scene s =
      Scene::from_text(std::string(square) +
                           "bank sub set level 2 0 5 1 list (level) endbank\n"
                           "subdivision s0\n  sd_type NOME_SD_CC_sharp\n  sd_level {expr $sub.level}\n"
                           "  instance i m endinstance\nendsubdivision\n"
                           "offset o0\n  offset_type NOME_OFFSET_DEFAULT\n  height 0.1\n  width 0.2\n"
                           "  instance j m translate (0 0 2) endinstance\nendoffset\n",
                       "t.nom");
  REQUIRE(s.instances().size() == 2);
  const StageSettings stages = s.stage_settings();
  CHECK(stages.subdivision_levels == 2);
  CHECK(stages.offset_distance == 0.1);
  const std::string saved = to_nome_text(s);
  CHECK_THAT(saved,
             Catch::Contains("subdivision s0\n    sd_type NOME_SD_CC_sharp\n    sd_level {expr $sub_level}\n"
                             "    instance i m endinstance\nendsubdivision\n"));
  CHECK_THAT(saved, Catch::Contains("    height 0.1\n    width 0.2\n"));
  const Scene back = Scene::from_text(saved, "saved.nom");
  CHECK(back.instances().size() == 2);
  CHECK(back.stage_settings().subdivision_levels == 2);

  CHECK_THROWS_WITH(
      Scene::from_text(std::string(square) + "subdivision s sd_level 1.5 endsubdivision\n", "t.nom"),
      Catch::Contains("t.nom:3:24: sd_level must be a whole number in 0..12, found 1.5"));
  CHECK_THROWS_WITH(
      Scene::from_text(std::string(square) + "offset o offset_type NOME_OFFSET_GRID height 1 endoffset\n",
                       "t.nom"),
      Catch::Contains("t.nom:3:22: offset_type 'NOME_OFFSET_GRID' is not supported yet"));
}

TEST_CASE("the boundary mode is a statement in either dialect and a setting of a subdivision block",
          "[scene]") {
  const Scene report = Scene::from_text(std::string(square) +
                                            "boundary edge_and_corner endboundary\n"
                                            "instance i m endinstance\n",
                                        "t.nome");
  CHECK(report.dialect().dialect == Dialect::report2016);
  CHECK(report.stage_settings().boundary == BoundaryMode::edge_and_corner);
  const Scene back = Scene::from_text(to_nome_text(report), "saved.nome");
  CHECK(back.stage_settings().boundary == BoundaryMode::edge_and_corner);

  const Scene successor = Scene::from_text(
      std::string(square) +
          "subdivision s sd_level 1 sd_boundary none instance i m endinstance endsubdivision\n",
      "t.nom");
  CHECK(successor.stage_settings().boundary == BoundaryMode::none);
  CHECK_THAT(to_nome_text(successor), Catch::Contains("    sd_boundary none\n"));
  CHECK_FALSE(Scene::from_text(std::string(square), "t.nom").stage_settings().boundary);

  CHECK_THROWS_WITH(
      Scene::from_text(std::string(square) + "boundary corners endboundary\n", "t.nom"),
      Catch::Contains("t.nom:3:10: unknown boundary mode 'corners' (none, edge_only or edge_and_corner)"));
}

TEST_CASE("render statements are parsed with their locations and become the picture's defaults", "[scene]") {
  const Scene s = Scene::from_text(
      std::string(square) +
          "bank v set g 0.5 0 1 0.1 endbank\n"
          "frontcolor (0.8 0 0) endfrontcolor\nbackcolor (0 0.5 0.5) endbackcolor\n"
          "light sun\n  type NOME_DIRECTIONAL\n  color (0.7 0.7 0.7)\nendlight\n"
          "camera cam\n  projection NOME_PERSPECTIVE\n  frustum (-0.2 0.2 -0.2 0.2 -4 -0.01)\nendcamera\n"
          "window w\n  origin (0 0)\n  size (1 1)\n  background (0.1 {expr $v.g} 0.9)\nendwindow\n"
          "viewport vp\n  cameraID cam\n  origin (0 0)\n  size (0.5 1)\nendviewport\n"
          "backface MS color (0 1 0) endbackface\n"
          "instance i m surface MS endinstance\ninstance l sun rotate (0 0 1) (30) endinstance\n",
      "t.nom");
  CHECK(s.dialect().dialect == Dialect::jipcad);
  REQUIRE(s.ast().render.size() == 7);
  CHECK(s.ast().render[2].keyword == "light");
  CHECK(s.ast().render[2].location == SourceLocation{6, 1});
  CHECK(s.ast().render[4].fields[2].key.text == "background");
  REQUIRE(s.instances().size() == 1);  // the light's instance places no geometry
  CHECK(s.ast().render_instances.size() == 1);
  const RenderDefaults d = s.render_defaults();
  CHECK(d.front_color == Color(0.8f, 0, 0));
  CHECK(d.back_color == Color(0, 1, 0));  // the backface the instance names wins over backcolor
  CHECK(d.background == Color(0.1f, 0.5f, 0.9f));
  CHECK(d.camera_projection == "NOME_PERSPECTIVE");
  CHECK(d.camera_frustum.size() == 6);
  CHECK(d.light_count == 1);
  const Scene back = Scene::from_text(to_nome_text(s), "saved.nom");
  CHECK(back.ast().render.size() == 7);
  CHECK(back.ast().render_instances.size() == 1);
  CHECK(back.render_defaults().background == d.background);
  CHECK(back.render_defaults().back_color == d.back_color);
}

TEST_CASE("JIPCAD's hello_cube merges into one closed sphere and its block subdivides it twice", "[scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const Scene s = read_scene(test::shared_examples_dir("jipcad") + "intro_files__hello_cube.nom");
  CHECK(s.dialect().dialect == Dialect::jipcad);
  const StageSettings stages = s.stage_settings();
  REQUIRE(stages.subdivision_levels == 2);
  PipelineSettings settings;
  settings.should_merge = true;
  settings.subdivision_levels = *stages.subdivision_levels;
  Pipeline pipeline;
  pipeline.set_input(PipelineInput{s.combined_soup(), {}, {}});
  settings.stage = Stage::merged;
  const TopologyReport merged = topology_report(pipeline.run(settings));
  CHECK(merged.components.size() == 1);
  CHECK(merged.borders == 0);
  CHECK(merged.orientable);
  CHECK(merged.chi == 2);
  CHECK(merged.faces == 6);
  settings.stage = Stage::subdivided;
  const TopologyReport subdivided = topology_report(pipeline.run(settings));
  CHECK(subdivided.faces == 96);
  CHECK(subdivided.chi == 2);
  CHECK(subdivided.borders == 0);
}
