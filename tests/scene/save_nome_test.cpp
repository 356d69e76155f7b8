#include <catch2/catch.hpp>

#include <filesystem>

#include "nome/io/read_scene.hpp"
#include "nome/scene/save_nome.hpp"
#include "scene/scene_support.hpp"
#include "support/face_colors.hpp"
#include "support/scratch_files.hpp"
#include "support/shared_examples.hpp"

using namespace nome;
using nome::scene::Scene;

namespace {

// Same vertices (names, exact positions), same faces, same colours, same rim lines.
void check_same_geometry(const Scene& a, const Scene& b) {
  REQUIRE(a.instances().size() == b.instances().size());
  for (size_t i = 0; i < a.instances().size(); ++i) {
    const scene::Piece& x = a.instances()[i].geometry;
    const scene::Piece& y = b.instances()[i].geometry;
    CHECK(a.instances()[i].name == b.instances()[i].name);
    CHECK(x.soup.positions == y.soup.positions);
    CHECK(x.soup.vertex_names == y.soup.vertex_names);
    CHECK(x.soup.face_offsets == y.soup.face_offsets);
    CHECK(x.soup.face_vertices == y.soup.face_vertices);
    CHECK(x.soup.face_names == y.soup.face_names);
    CHECK(test::face_colors(x.soup) == test::face_colors(y.soup));
    CHECK(x.soup.sharp_edges == y.soup.sharp_edges);
    CHECK(x.rims.size() == y.rims.size());
  }
}

Scene reread(const Scene& s) {
  return Scene::from_text(scene::to_nome_text(s), "saved.nome");
}

}  // namespace

TEST_CASE("saving every example and reading it back gives the same geometry", "[scene]") {
  const std::vector<std::string> files = test::scene_files();
  for (const std::string& file : files) {
    INFO(file);
    const Scene s = read_scene(file);
    check_same_geometry(s, reread(s));
  }
  // The project's own scenes, then the 2016 program's, which a clone without ../shared leaves out.
  CHECK(files.size() >= 7);
  NOME_NEEDS_SHARED_EXAMPLES("original");
  CHECK(files.size() >= 12);
}

TEST_CASE("an edited scene saves its slider values, consolidated faces and deletions", "[scene]") {
  // Edits by any unique suffix, dotted or not: the deletions are saved by full name, the consolidated
  // faces as written.
  const std::string text =
      test::read_text(test::assets_dir() + "funnel_cube.nome") +
      "consolidate\n"
      "  consolidateface vertex fun3_hc3 endvertex vertex fun5_hc3 endvertex vertex fun2_hc5 "
      "endvertex endconsolidateface\n"
      "  consolidateface vertex fun3_hc3 endvertex vertex fun2_hc5 endvertex vertex fun2_hc6 "
      "endvertex vertex fun3_hc2 endvertex endconsolidateface\n"
      "endconsolidate\n"
      "delete face fun1_f0 endface face cf.fun6.f3 endface enddelete\n";
  Scene s = Scene::from_text(text, "funnel_cube.nome");
  s.set_parameter(*s.find_parameter("fp_ro"), 0.5);
  s.set_parameter(*s.find_parameter("fp_z"), -1.1);
  CHECK(s.edits().deleted == std::vector<std::string>{"cf_fun1_f0", "cf_fun6_f3"});
  REQUIRE(s.instances().size() == 2);
  CHECK(s.instances()[0].geometry.soup.num_faces() == 46);
  CHECK(s.instances()[1].name == "consolidatemesh");
  CHECK(s.instances()[1].geometry.soup.num_faces() == 2);

  const std::string dir = test::scratch_path("nome_save_test", "").parent_path();
  scene::write_nome(s, dir + "/edited.nome");
  const Scene back = read_scene(dir + "/edited.nome");
  check_same_geometry(s, back);
  CHECK(back.parameters()[*back.find_parameter("fp_z")].value == -1.1);
  CHECK(back.edits().consolidated.size() == 2);
  const std::string saved = scene::to_nome_text(s);
  CHECK_THAT(saved, Catch::Contains("    set z -1.1 -1.5 -0.1 0.1\n"));
  CHECK_THAT(saved, Catch::Contains("delete\n    face cf_fun1_f0 endface\n"));
  CHECK_THAT(saved, Catch::Contains("consolidate\n    consolidateface\n        vertex fun3_hc3 endvertex\n"));
  CHECK_THAT(saved, Catch::Contains("translate (0 0 {expr $fp_z}) rotate (1 0 0) (180)"));
}

