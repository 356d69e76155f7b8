// The topology section's text as the sidebar draws it (imgui_text): the totals and a row per part.
#include <catch2/catch.hpp>

#include <string>

#include "app/viewer/imgui_text.hpp"
#include "nome/mesh/topology_report.hpp"
#include "support/shapes.hpp"
#include "viewer/panels/panels.hpp"

using namespace nome;

TEST_CASE("the topology section numbers each part and gives its counts", "[app]") {
  PolygonSoup soup = test::mobius_band(12, 2);
  append_soup(soup, test::grid(2, 1));
  const TopologyReport report = topology_report(build_mesh(soup));
  REQUIRE(report.components.size() == 2);
  const std::string text =
      test::imgui_text([&] { viewer::draw_topology_section(report, glm::dvec3(1, 2, 3)); });
  INFO(text);
  CHECK(text.find("V " + std::to_string(report.vertices) + "  E " + std::to_string(report.edges)) !=
        std::string::npos);
  for (std::size_t i = 0; i < 2; ++i) {
    const ComponentTopology& c = report.components[i];
    const std::string row = std::to_string(i) + " | " + std::to_string(c.vertices) + " | " +
                            std::to_string(c.edges) + " | " + std::to_string(c.faces);
    CHECK(text.find(row) != std::string::npos);
  }
}
