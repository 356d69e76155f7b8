#include <catch2/catch.hpp>

#include "nome/mesh/topology_report.hpp"
#include "viewer/stage_pipeline.hpp"

using namespace nome;
using nome::viewer::Stage;
using nome::viewer::StagePipeline;
using nome::viewer::StageSettings;

namespace {

// Two unit squares side by side, each with its own copy of the shared edge (two pieces until merged).
PolygonSoup two_pieces() {
  PolygonSoup soup;
  for (const double x : {0.0, 1.0}) {
    const Index a = soup.add_vertex({x, 0, 0}), b = soup.add_vertex({x + 1, 0, 0}),
                c = soup.add_vertex({x + 1, 1, 0}), d = soup.add_vertex({x, 1, 0});
    soup.add_face({a, b, c, d});
  }
  return soup;
}

Mesh shown(StagePipeline& pipeline, const PolygonSoup& soup, const StageSettings& settings) {
  const auto result = pipeline.run(soup, settings, std::stop_token{});
  REQUIRE(result);
  CHECK(result->display.num_faces == result->mesh->num_faces());
  CHECK(result->stage == settings.stage);
  CHECK(result->topology.faces == result->mesh->num_faces());
  return *result->mesh;
}

}  // namespace

TEST_CASE("the later stages start from the merged mesh, or from the scene's pieces on their own", "[app]") {
  StagePipeline pipeline;
  const PolygonSoup soup = two_pieces();
  StageSettings settings;
  settings.stage = Stage::subdivided;
  settings.subdivision_levels = 1;
  // Merged: one 4 x 2 grid of quads; apart: two 2 x 2 grids.
  CHECK(shown(pipeline, soup, settings).num_vertices() == 15);
  settings.subdivide_merged = false;
  const Mesh apart = shown(pipeline, soup, settings);
  CHECK(apart.num_vertices() == 18);
  CHECK(apart.num_components() == 2);

  settings.subdivide_merged = true;
  settings.stage = Stage::offset;
  const TopologyReport solid = topology_report(shown(pipeline, soup, settings));
  CHECK(solid.borders == 0);
  CHECK(solid.orientable);
  CHECK(solid.chi == 2);  // a disc thickened into a ball's skin
  settings.stage = Stage::subdivided_offset;
  settings.subdivision_after = 1;
  CHECK(shown(pipeline, soup, settings).num_faces() == 4 * (2 * 8 + 12));  // two sheets and the rim strip
}

TEST_CASE("only the scene and merged stages take edits; a stopped run does nothing", "[app]") {
  CHECK(viewer::is_editable(Stage::scene));
  CHECK(viewer::is_editable(Stage::merged));
  CHECK_FALSE(viewer::is_editable(Stage::subdivided));
  CHECK_FALSE(viewer::is_editable(Stage::offset));
  CHECK_FALSE(viewer::is_editable(Stage::subdivided_offset));
  std::stop_source stop;
  stop.request_stop();
  StagePipeline pipeline;
  CHECK_FALSE(pipeline.run(two_pieces(), StageSettings{}, stop.get_token()));
}
