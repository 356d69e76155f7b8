#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>

#include "nome/edit/scene_document.hpp"
#include "nome/error.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "nome/ops/pipeline.hpp"
#include "scene/scene_support.hpp"
#include "support/scratch_files.hpp"
#include "support/shared_examples.hpp"

using namespace nome;

namespace {

const scene::SceneOptions for_document{.shows_edits = false};

SceneDocument read_document(const std::string& path) {
  return SceneDocument::from_scene(scene::Scene::from_text(test::read_text(path), path, for_document));
}

// The scene's vertex names around face f of the document's scene geometry.
std::vector<std::string> face_vertices(const PolygonSoup& soup, Index f) {
  std::vector<std::string> names;
  for (Index k = soup.face_offsets[f]; k < soup.face_offsets[f + 1]; ++k)
    names.push_back(soup.vertex_names[soup.face_vertices[k]]);
  return names;
}

// One edit of each kind a file keeps: the first face deleted and added back as a consolidated face, and
// an edge of the second face given sharpness 2.5.
void edit_every_way(SceneDocument& doc) {
  Document& edits = doc.edits();
  const PolygonSoup& scene = edits.scene_geometry();
  const std::vector<std::string> first = face_vertices(scene, 0), second = face_vertices(scene, 1);
  REQUIRE(edits.delete_faces({scene.face_names[0]}).applied);
  REQUIRE(edits.add_polygon(first).applied);
  REQUIRE(edits.accept_temporary().applied);
  REQUIRE(edits.set_sharp({{second[0], second[1]}}, 2.5f).applied);
}

std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

// What the document writes, by save() and saved_text(), and again after reading its own file back.
std::string saved_twice(const SceneDocument& doc, const std::string& name) {
  const std::string path = test::scratch_path("nome_document_saving", name);
  CHECK(doc.save(path).empty());
  const std::string written = test::read_text(path);
  CHECK(written == doc.saved_text());
  CHECK(read_document(path).saved_text() == written);
  return written;
}

}  // namespace

// The expected files were written by the earlier save, which copied the scene, put the edits into the
// copy and evaluated it before writing it.
TEST_CASE("a document saves the same bytes as before, with consolidated faces, deletions and sharp edges",
          "[scene]") {
  const std::string expected = std::string(NOME_SOURCE_DIR) + "/tests/data/saved/";
  SceneDocument consolidated = read_document(test::assets_dir() + "funnel_cube_consolidated.nome");
  edit_every_way(consolidated);
  CHECK(saved_twice(consolidated, "consolidated.nome") ==
        test::read_text(expected + "funnel_cube_consolidated_edited.nome"));

  SceneDocument cube = read_document(test::assets_dir() + "funnel_cube.nome");
  cube.set_parameter("fp_ro", 0.5);
  edit_every_way(cube);
  CHECK(saved_twice(cube, "cube.nome") == test::read_text(expected + "funnel_cube_edited.nome"));
}

TEST_CASE("a JIPCAD document saves the same bytes as before", "[scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  // Their length and FNV-1a hash: the files are others' work, not copied here.
  const struct {
    const char* file;
    std::size_t size;
    std::uint64_t hash;
  } cases[] = {{"Twisted_TetraTangle.nom", 5222, 0x19fbe124f31f637eull},
               {"arts_expo__cross.nom", 933, 0x714c86f82475e8e6ull}};
  for (const auto& c : cases) {
    INFO(c.file);
    SceneDocument doc = read_document(test::shared_examples_dir("jipcad") + c.file);
    edit_every_way(doc);
    const std::string saved = saved_twice(doc, c.file);
    CHECK(saved.size() == c.size);
    CHECK(fnv1a(saved) == c.hash);
  }
}

TEST_CASE("a document is evaluated once when read, and not at all when saved", "[scene]") {
  const std::string file = test::assets_dir() + "funnel_cube_consolidated.nome";
  const std::string text = test::read_text(file);
  std::uint64_t evaluations = scene::scene_evaluation_count();
  SceneDocument doc = SceneDocument::from_scene(scene::Scene::from_text(text, file, for_document));
  CHECK(scene::scene_evaluation_count() == evaluations + 1);
  edit_every_way(doc);

  evaluations = scene::scene_evaluation_count();
  const std::string path = test::scratch_path("nome_document_saving", "evaluations.nome");
  CHECK(doc.save(path).empty());
  CHECK(doc.saved_edits().consolidated.size() == 1);
  CHECK(!doc.saved_text().empty());
  CHECK(scene::scene_evaluation_count() == evaluations);

  // The scene keeps no edits of its own: they are the document's.
  CHECK(doc.scene()->edits().empty());
  CHECK(doc.scene()->ast().consolidated_faces.empty());

  // Reading the saved file (its edits now in the text) is one evaluation; so is the text read again.
  evaluations = scene::scene_evaluation_count();
  SceneDocument back = read_document(path);
  CHECK(scene::scene_evaluation_count() == evaluations + 1);
  CHECK(back.edits().consolidated_faces().size() == 1);
  CHECK(back.edits().deleted_faces() == doc.edits().deleted_faces());
  CHECK(back.edits().sharp_edges() == doc.edits().sharp_edges());
  back.reload(scene::Scene::from_text(test::read_text(path), path, for_document));
  CHECK(scene::scene_evaluation_count() == evaluations + 2);
  CHECK(back.edits().consolidated_faces().size() == 1);
  CHECK(back.saved_text() == doc.saved_text());
}

