// Rim lines (report 6.3) zipped by the document: to a funnel's rim, to another rim line.
#include <catch2/catch.hpp>

#include <cmath>

#include "nome/edit/document.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/scene/scene_rim_lines.hpp"
#include "scene/scene_support.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

// A funnel whose high circle (radius 1.5 at z = 1) is ringed by a closed rim line of eight points of
// radius `radius` at the same height, and a second rim line above it.
std::string funnel_and_rims(double radius) {
  std::string text = "funnel fun (8 1 0.5 1) endfunnel\n";
  for (int line = 0; line < 2; ++line)
    for (int i = 0; i < 8; ++i) {
      const double a = 2 * 3.14159265358979323846 * i / 8;
      text += "point p" + std::to_string(line) + "_" + std::to_string(i) + " (" +
              std::to_string(radius * std::cos(a)) + " " + std::to_string(radius * std::sin(a)) + " " +
              std::to_string(1 + line) + ") endpoint\n";
    }
  for (int line = 0; line < 2; ++line) {
    text += "polyline rim" + std::to_string(line) + " (";
    for (int i = 0; i < 8; ++i) text += "p" + std::to_string(line) + "_" + std::to_string(i) + " ";
    text += ") isloop endpolyline\n";
  }
  return text + "instance f fun endinstance\ninstance r0 rim0 endinstance\ninstance r1 rim1 endinstance\n";
}

std::vector<std::string> loop_names(const RimLines& rims, Index line) {
  std::vector<std::string> names(rims.names.begin() + rims.offsets[line],
                                 rims.names.begin() + rims.offsets[line + 1]);
  names.push_back(names.front());
  return names;
}

// The merged stage as the viewer shows it: the scene's, consolidated and temporary faces joined where
// their borders meet.
TopologyReport edited_topology(const Document& document) {
  Pipeline pipeline;
  pipeline.set_input(document.pipeline_input());
  PipelineSettings settings;
  settings.stage = Stage::merged;
  return topology_report(pipeline.run(settings));
}

}  // namespace

TEST_CASE("a polyline rim zipped to a funnel's rim gives one surface", "[scene]") {
  const Scene scene = Scene::from_text(funnel_and_rims(2.5), "rims.nome");
  const RimLines rims = scene_rim_lines(scene);
  REQUIRE(rims.num_lines() == 2);
  CHECK(rims.names[0] == "r0_p0_0");
  Document document(scene.combined_soup());
  std::vector<std::string> high_circle;
  for (int i = 0; i <= 8; ++i) high_circle.push_back("f_hc" + std::to_string(i % 8));
  const EditOutcome zipped = document.zip_chains(loop_names(rims, 0), high_circle);
  INFO(zipped.message);
  REQUIRE(zipped.applied);
  CHECK(document.temporary_faces().size() == 8);
  const TopologyReport t = edited_topology(document);
  CHECK(t.components.size() == 1);
  CHECK(t.orientable);
  CHECK(t.borders == 2);  // the funnel's base circle and the rim line
  CHECK(t.mobius_edges == 0);
  CHECK(t.chi == 0);

  SECTION("the strip's orientation follows the funnel's faces whichever chain comes first") {
    REQUIRE(document.undo());
    REQUIRE(document.zip_chains(high_circle, loop_names(rims, 0)).applied);
    CHECK(edited_topology(document).mobius_edges == 0);
  }
  SECTION("then the second rim line is zipped to the first: still one surface, one border more ringed") {
    REQUIRE(document.zip_chains(loop_names(rims, 1), loop_names(rims, 0)).applied);
    const TopologyReport two = edited_topology(document);
    CHECK(two.components.size() == 1);
    CHECK(two.orientable);
    CHECK(two.borders == 2);
    CHECK(two.mobius_edges == 0);
  }
  SECTION("a loop and a segment, an unknown or a shared vertex are refused") {
    REQUIRE(document.undo());
    auto segment = loop_names(rims, 1);
    segment.pop_back();
    CHECK_THAT(document.zip_chains(segment, high_circle).message, Catch::Contains("whole loop"));
    CHECK_THAT(document.zip_chains({"nowhere", "f_hc0"}, {"f_hc1", "f_hc2"}).message,
               Catch::Contains("no vertex named nowhere"));
    CHECK_THAT(document.zip_chains(high_circle, high_circle).message, Catch::Contains("overlap at f_hc"));
    CHECK(document.temporary_faces().empty());
  }
}
