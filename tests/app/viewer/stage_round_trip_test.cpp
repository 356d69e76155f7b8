#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

#include "nome/mesh/topology_report.hpp"
#include "support/same_mesh.hpp"
#include "support/shapes.hpp"
#include "viewer/session/session.hpp"
#include "viewer/session/stage_pipeline.hpp"

using namespace nome;
using nome::viewer::StagePipeline;

namespace {

constexpr Stage every_stage[] = {Stage::scene, Stage::merged, Stage::subdivided, Stage::offset,
                                 Stage::subdivided_offset};

struct Surface {
  const char* name;
  PolygonSoup soup;
};

// Open (a grid and a Möbius band, one-sided), closed two-sided (a torus) and closed one-sided (a Klein
// bottle): the three kinds of surface every stage must handle.
std::vector<Surface> surfaces() {
  return {{"grid", test::grid(4, 3)},
          {"mobius band", test::mobius_band(12, 2)},
          {"torus", test::torus(12, 6)},
          {"klein bottle", test::klein_bottle(12, 8)}};
}

// What the viewer's stage holds: the settings the control panel and the script commands change.
struct Shown {
  PipelineSettings settings = viewer::initial_settings();
  std::string steps;
};

// Runs the settings on the long-lived pipeline (its caches, its lent results) and on a fresh one: the
// mesh and the display arrays must be the same, and the display arrays must describe that mesh.
void check_like_fresh(StagePipeline& pipeline, const PipelineInput& input, const Shown& shown) {
  INFO("steps: " << shown.steps);
  const auto result = pipeline.run(input, shown.settings, nome::stop_token{});
  REQUIRE(result);
  StagePipeline fresh_pipeline;
  const auto fresh = fresh_pipeline.run(input, shown.settings, nome::stop_token{});
  REQUIRE(fresh);
  CHECK(result->stage == shown.settings.stage);
  test::check_same_mesh(*result->mesh, *fresh->mesh);
  const render::DisplayTopology& topology = *result->display.topology;
  CHECK(topology.num_faces == result->mesh->num_faces());
  CHECK(topology.num_vertices == result->mesh->num_vertices());
  const render::DisplayPositions& positions = *result->display.positions;
  CHECK(positions.vertices.size() == result->mesh->num_vertices());
  CHECK(positions.face_normals.size() == result->mesh->num_faces());
  CHECK(positions.vertices == fresh->display.positions->vertices);
  CHECK(positions.vertex_normals == fresh->display.positions->vertex_normals);
  CHECK(positions.face_normals == fresh->display.positions->face_normals);
  CHECK(topology.triangles == fresh->display.topology->triangles);
  CHECK(result->topology.chi == topology_report(*result->mesh).chi);
  CHECK(result->topology.borders == topology_report(*result->mesh).borders);
}

void show_stage(Shown& shown, Stage stage) {
  shown.settings.stage = stage;
  shown.steps += std::string(" stage ") + to_string(stage);
}

}  // namespace

TEST_CASE("every stage to every other stage and back, the display arrays of a fresh run each time", "[app]") {
  for (Surface& surface : surfaces()) {
    INFO(surface.name);
    PipelineInput input;
    input.soup = std::move(surface.soup);
    for (const Stage from : every_stage)
      for (const Stage to : every_stage) {
        StagePipeline pipeline;
        Shown shown;
        show_stage(shown, from);
        check_like_fresh(pipeline, input, shown);
        show_stage(shown, to);
        check_like_fresh(pipeline, input, shown);
        show_stage(shown, from);
        check_like_fresh(pipeline, input, shown);
        // The levels changed while another stage is shown, then back to it.
        shown.settings.subdivision_levels = 1;
        shown.steps += " levels 1";
        check_like_fresh(pipeline, input, shown);
        show_stage(shown, to);
        check_like_fresh(pipeline, input, shown);
        shown.settings.subdivision_levels = 2;
        shown.steps += " levels 2";
        show_stage(shown, from);
        check_like_fresh(pipeline, input, shown);
      }
  }
}

TEST_CASE("the offset turned off and on again, levels changed between, gives the solid back", "[app]") {
  for (Surface& surface : surfaces()) {
    INFO(surface.name);
    PipelineInput input;
    input.soup = std::move(surface.soup);
    StagePipeline pipeline;
    Shown shown;
    // The viewer's own commands: `offset D` shows the offset stage, `offset 0` the subdivided one, `subdiv
    // N` sets the levels before the offset.
    const auto offset = [&](double distance) {
      shown.steps += " offset " + std::to_string(distance);
      if (distance == 0) {
        shown.settings.stage = Stage::subdivided;
      } else {
        shown.settings.offset_distance = distance;
        shown.settings.stage = Stage::offset;
      }
      check_like_fresh(pipeline, input, shown);
    };
    const auto subdiv = [&](int levels) {
      shown.steps += " subdiv " + std::to_string(levels);
      shown.settings.subdivision_levels = levels;
      if (is_editable(shown.settings.stage)) shown.settings.stage = Stage::subdivided;
      check_like_fresh(pipeline, input, shown);
    };
    offset(0.05);
    offset(0);
    offset(0.05);
    subdiv(1);
    offset(0.05);
    offset(0);
    offset(0.05);
    subdiv(2);
    offset(0);
    offset(0.04);
    offset(0);
    subdiv(1);
    offset(0.04);
    // The levels after the offset, on and off, and the offset off under them.
    shown.settings.subdivision_after = 1;
    show_stage(shown, Stage::subdivided_offset);
    check_like_fresh(pipeline, input, shown);
    offset(0);
    show_stage(shown, Stage::subdivided_offset);
    check_like_fresh(pipeline, input, shown);
    show_stage(shown, Stage::offset);
    check_like_fresh(pipeline, input, shown);
  }
}

TEST_CASE("slider ticks between stage changes keep every stage in step with a fresh run", "[app]") {
  viewer::Session session = viewer::Session::open(NOME_SOURCE_DIR "/assets/funnel_cube_consolidated.nome");
  StagePipeline pipeline;
  Shown shown;
  double height = 0.3;
  for (const Stage stage : {Stage::offset, Stage::subdivided, Stage::offset, Stage::scene, Stage::offset,
                            Stage::subdivided_offset, Stage::subdivided, Stage::subdivided_offset}) {
    show_stage(shown, stage);
    height += 0.05;
    session.set_parameter("fp_h", height);
    shown.steps += " fp_h " + std::to_string(height);
    INFO("steps: " << shown.steps);
    const auto result = pipeline.run(session.scene_input(), shown.settings, nome::stop_token{});
    REQUIRE(result);
    StagePipeline fresh_pipeline;
    const auto fresh = fresh_pipeline.run(session.scene_input(), shown.settings, nome::stop_token{});
    REQUIRE(fresh);
    test::check_same_mesh(*result->mesh, *fresh->mesh);
    CHECK(result->display.positions->vertices == fresh->display.positions->vertices);
    CHECK(result->display.topology->num_faces == result->mesh->num_faces());
  }
}
