#include "scene/fresh_scene_oracle.hpp"
#include "support/face_colors.hpp"

#include <catch2/catch.hpp>

namespace nome::test {
namespace {

void check_same_soup(const PolygonSoup& got, const PolygonSoup& fresh) {
  CHECK(got.positions == fresh.positions);
  CHECK(got.face_offsets == fresh.face_offsets);
  CHECK(got.face_vertices == fresh.face_vertices);
  CHECK(got.vertex_names.list() == fresh.vertex_names.list());
  CHECK(got.face_names.list() == fresh.face_names.list());
  CHECK(test::face_colors(got) == test::face_colors(fresh));
}

}  // namespace

void check_same_as_fresh(const SceneDocument& moved, const std::string& fresh_text) {
  const SceneDocument fresh = SceneDocument::from_scene(scene::Scene::from_text(fresh_text, "t.nome"));
  {
    INFO("the scene's combined soup");
    check_same_soup(moved.scene()->combined_soup(), fresh.scene()->combined_soup());
  }
  {
    INFO("the document's pipeline input");
    check_same_soup(moved.pipeline_input().soup, fresh.pipeline_input().soup);
  }
}

}  // namespace nome::test
