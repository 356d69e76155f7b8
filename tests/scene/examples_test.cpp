#include <catch2/catch.hpp>
#include "nome/mesh/mesh.hpp"
#include "nome/mesh/topology_report.hpp"
#include "scene/scene_support.hpp"
#include "support/shared_examples.hpp"

using namespace nome;

TEST_CASE("every scene of the original programs loads and builds a manifold", "[scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  struct Row {
    const char* file;
    size_t instances;
    Index faces;
  };
  const Row rows[] = {
      {"cube.nom", 1, 6},
      {"cube_mesh.nom", 1, 6},
      {"rimline.nom", 1, 0},
      {"zero.nom", 2, 0},
      {"kleinbottle.nom", 1, 80},
      {"hild.nom", 1, 104},
      {"funnelcube_savework.nom", 9, 48 + 8 * 4},
      {"kleinbottle_savework.nom", 2, 80 + 40},
      {"tunnelConsolidated_nome2.nom", 2, 32 + 8},
  };
  for (const Row& row : rows) {
    INFO(row.file);
    const scene::Scene s = test::load_scene_file(test::originals_dir() + row.file);
    CHECK(s.instances().size() == row.instances);
    const Mesh m = build_mesh(s.combined_soup());
    CHECK(m.num_faces() == row.faces);
  }
}

TEST_CASE("every .nome and .nom file in the repository loads", "[scene]") {
  const std::vector<std::string> files = test::scene_files();
  for (const std::string& file : files) {
    INFO(file);
    CHECK_NOTHROW(build_mesh(test::load_scene_file(file).combined_soup()));
  }
  CHECK(files.size() >= 7);
  NOME_NEEDS_SHARED_EXAMPLES("original");
  CHECK(files.size() >= 12);
}

TEST_CASE("the assets' scenes have the topology they are made for", "[scene]") {
  auto report = [](const std::string& file) {
    return topology_report(build_mesh(test::load_scene_file(test::assets_dir() + file).combined_soup()));
  };
  const TopologyReport mobius = report("mobius_band.nome");
  CHECK(mobius.components.size() == 1);
  CHECK(mobius.chi == 0);
  CHECK(mobius.borders == 1);
  CHECK_FALSE(mobius.orientable);
  CHECK(mobius.faces == 48);

  const TopologyReport klein = report("klein_bottle_figure8.nome");
  CHECK(klein.components.size() == 1);
  CHECK(klein.chi == 0);
  CHECK(klein.borders == 0);
  CHECK_FALSE(klein.orientable);
  CHECK(klein.mobius_edges > 0);

  const TopologyReport tunnels = report("klein_bottle.nome");
  CHECK(tunnels.components.size() == 5);
  for (const ComponentTopology& c : tunnels.components) CHECK((c.chi == 0 && c.borders == 2 && c.orientable));

  const TopologyReport corners = report("funnel_cube_consolidated.nome");
  CHECK(corners.components.size() == 6 + 8);
  CHECK(corners.faces == 48 + 8 * 4);
}

TEST_CASE("the Klein bottle's slider moves every point and keeps the topology", "[scene]") {
  scene::Scene s = test::load_scene_file(test::assets_dir() + "klein_bottle_figure8.nome");
  const Vec3 before = test::vertex_position(s, "kb_p0_0");
  s.set_parameter(*s.find_parameter("kb_r"), 3);
  CHECK(test::vertex_position(s, "kb_p0_0").x == Approx(before.x + 1));
  CHECK(s.instances()[0].topology_version == 1);
  CHECK(s.instances()[0].geometry_version == 2);
}
