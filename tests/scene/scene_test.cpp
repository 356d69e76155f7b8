#include <catch2/catch.hpp>

#include <cmath>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/scene/save_nome.hpp"
#include "nome/scene/scene.hpp"
#include "scene/scene_support.hpp"
#include "support/face_colors.hpp"
#include "support/shared_examples.hpp"

using namespace nome;
using nome::scene::Scene;
using nome::test::assets_dir;
using nome::test::vertex_position;

namespace {

TopologyReport report_of(const Scene& s) {
  return topology_report(build_mesh(s.combined_soup()));
}

}  // namespace

TEST_CASE("funnel_cube.nome: six annuli of eight quads", "[scene]") {
  const Scene s = nome::test::load_scene_file(assets_dir() + "funnel_cube.nome");
  REQUIRE(s.instances().size() == 1);
  CHECK(s.instances()[0].name == "cf");
  const TopologyReport r = report_of(s);
  CHECK(r.faces == 48);
  REQUIRE(r.components.size() == 6);
  for (const ComponentTopology& c : r.components) {
    CHECK(c.faces == 8);
    CHECK(c.chi == 0);
    CHECK(c.borders == 2);
    CHECK(c.orientable);
  }
  const PolygonSoup soup = s.combined_soup();
  for (Index f = 0; f < soup.num_faces(); ++f) CHECK(soup.face_offsets[f + 1] - soup.face_offsets[f] == 4);
  // Order written: translate then rotate; fun2 is turned upside down so its base lies at z = +0.8.
  CHECK(vertex_position(s, "cf_fun1_bc0").z == Approx(-0.8));
  CHECK(vertex_position(s, "cf_fun2_bc0").z == Approx(0.8));
  CHECK(vertex_position(s, "cf_fun3_bc0").y == Approx(0.8));
}

TEST_CASE("funnel_cube_consolidated.nome closes each corner with small non-degenerate faces", "[scene]") {
  const Scene s = nome::test::load_scene_file(assets_dir() + "funnel_cube_consolidated.nome");
  REQUIRE(s.instances().size() == 9);
  for (size_t i = 1; i < 9; ++i) {
    const auto& soup = s.instances()[i].geometry.soup;
    CHECK(s.instances()[i].name == "tp" + std::to_string(i - 1));
    REQUIRE(soup.num_faces() == 4);
    int triangles = 0;
    for (Index f = 0; f < 4; ++f) {
      const Index n = soup.face_offsets[f + 1] - soup.face_offsets[f];
      triangles += n == 3;
      Vec3 area(0);
      for (Index k = 0; k < n; ++k) {
        const Vec3 a = soup.positions[soup.face_vertices[soup.face_offsets[f] + k]];
        const Vec3 b = soup.positions[soup.face_vertices[soup.face_offsets[f] + (k + 1) % n]];
        const double edge = glm::length(b - a);
        CHECK(edge > 0.05);  // no two corners coincide
        CHECK(edge < 0.6);   // small next to the cube's side of 2
        area += glm::cross(a, b);
      }
      CHECK(glm::length(area) / 2 > 0.01);
    }
    CHECK(triangles == 1);
    // Every corner lies near one cube corner (|x|, |y|, |z| all well away from 0 for the triangle).
  }
  // The referenced vertices are the funnels' inner circles: tp0's first corner is cf_fun3_hc3.
  CHECK(s.instances()[1].geometry.soup.vertex_names[0] == "tp0_cf_fun3_hc3");
  const Vec3 p = vertex_position(s, "tp0_cf_fun3_hc3");
  CHECK(glm::length(p - vertex_position(s, "cf_fun3_hc3")) < 1e-12);
  CHECK(p.x == Approx(-0.5 * std::sqrt(0.5)));
  CHECK(p.y == Approx(0.7));
}

TEST_CASE("klein_bottle.nome: five tunnels with hierarchical names", "[scene]") {
  const Scene s = nome::test::load_scene_file(assets_dir() + "klein_bottle.nome");
  const TopologyReport r = report_of(s);
  CHECK(r.components.size() == 5);
  CHECK(r.faces == 80);
  // t3: rotate about y by 90 degrees, then translate (x 0 z).
  const Vec3 hc0 = vertex_position(s, "kb_t3_hc0");
  CHECK(hc0.x == Approx(-2 + 0.2));
  CHECK(hc0.z == Approx(8 - 2));
  CHECK(s.banks().size() == 5);
  CHECK(s.parameters().size() == 22);
}

