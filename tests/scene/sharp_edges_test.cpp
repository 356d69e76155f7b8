// Sharp edges marked as edits (the viewer's edge mode and K): kept by name, undone, saved as
// `sharpedges`, read back, and used by subdivision.
#include <catch2/catch.hpp>

#include "nome/edit/scene_document.hpp"
#include "nome/ops/pipeline.hpp"
#include "scene/scene_support.hpp"

using namespace nome;

namespace {

const char* const sharp_cube_text =
    "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (1 1 0) endpoint point d (0 1 0) endpoint\n"
    "point e (0 0 1) endpoint point f (1 0 1) endpoint point g (1 1 1) endpoint point h (0 1 1) endpoint\n"
    "mesh box\n"
    "  face bottom (a d c b) endface face top (e f g h) endface face front (a b f e) endface\n"
    "  face back (c d h g) endface face left (a e h d) endface face right (b c g f) endface\n"
    "  sharp (a b) endsharp\n"
    "endmesh\n"
    "instance k box endinstance\n";

// The document's scene subdivided `levels` times.
Buffer<Vec3> sharp_subdivided(const SceneDocument& doc, int levels = 1) {
  Pipeline pipeline;
  pipeline.set_input(doc.pipeline_input());
  PipelineSettings s;
  s.stage = Stage::subdivided;
  s.subdivision_levels = levels;
  return pipeline.run(s).positions();
}

}  // namespace

TEST_CASE("an edge marked sharp as an edit is undone, refused where it cannot be, and subdivides as a crease",
          "[scene]") {
  SceneDocument doc = SceneDocument::from_scene(scene::Scene::from_text(sharp_cube_text, "t.nome"));
  const Buffer<Vec3> smooth = sharp_subdivided(doc);
  Document& edits = doc.edits();
  const EditOutcome marked = edits.set_sharp({{"k_g", "k_f"}}, infinite_sharpness);
  CHECK(marked.applied);
  CHECK(marked.message == "1 edge marked sharp");
  CHECK(edits.sharp_edges() == std::vector<NamedSharpEdge>{{"k_f", "k_g"}});
  CHECK(doc.pipeline_input().soup.sharp_edges.size() == 2);  // the text's (a b) and the edit's
  const Buffer<Vec3> creased = sharp_subdivided(doc);
  CHECK(creased != smooth);

  CHECK_FALSE(edits.set_sharp({{"k_f", "k_g"}}, infinite_sharpness).applied);  // sharp already
  CHECK(edits.set_sharp({{"k_a", "k_g"}}, infinite_sharpness).message ==
        "(k_a, k_g) is no edge of the scene's faces (an added face's edges cannot be sharp yet)");
  CHECK(edits.set_sharp({{"k_a", "k_b"}}, 0.0f).message ==
        "(k_a, k_b) is sharp in the scene's text: change its `sharp` there");
  CHECK(edits.undo());
  CHECK(edits.sharp_edges().empty());
  CHECK(sharp_subdivided(doc) == smooth);
  CHECK(edits.redo());
  CHECK(edits.set_sharp({{"k_f", "k_g"}}, 0.0f).message == "1 edge marked smooth");
  CHECK(edits.sharp_edges().empty());
}

TEST_CASE("sharp edges marked as edits are saved as sharpedges and read back", "[scene]") {
  SceneDocument doc = SceneDocument::from_scene(scene::Scene::from_text(sharp_cube_text, "t.nome"));
  REQUIRE(doc.edits().set_sharp({{"k_f", "k_g"}, {"k_h", "k_g"}}, infinite_sharpness).applied);
  const std::string saved = doc.saved_text();
  CHECK_THAT(saved, Catch::Contains("sharpedges\n    (k_f k_g)\n    (k_g k_h)\nendsharpedges\n"));
  const SceneDocument back = SceneDocument::from_scene(scene::Scene::from_text(saved, "saved.nome"));
  CHECK(back.edits().sharp_edges() == doc.edits().sharp_edges());
  CHECK(sharp_subdivided(back) == sharp_subdivided(doc));
  // The command line sees them too: the scene's own soup carries them.
  CHECK(scene::Scene::from_text(saved, "saved.nome").combined_soup().sharp_edges.size() == 3);
  CHECK(test::scene_errors(std::string(sharp_cube_text) + "sharpedges (k_a k_zz) endsharpedges\n") ==
        std::vector<std::string>{"t.nome:9:17: unknown vertex 'k_zz'"});
}

TEST_CASE(
    "a weighted sharp edit subdivides as the text's sharp with that weight, saves, and undoes to the "
    "weight before",
    "[scene]") {
  std::string plain = sharp_cube_text;
  plain.replace(plain.find("  sharp (a b) endsharp\n"), 23, "");
  std::string weighted = plain;
  weighted.replace(weighted.find("endmesh"), 0, "  sharp 2.5 (f g h) endsharp\n");
  SceneDocument doc = SceneDocument::from_scene(scene::Scene::from_text(plain, "t.nome"));
  Document& edits = doc.edits();
  CHECK(edits.set_sharp({{"k_f", "k_g"}, {"k_g", "k_h"}}, 1.0f).message == "2 edges given sharpness 1");
  CHECK(edits.set_sharp({{"k_f", "k_g"}, {"k_g", "k_h"}}, 2.5f).message == "2 edges given sharpness 2.5");
  const SceneDocument text = SceneDocument::from_scene(scene::Scene::from_text(weighted, "t.nome"));
  CHECK(sharp_subdivided(doc, 3) == sharp_subdivided(text, 3));
  const std::string saved = doc.saved_text();
  CHECK_THAT(saved, Catch::Contains("sharpedges\n    2.5 (k_f k_g)\n    2.5 (k_g k_h)\nendsharpedges\n"));
  const SceneDocument back = SceneDocument::from_scene(scene::Scene::from_text(saved, "saved.nome"));
  CHECK(back.edits().sharp_edges() == edits.sharp_edges());
  CHECK(sharp_subdivided(back, 3) == sharp_subdivided(text, 3));

  CHECK(edits.undo());
  CHECK(edits.sharp_edges() == std::vector<NamedSharpEdge>{{"k_f", "k_g", 1.0f}, {"k_g", "k_h", 1.0f}});
  CHECK(sharp_subdivided(doc, 3) != sharp_subdivided(text, 3));
  CHECK(edits.undo());
  CHECK(edits.sharp_edges().empty());
  CHECK(edits.redo());
  CHECK(edits.redo());
  CHECK(sharp_subdivided(doc, 3) == sharp_subdivided(text, 3));
  // An edge the text makes sharp keeps the text's weight.
  CHECK(SceneDocument::from_scene(scene::Scene::from_text(weighted, "t.nome"))
            .edits()
            .set_sharp({{"k_f", "k_g"}}, 1.0f)
            .message == "(k_f, k_g) is sharp in the scene's text: change its `sharp` there");
  CHECK(test::scene_errors(plain + "sharpedges -2 (k_a k_b) endsharpedges\n") ==
        std::vector<std::string>{"t.nome:8:12: a sharpness is 0 or more, found -2"});
}
