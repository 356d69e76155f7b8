// In the successor's dialect a subdivision welds coincident vertices first, as JIPCAD's merger does; the
// 2016 dialect merges only when asked.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "nome/mesh/topology_report.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/scene/scene.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

// Six separate unit squares round the origin, the faces of the cube [-1, 1]^3 (JIPCAD's hello cube).
constexpr const char* weld_six_faces =
    "point p1 (1 1 1) endpoint\npoint p2 (1 -1 1) endpoint\npoint p3 (-1 -1 1) endpoint\n"
    "point p4 (-1 1 1) endpoint\nmesh one_face face f1 (p4 p3 p2 p1) endface endmesh\n"
    "group cube\ninstance front one_face endinstance\n"
    "instance back one_face rotate (0 1 0) (180) endinstance\n"
    "instance left one_face rotate (0 1 0) (-90) endinstance\n"
    "instance right one_face rotate (0 1 0) (90) endinstance\n"
    "instance top one_face rotate (1 0 0) (90) endinstance\n"
    "instance bottom one_face rotate (1 0 0) (-90) endinstance\nendgroup\n";

// How many of the mesh's vertices lie at p.
int weld_vertices_at(const Mesh& mesh, Vec3 p) {
  int n = 0;
  for (const Vec3& q : mesh.positions()) n += glm::length(q - p) < 1e-9;
  return n;
}

}  // namespace

TEST_CASE("subdivision weld: a successor file's subdivision welds its six faces into one closed cube",
          "[scene]") {
  const Scene s =
      Scene::from_text(std::string(weld_six_faces) +
                           "subdivision sub0 sd_level 1 instance i cube endinstance endsubdivision\n",
                       "t.nom");
  REQUIRE(s.dialect().dialect == Dialect::jipcad);
  const StageSettings stages = s.stage_settings();
  CHECK(stages.welds_before_subdividing);
  PipelineSettings settings;
  settings.subdivision_levels = *stages.subdivision_levels;
  CHECK(weld_before_subdividing(stages, settings));
  CHECK(settings.should_merge);
  Pipeline pipeline;
  pipeline.set_input(PipelineInput{s.combined_soup(), {}, {}});
  const Mesh& mesh = pipeline.run(settings);
  const TopologyReport r = topology_report(mesh);
  CHECK(r.components.size() == 1);
  CHECK(r.borders == 0);
  CHECK(r.chi == 2);
  CHECK(r.faces == 24);
  // Catmull-Clark moves a cube's corner, of three faces, to 5/9 of it: (Q + 2R) / 3 with the faces'
  // centres Q = c/3 and the edges' midpoints R = 2c/3. Each face alone would keep its corners.
  for (const double x : {-1.0, 1.0})
    for (const double y : {-1.0, 1.0})
      for (const double z : {-1.0, 1.0}) {
        INFO(x << " " << y << " " << z);
        CHECK(weld_vertices_at(mesh, Vec3(x, y, z) * (5.0 / 9.0)) == 1);
        CHECK(weld_vertices_at(mesh, Vec3(x, y, z)) == 0);
      }
}

TEST_CASE("subdivision weld: the successor's files weld only where they subdivide, the 2016 dialect's never",
          "[scene]") {
  const Scene successor = Scene::from_text(
      "# nome-dialect: jipcad\n" + std::string(weld_six_faces) + "instance i cube endinstance\n", "t.nom");
  REQUIRE(successor.dialect().dialect == Dialect::jipcad);
  PipelineSettings unrefined;
  CHECK_FALSE(weld_before_subdividing(successor.stage_settings(), unrefined));
  CHECK_FALSE(unrefined.should_merge);
  PipelineSettings before_subdividing;
  before_subdividing.subdivision_levels = 2;
  before_subdividing.stage = Stage::merged;
  CHECK_FALSE(weld_before_subdividing(successor.stage_settings(), before_subdividing));
  CHECK_FALSE(before_subdividing.should_merge);

  const Scene report =
      Scene::from_text(std::string(weld_six_faces) + "instance i cube endinstance\n", "t.nome");
  REQUIRE(report.dialect().dialect == Dialect::report2016);
  CHECK_FALSE(report.stage_settings().welds_before_subdividing);
  PipelineSettings settings;
  settings.subdivision_levels = 1;
  CHECK_FALSE(weld_before_subdividing(report.stage_settings(), settings));
  CHECK_FALSE(settings.should_merge);
  Pipeline pipeline;
  pipeline.set_input(PipelineInput{report.combined_soup(), {}, {}});
  const TopologyReport r = topology_report(pipeline.run(settings));
  CHECK(r.components.size() == 6);
  CHECK(r.borders == 6);
}
