// The top-level `sharp` statement: creases and corners over instances' vertices by path, a generator's
// border by one of its vertices, weights that follow sliders, saved as written.
#include <catch2/catch.hpp>

#include "nome/ops/pipeline.hpp"
#include "nome/scene/save_nome.hpp"
#include "scene/scene_support.hpp"

using namespace nome;

namespace {

// Two funnels joined at their base rims (the second mirrored below z = 0): merged, the rim is a seam whose
// sharpness shapes the subdivision (a lone border is a crease anyway).
const char* const funnel_text =
    "bank fp\n  set n 8 3 12 1\n  set w 2 0 10 0.5\nendbank\n"
    "funnel fun ({expr $fp_n} 1 0.5 1) endfunnel\n"
    "instance f1 fun endinstance instance f2 fun mirror (0 0 1 0) endinstance\n";

// The scene's combined soup merged and subdivided `levels` times.
Buffer<Vec3> subdivided(const scene::Scene& s, int levels = 2) {
  Pipeline pipeline;
  PipelineInput input;
  input.soup = s.combined_soup();
  pipeline.set_input(std::move(input));
  PipelineSettings settings;
  settings.stage = Stage::subdivided;
  settings.should_merge = true;
  settings.subdivision_levels = levels;
  return pipeline.run(settings).positions();
}

scene::Scene funnel_with(const std::string& sharp) {
  return scene::Scene::from_text(std::string(funnel_text) + sharp, "t.nome");
}

std::string bc_ring(int n) {
  std::string ring;
  for (int i = 0; i <= n; ++i) ring += " f1_bc" + std::to_string(i % n);
  return ring;
}

}  // namespace

TEST_CASE("a top-level sharp border creases a funnel's rim as the chain of its vertices does", "[scene]") {
  const scene::Scene border = funnel_with("sharp 2 border (f1_bc0) endsharp\n");
  const scene::Scene chain = funnel_with("sharp 2 (" + bc_ring(8) + ") endsharp\n");
  const PolygonSoup soup = border.combined_soup();
  CHECK(soup.sharp_edges.size() == 8);
  CHECK(soup.sharp_edge_weights == std::vector<float>(8, 2.0f));
  CHECK(chain.combined_soup().sharp_edges.size() == 8);
  CHECK(subdivided(border, 3) == subdivided(chain, 3));
  CHECK(subdivided(border) != subdivided(funnel_with("")));
  CHECK(subdivided(border, 3) != subdivided(funnel_with("sharp border (f1_bc0) endsharp\n"), 3));
  CHECK(subdivided(border) != subdivided(funnel_with("sharp 1 border (f1_bc0) endsharp\n")));
  // A weight is no cue for the successor's dialect: the funnel keeps the report's argument order.
  CHECK(border.dialect().dialect == scene::Dialect::report2016);
}

TEST_CASE("a sharp border follows the slider of its vertex count and its weight the slider it reads",
          "[scene]") {
  scene::Scene s = funnel_with("sharp {expr $fp_w} border (f1_bc0) endsharp\nsharp 1.5 (f1_hc3) endsharp\n");
  CHECK(s.combined_soup().sharp_vertices.size() == 1);
  s.set_parameter(*s.find_parameter("fp_n"), 11);
  CHECK(s.combined_soup().sharp_edges.size() == 11);
  s.set_parameter(*s.find_parameter("fp_w"), 0.5);
  CHECK_FALSE(s.last_change_moved_vertices_only());
  CHECK(s.combined_soup().sharp_edge_weights == std::vector<float>(11, 0.5f));
}

TEST_CASE("top-level sharp statements are saved as written and read back to the same creases", "[scene]") {
  const scene::Scene s =
      funnel_with("sharp {expr $fp_w} border (f1_bc0 f1_hc0) endsharp\nsharp (f1_hc3) endsharp\n");
  const std::string saved = scene::to_nome_text(s);
  CHECK_THAT(saved, Catch::Contains("sharp {expr $fp_w} border (f1_bc0 f1_hc0) endsharp\n"));
  CHECK_THAT(saved, Catch::Contains("sharp (f1_hc3) endsharp\n"));
  const scene::Scene back = scene::Scene::from_text(saved, "saved.nome");
  CHECK(back.combined_soup().sharp_edges == s.combined_soup().sharp_edges);
  CHECK(back.combined_soup().sharp_vertices == s.combined_soup().sharp_vertices);
  CHECK(subdivided(back) == subdivided(s));
}

TEST_CASE("a top-level sharp names vertices that exist, edges of faces, borders and weights of 0 or more",
          "[scene]") {
  const std::string prefix = std::string(funnel_text);
  CHECK(test::scene_errors(prefix + "sharp (f1_hc0 f1_zz) endsharp\n") ==
        std::vector<std::string>{"t.nome:7:15: unknown vertex 'f1_zz'"});
  CHECK(test::scene_errors(prefix + "sharp (f1_hc0 f1_bc4) endsharp\n") ==
        std::vector<std::string>{"t.nome:7:15: (f1_hc0, f1_bc4) is no edge of the scene's faces"});
  CHECK(test::scene_errors(prefix + "sharp -1 (f1_hc0 f1_hc1) endsharp\n") ==
        std::vector<std::string>{"t.nome:7:7: a sharpness is 0 or more, found -1"});
  const std::string cube =
      "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (0 1 0) endpoint point d (0 0 1) endpoint\n"
      "mesh t face f0 (a c b) endface face f1 (a b d) endface face f2 (b c d) endface face f3 (c a d) "
      "endface endmesh\ninstance k t endinstance\n";
  CHECK(test::scene_errors(cube + "sharp border (k_a) endsharp\n") ==
        std::vector<std::string>{"t.nome:4:15: 'k_a' is on no border of instance k"});
}