TEST_CASE("unknown names in the editing data are refused with candidates, shown or kept by an editor",
          "[scene]") {
  const std::string cube = test::read_text(test::assets_dir() + "funnel_cube.nome");
  for (const bool shows_edits : {true, false}) {
    INFO("shows_edits " << shows_edits);
    const scene::SceneOptions options{.shows_edits = shows_edits};
    CHECK_THROWS_WITH(Scene::from_text(cube + "delete face fun1_f9 endface enddelete\n", "t.nome", options),
                      Catch::Contains("unknown face 'fun1_f9' (did you mean"));
    CHECK_THROWS_WITH(
        Scene::from_text(cube + "consolidate consolidateface vertex hc3 endvertex vertex fun5_hc3 "
                                "endvertex vertex fun2_hc5 endvertex endconsolidateface endconsolidate\n",
                         "t.nome", options),
        Catch::Contains("ambiguous vertex name 'hc3': 6 candidates: cf_fun1_hc3"));
  }
}

TEST_CASE("a scene read for an editor resolves its edits to full names, shows none and hands them over",
          "[scene]") {
  const std::string text = test::read_text(test::assets_dir() + "funnel_cube.nome") +
                           "consolidate consolidateface vertex fun3.hc3 endvertex vertex fun5_hc3 endvertex "
                           "vertex fun2_hc5 endvertex endconsolidateface endconsolidate\n"
                           "delete face fun1_f0 endface enddelete\n"
                           "sharpedges 2 (fun1_bc1 fun1_bc2) endsharpedges\n";
  const Scene shown = Scene::from_text(text, "t.nome");
  const std::uint64_t evaluations = scene::scene_evaluation_count();
  Scene kept = Scene::from_text(text, "t.nome", {.shows_edits = false});
  CHECK(scene::scene_evaluation_count() == evaluations + 1);
  REQUIRE(kept.instances().size() == 1);
  CHECK(kept.instances()[0].geometry.soup.num_faces() == 48);
  CHECK(kept.combined_soup().sharp_edges.empty());
  CHECK(shown.instances().size() == 2);
  CHECK(shown.instances()[0].geometry.soup.num_faces() == 47);
  CHECK(shown.combined_soup().sharp_edges.size() == 1);

  const scene::SceneEdits edits = kept.take_edits();
  CHECK(scene::scene_evaluation_count() == evaluations + 1);
  CHECK(edits.consolidated ==
        std::vector<std::vector<std::string>>{{"cf_fun3_hc3", "cf_fun5_hc3", "cf_fun2_hc5"}});
  CHECK(edits.deleted == std::vector<std::string>{"cf_fun1_f0"});
  CHECK(edits.sharp == std::vector<NamedSharpEdge>{{"cf_fun1_bc1", "cf_fun1_bc2", 2.0f}});
  CHECK(kept.edits().empty());
  CHECK(kept.ast().consolidated_faces.empty());
  CHECK(kept.ast().deleted_faces.empty());
  CHECK(kept.ast().sharp_edges.empty());
  // The scene that showed them hands over the same, evaluated again without the consolidated mesh.
  Scene was_shown = shown;
  CHECK(was_shown.take_edits().consolidated == edits.consolidated);
  CHECK(was_shown.instances().size() == 1);
  CHECK(was_shown.instances()[0].geometry.soup.num_faces() == 48);
  CHECK(scene::to_nome_text(was_shown) == scene::to_nome_text(kept));
}

TEST_CASE(".anom files apply saved slider values and a working mesh to an open scene", "[scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  Scene s = test::load_scene_file(test::originals_dir() + "kleinbottle.nom");
  s.set_parameter(*s.find_parameter("tp3_x"), 1);
  s.apply_anom(test::read_text(test::originals_dir() + "kleinbottle_s1.anom"), "s1.anom");
  CHECK(s.parameters()[*s.find_parameter("tp3_x")].value == -2);
  REQUIRE(s.instances().size() == 2);
  CHECK(s.instances()[1].geometry.soup.num_faces() == 8);
  CHECK(s.edits().consolidated[0] == std::vector<std::string>{"t1_lc5", "t1_lc4", "t5_lc4", "t5_lc5"});
  CHECK_THROWS_WITH(s.apply_anom("savedparameter tp9_n 8 endsavedparameter\n", "bad.anom"),
                    Catch::Contains("bad.anom:1:16: unknown parameter 'tp9_n' (did you mean tp1_n"));
}