TEST_CASE("an .anom file evaluates the document once and replaces its consolidated faces", "[scene]") {
  const std::string file = test::assets_dir() + "funnel_cube.nome";
  SceneDocument doc = read_document(file);
  edit_every_way(doc);
  const std::vector<std::string> deleted = doc.edits().deleted_faces();
  const std::uint64_t evaluations = scene::scene_evaluation_count();
  doc.apply_anom(
      "savedparameter fp_ro 0.5 endsavedparameter\n"
      "savedworkingmesh wm\n"
      "face vertex fun3.hc3 endvertex vertex fun5.hc3 endvertex vertex fun2.hc5 endvertex endface\n"
      "endsavedworkingmesh\n",
      "s.anom");
  CHECK(scene::scene_evaluation_count() == evaluations + 1);
  REQUIRE(doc.edits().consolidated_faces().size() == 1);
  CHECK(doc.edits().consolidated_faces()[0].vertices ==
        std::vector<std::string>{"cf_fun3_hc3", "cf_fun5_hc3", "cf_fun2_hc5"});
  CHECK(doc.edits().deleted_faces() == deleted);
  CHECK(doc.scene()->edits().empty());
  CHECK_THROWS_WITH(doc.apply_anom("savedworkingmesh wm\n"
                                   "face vertex fun2.hc9 endvertex vertex fun5.hc3 endvertex vertex fun3.hc3 "
                                   "endvertex endface\nendsavedworkingmesh\n",
                                   "bad.anom"),
                    Catch::Contains("bad.anom:2:13: unknown vertex 'fun2_hc9'"));
  CHECK(doc.edits().consolidated_faces().size() == 1);
}

TEST_CASE(
    "a colour changes the document's face attributes alone, and the pipeline carries it without a rebuild",
    "[kernel]") {
  SceneDocument doc = read_document(NOME_SOURCE_DIR "/assets/funnel_cube.nome");
  REQUIRE(doc.edits().delete_faces({doc.pipeline_input().soup.face_names[0]}).applied);
  const PipelineInput input = doc.pipeline_input();
  const std::uint64_t topology = doc.input_topology_version(), attributes = doc.input_attributes_version();
  Pipeline pipeline;
  pipeline.replace_input(input);
  PipelineSettings settings;
  settings.subdivision_levels = 1;
  settings.offset_distance = 0.02;
  settings.subdivision_after = 1;
  pipeline.run(settings);
  const std::uint64_t builds = build_mesh_count();

  doc.set_instance_color("cf_fun2", Color(1.0f, 0.0f, 0.0f));
  CHECK(doc.input_topology_version() == topology);
  CHECK(doc.input_attributes_version() > attributes);
  const Attributes faces = doc.pipeline_face_attributes();
  // Exactly what a whole new input would hold, the deleted face left out.
  CHECK(faces == doc.pipeline_input().soup.face_attributes);
  for (Index f = 0; f < input.soup.num_faces(); ++f)
    CHECK((face_color(faces, f) == Color(1.0f, 0.0f, 0.0f)) ==
          input.soup.face_names[f].starts_with("cf_fun2_"));

  pipeline.set_input_face_attributes(faces);
  const Mesh& solid = pipeline.run(settings);
  CHECK(build_mesh_count() == builds);
  CHECK(pipeline.work(Stage::subdivided) == StageWork::positions);
  CHECK(pipeline.work(Stage::subdivided_offset) == StageWork::positions);
  // The same colours as a pipeline that built the coloured input from the start.
  Pipeline fresh;
  fresh.replace_input(doc.pipeline_input());
  CHECK(solid.face_attributes() == fresh.run(settings).face_attributes());
  CHECK(find_colors(solid.face_attributes()));
  // Undone: the colours go again, still without a rebuild (the fresh pipeline built one).
  const std::uint64_t builds_before_undo = build_mesh_count();
  doc.set_instance_surface("cf_fun2", std::nullopt);
  pipeline.set_input_face_attributes(doc.pipeline_face_attributes());
  CHECK_FALSE(find_colors(pipeline.run(settings).face_attributes()));
  CHECK(build_mesh_count() == builds_before_undo);
  CHECK_THROWS_AS(Pipeline().set_input_face_attributes(faces), InvalidInputError);
}
