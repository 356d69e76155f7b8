// A per-face attribute that no part of the kernel knows (a material number), added here alone: it reaches
// the subdivided offset's exports and the lookup from a shown face to its statement, carried by the
// operations' provenance.
#include <catch2/catch.hpp>

#include <cstdint>
#include <map>

#include <glm/geometric.hpp>

#include "nome/io/ply.hpp"
#include "nome/io/three_mf.hpp"
#include "nome/mesh/input_faces.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/scene/scene.hpp"
#include "nome/scene/source_place.hpp"
#include "support/mesh_measures.hpp"
#include "support/scratch_files.hpp"

using namespace nome;

namespace {

// Two open funnels apart (the offset gives them rims) and a closed cube.
const char* const scene_text = R"(funnel fun (6 1 0.5 1) endfunnel
instance a fun endinstance
instance b fun translate (5 0 0) endinstance
mesh box
  point p0 (0 0 0) endpoint  point p1 (1 0 0) endpoint  point p2 (1 1 0) endpoint  point p3 (0 1 0) endpoint
  point p4 (0 0 1) endpoint  point p5 (1 0 1) endpoint  point p6 (1 1 1) endpoint  point p7 (0 1 1) endpoint
  face q0 (p0 p3 p2 p1) endface  face q1 (p4 p5 p6 p7) endface  face q2 (p0 p1 p5 p4) endface
  face q3 (p1 p2 p6 p5) endface  face q4 (p2 p3 p7 p6) endface  face q5 (p3 p0 p4 p7) endface
endmesh
instance c box translate (10 0 0) endinstance
)";

constexpr const char* material = "material";
constexpr const char* origin = "origin";

// Each scene face's material: 100 per instance, plus the face's number in it; and its own number as the
// int "origin" a file can hold, to check every exported face against.
std::vector<std::int32_t> give_materials(PolygonSoup& soup) {
  std::vector<std::int32_t> materials;
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const std::string& name = soup.face_names[f];
    const std::int32_t instance = name[0] == 'a' ? 1 : name[0] == 'b' ? 2 : 3;
    materials.push_back(100 * instance + std::int32_t(f % 7));
    soup.face_attributes.add<std::int32_t>(material, -1).set(f, materials.back());
    soup.face_attributes.add<std::int32_t>(origin, -1).set(f, std::int32_t(f));
  }
  return materials;
}

PipelineSettings smoothed_solid() {
  return {.subdivision_levels = 1, .offset_distance = 0.05, .subdivision_after = 1};
}

// The scene face whose centre is nearest: by the funnels' and the cube's symmetry, the planes halfway between
// two neighbouring faces' centres hold the edge between them, so every face made from a scene face (its
// children, its offset copies, the rims on its border) lies nearest to that face's centre.
Index nearest_face(const PolygonSoup& scene, const Vec3& p) {
  Index best = 0;
  for (Index f = 1; f < scene.num_faces(); ++f)
    if (glm::distance(test::face_centre(scene, f), p) < glm::distance(test::face_centre(scene, best), p))
      best = f;
  return best;
}

// Every face of a file read back: its material is that of the scene face it names as its origin, which is
// where it lies; every scene face has descendants.
void check_read_back(const PolygonSoup& back, const PolygonSoup& scene,
                     const std::vector<std::int32_t>& materials) {
  const auto* read_material = back.face_attributes.find<std::int32_t>(material);
  const auto* read_origin = back.face_attributes.find<std::int32_t>(origin);
  REQUIRE(read_material);
  REQUIRE(read_origin);
  std::map<std::int32_t, int> descendants;
  for (Index f = 0; f < back.num_faces(); ++f) {
    const std::int32_t from = (*read_origin)[f];
    REQUIRE(from >= 0);
    REQUIRE(std::size_t(from) < materials.size());
    CHECK((*read_material)[f] == materials[std::size_t(from)]);
    CHECK(nearest_face(scene, test::face_centre(back, f)) == Index(from));
    ++descendants[from];
  }
  CHECK(descendants.size() == materials.size());
}

}  // namespace