TEST_CASE("a slider re-evaluates only the placements that read it", "[scene]") {
  Scene s = nome::test::load_scene_file(assets_dir() + "klein_bottle.nome");
  const size_t at_load = s.placement_evaluations();
  CHECK(at_load == 5);
  const auto before = s.instances()[0].geometry.soup.positions;
  const auto changed = s.set_parameter(*s.find_parameter("tp3_x"), -1);
  CHECK(s.placement_evaluations() - at_load == 1);
  CHECK(changed == std::vector<scene::InstanceId>{scene::InstanceId(0)});
  CHECK(vertex_position(s, "kb_t3_hc0").x == Approx(-1 + 0.2));
  CHECK(s.instances()[0].geometry.soup.positions[0] == before[0]);  // t1 untouched
  const auto topology = s.instances()[0].topology_version;
  s.set_parameter(*s.find_parameter("tp1_n"), 6);
  CHECK(s.placement_evaluations() - at_load == 2);
  CHECK(s.instances()[0].topology_version == topology + 1);
  CHECK(s.instances()[0].geometry.soup.num_faces() == 76);

  Scene cube = nome::test::load_scene_file(assets_dir() + "funnel_cube_consolidated.nome");
  const size_t n0 = cube.placement_evaluations();
  CHECK(n0 == 6 + 8);
  cube.set_parameter(*cube.find_parameter("fp_z"), -1.2);  // moves every funnel and every corner patch
  // The funnels are made again; the corner patches copy their moved vertices without evaluating.
  CHECK(cube.placement_evaluations() - n0 == 6);
  CHECK(cube.last_change_moved_vertices_only());
  CHECK(vertex_position(cube, "tp0_cf_fun3_hc3").y == Approx(0.9));
}

TEST_CASE("a failing slider value is refused and the scene keeps the previous one", "[scene]") {
  Scene s = Scene::from_text(
      "bank b set k 1 0 2 0.5 endbank\n"
      "point p ({expr 1 / $b_k} 0 0) endpoint point q (0 1 0) endpoint point r (0 0 1) endpoint\n"
      "face f (p q r) endface instance i f endinstance\n",
      "t.nome");
  CHECK_THROWS_WITH(s.set_parameter(scene::ParameterId(0), 0),
                    Catch::Contains("t.nome:2:18: division by zero"));
  CHECK(s.parameters().front().value == 1);
  CHECK(vertex_position(s, "i_p").x == 1);
  CHECK_THROWS_WITH(s.set_parameter(scene::ParameterId(0), 3),
                    Catch::Contains("outside its slider range [0, 2]"));
}

TEST_CASE("mirror reflects in a plane and reverses the winding", "[scene]") {
  const Scene s = Scene::from_text(
      "point a (1 0 0) endpoint point b (2 0 0) endpoint point c (1 1 0) endpoint\n"
      "mesh m face f (a b c) endface endmesh\n"
      "instance plain m endinstance\n"
      "instance mirrored m mirror (1 0 0 -3) endinstance\n",
      "t.nome");
  const auto& plain = s.instances()[0].geometry.soup;
  const auto& mirrored = s.instances()[1].geometry.soup;
  CHECK(vertex_position(s, "mirrored_a").x == Approx(5));
  CHECK(vertex_position(s, "mirrored_b").x == Approx(4));
  auto normal = [](const PolygonSoup& p) {
    const Vec3 a = p.positions[p.face_vertices[0]], b = p.positions[p.face_vertices[1]],
               c = p.positions[p.face_vertices[2]];
    return glm::cross(b - a, c - a);
  };
  // A reflection in x = 3 keeps the z-normal of a face in z = 0 only if the winding is reversed.
  CHECK(normal(plain).z > 0);
  CHECK(normal(mirrored).z > 0);
}

