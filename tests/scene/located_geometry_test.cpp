#include <catch2/catch.hpp>

#include "nome/edit/scene_document.hpp"
#include "nome/error.hpp"
#include "nome/ops/pipeline.hpp"

using namespace nome;

namespace {

// Four points and a mesh of two faces; the second face is written on line 8.
std::string located_two_faces(const std::string& second_face) {
  return "point a (0 0 0) endpoint\n"
         "point b (1 0 0) endpoint\n"
         "point c (1 1 0) endpoint\n"
         "point d (0 1 0) endpoint\n"
         "point e (0 0 0) endpoint\n"
         "mesh m\n"
         "  face f1 (a b c) endface\n"
         "  face f2 " +
         second_face +
         " endface\n"
         "endmesh\n"
         "instance j m endinstance\n";
}

std::string located_build_error(const std::string& text, Joining joining) {
  PipelineInput input;
  input.soup = scene::Scene::from_text(text, "t.nome").combined_soup();
  input.joining = joining;
  Pipeline pipeline;
  try {
    pipeline.set_input(std::move(input));
  } catch (const TopologyError& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST_CASE("a face that repeats a vertex is located at its face statement", "[scene]") {
  const std::string text = located_two_faces("(a c d c)");
  for (const Joining joining : {Joining::manifold, Joining::across_edges})
    CHECK(located_build_error(text, joining) == "t.nome:8:8: not a 2-manifold: face j_f2 repeats vertex j_c");
}

TEST_CASE("an edge of three faces is located at the face statement that adds the third", "[scene]") {
  const std::string text =
      "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (0 1 0) endpoint\n"
      "point d (0 -1 0) endpoint point e (0 0 1) endpoint\n"
      "mesh m face f1 (a b c) endface face f2 (b a d) endface\n"
      "  face f3 (a b e) endface endmesh\n"
      "instance j m endinstance\n";
  CHECK_THAT(located_build_error(text, Joining::manifold),
             Catch::StartsWith("t.nome:4:8: not a 2-manifold: edge (j_a, j_b) has a third face j_f3"));
  // The viewer's joining keeps the faces apart and warns, located the same way.
  PipelineInput input;
  input.soup = scene::Scene::from_text(text, "t.nome").combined_soup();
  input.joining = Joining::across_edges;
  Pipeline pipeline;
  pipeline.set_input(std::move(input));
  pipeline.run(PipelineSettings{});
  REQUIRE(pipeline.warnings().size() == 1);
  CHECK_THAT(pipeline.warnings()[0], Catch::StartsWith("t.nome:3:13: edge (j_a, j_b) has 3 faces"));
}

TEST_CASE("a face with coinciding vertices is warned about on load at its statement", "[scene]") {
  SceneDocument doc =
      SceneDocument::from_scene(scene::Scene::from_text(located_two_faces("(a c d e)"), "t.nome"));
  Pipeline pipeline;
  pipeline.set_input(doc.pipeline_input());
  pipeline.run(PipelineSettings{});
  REQUIRE(pipeline.warnings().size() == 1);
  CHECK(pipeline.warnings()[0] ==
        "t.nome:8:8: face j_f2 has coinciding vertices j_a and j_e (no normal "
        "there: its offset and shading are undefined)");
}

TEST_CASE("a generator's faces are located at its statement", "[scene]") {
  const scene::Scene s = scene::Scene::from_text(
      "funnel f (4 1 0.5 1) endfunnel\ninstance a f endinstance\n  instance b f endinstance\n", "t.nome");
  const PolygonSoup soup = s.combined_soup();
  REQUIRE(soup.num_faces() == 8);
  CHECK(soup.origin(0) == "t.nome:1:8");
  CHECK(soup.origin(7) == "t.nome:1:8");
}