TEST_CASE("a face attribute of the test's own reaches the subdivided offset's PLY and 3MF exports", "[io]") {
  PolygonSoup soup = scene::Scene::from_text(scene_text, "materials.nome").combined_soup();
  const std::vector<std::int32_t> materials = give_materials(soup);
  Pipeline pipeline;
  pipeline.set_input({soup, {}, Joining::manifold});
  const Mesh& solid = pipeline.run(smoothed_solid());
  // Children of quads make 4 quads, children of an n-gon n: the funnels' faces are quads, the solid's too.
  REQUIRE(solid.num_faces() > 4 * 2 * soup.num_faces());
  const auto* carried_material = solid.face_attributes().find<std::int32_t>(material);
  REQUIRE(carried_material);

  const auto ply = test::scratch_path("face_attribute_export", "solid.ply");
  write_ply(ply, solid);
  const PolygonSoup from_ply = read_ply(ply);
  REQUIRE(from_ply.num_faces() == solid.num_faces());
  check_read_back(from_ply, soup, materials);

  const auto three_mf = test::scratch_path("face_attribute_export", "solid.3mf");
  write_3mf(three_mf, solid);
  const PolygonSoup from_3mf = three_mf_polygons(read_3mf(three_mf));
  REQUIRE(from_3mf.num_faces() == 2 * solid.num_faces());  // two triangles a quad
  check_read_back(from_3mf, soup, materials);

  SECTION("a slider tick (positions only) keeps them, and a changed material reaches the solid") {
    PolygonSoup moved = soup;
    for (Vec3& p : moved.positions) p.z *= 1.1;
    moved.face_attributes.add<std::int32_t>(material, -1).set(0, 77);
    pipeline.set_input({moved, {}, Joining::manifold});
    const Mesh& again = pipeline.run(smoothed_solid());
    CHECK(pipeline.work(Stage::subdivided_offset) == StageWork::positions);
    const auto* now = again.face_attributes().find<std::int32_t>(material);
    const auto* from = again.face_attributes().find<std::int32_t>(origin);
    REQUIRE(now);
    REQUIRE(from);
    for (Index f = 0; f < again.num_faces(); ++f)
      CHECK((*now)[f] == ((*from)[f] == 0 ? 77 : materials[std::size_t((*from)[f])]));
  }
}

TEST_CASE("a face of the smoothed solid finds the statement of the scene face it came from", "[scene]") {
  PolygonSoup soup = scene::Scene::from_text(scene_text, "materials.nome").combined_soup();
  const std::vector<std::int32_t> materials = give_materials(soup);
  mark_input_faces(soup);
  Pipeline pipeline;
  pipeline.set_input({soup, {}, Joining::manifold});
  for (Stage stage : {Stage::scene, Stage::subdivided, Stage::offset, Stage::subdivided_offset}) {
    PipelineSettings s = smoothed_solid();
    s.stage = stage;
    const Mesh& shown = pipeline.run(s);
    const auto* shown_material = shown.face_attributes().find<std::int32_t>(material);
    REQUIRE(shown_material);
    for (Index f = 0; f < shown.num_faces(); ++f) {
      const std::optional<Index> input = input_face(shown, f);
      REQUIRE(input);
      CHECK((*shown_material)[f] == materials[*input]);
      const std::optional<scene::SourcePlace> place = scene::shown_face_statement(shown, soup, f);
      REQUIRE(place);
      CHECK(place == scene::face_statement(soup, *input));
    }
  }
  // The cube's faces come from its face statements, lines 7 to 8; a funnel's from its generator, line 1.
  const Mesh& solid = pipeline.run(smoothed_solid());
  std::map<int, int> lines;
  for (Index f = 0; f < solid.num_faces(); ++f)
    ++lines[scene::shown_face_statement(solid, soup, f)->location.line];
  CHECK(lines.count(1));
  CHECK(lines.count(7));
  CHECK(lines.count(8));
  CHECK(lines.size() == 3);
}