TEST_CASE("a face names a vertex by a unique suffix, ambiguity lists the candidates", "[scene]") {
  const std::string base =
      "funnel fun (4 1 0 1) endfunnel\n"
      "group g instance f1 fun endinstance instance f2 fun translate (5 0 0) endinstance endgroup\n"
      "instance top g endinstance\n";
  const Scene ok = Scene::from_text(base +
                                        "mesh m face x (f1_hc0 f2_hc1 top_f2_bc0) endface endmesh\n"
                                        "instance mi m endinstance\n",
                                    "t.nome");
  CHECK(ok.instances()[1].geometry.soup.vertex_names[1] == "mi_top_f2_hc1");
  CHECK(ok.resolve_vertex_name("f2.hc1") == "top_f2_hc1");
  const auto errors = nome::test::scene_errors(base +
                                               "mesh m face x (hc0 f2_hc1 f2_bc0) endface endmesh\n"
                                               "instance mi m endinstance\n");
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] == "t.nome:4:16: ambiguous vertex name 'hc0': 2 candidates: top_f1_hc0, top_f2_hc0");
  const auto unknown = nome::test::scene_errors(base +
                                                "mesh m face x (f1_hc9 f2_hc1 f2_bc0) endface endmesh\n"
                                                "instance mi m endinstance\n");
  REQUIRE(unknown.size() == 1);
  CHECK_THAT(unknown[0], Catch::StartsWith("t.nome:4:16: unknown vertex 'f1_hc9' (did you mean top_f1_hc"));
}

TEST_CASE("surfaces colour faces: a face's own surface wins over its instance's", "[scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  const Scene s = nome::test::load_scene_file(nome::test::originals_dir() + "cube.nom");
  const auto& soup = s.instances()[0].geometry.soup;
  REQUIRE(test::face_colors(soup).size() == 6);
  CHECK(test::face_colors(soup)[0] == Color(0, 0.9f, 0));  // c1: surface G
  CHECK(test::face_colors(soup)[1] == Color(0, 0.5f, 1));  // c2: surface U
  CHECK(test::face_colors(soup)[2] == Color(0, 0, 1));     // c3: the instance's surface B
  CHECK(soup.face_names[0] == "cube1_c1");
}

TEST_CASE("sharp weighs edges and single vertices with OpenSubdiv's sharpness", "[scene]") {
  const Scene s = Scene::from_text(
      "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (1 1 0) endpoint point d (0 1 0) endpoint\n"
      "point e (2 0 0) endpoint point f (2 1 0) endpoint\n"
      "mesh m face q1 (a b c d) endface face q2 (b e f c) endface\n"
      "  sharp 1.5 (b c) endsharp sharp 0.5 (a) endsharp sharp (f) endsharp endmesh\n"
      "instance i m endinstance\n",
      "t.nome");
  CHECK(s.warnings().empty());
  const Mesh m = build_mesh(s.combined_soup());
  Index shared = no_index;
  for (Index e = 0; e < m.num_edges(); ++e)
    if (!m.edge(e).is_boundary()) shared = e;
  REQUIRE(shared != no_index);
  CHECK(m.edge_sharpness(shared) == 1.5f);
  CHECK(m.vertex_sharpness(0) == 0.5f);
  CHECK(m.vertex_sharpness(5) == infinite_sharpness);
  CHECK_THAT(to_nome_text(s), Catch::Contains("sharp 0.5 (a) endsharp"));
}

TEST_CASE("sharp marks a chain of edges, delete removes faces by name", "[scene]") {
  const Scene s = Scene::from_text(
      "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (1 1 0) endpoint point d (0 1 0) endpoint\n"
      "point e (2 0 0) endpoint point f (2 1 0) endpoint\n"
      "mesh m face q1 (a b c d) endface face q2 (b e f c) endface sharp (a b e) endsharp endmesh\n"
      "instance i m endinstance\n"
      "delete face q2 endface enddelete\n",
      "t.nome");
  const auto& soup = s.instances()[0].geometry.soup;
  CHECK(soup.num_faces() == 1);
  CHECK(soup.num_vertices() == 4);      // e and f, used only by the deleted face, are gone
  CHECK(soup.sharp_edges.size() == 1);  // with the sharp edge b-e
  CHECK(s.edits().deleted == std::vector<std::string>{"i_q2"});
}
