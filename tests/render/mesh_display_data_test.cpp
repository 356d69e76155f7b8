#include <catch2/catch.hpp>

#include <set>

#include <glm/geometric.hpp>

#include "render/mesh_display_data.hpp"
#include "support/shapes.hpp"

using namespace nome;

TEST_CASE("display data: real edges, Möbius and border edges, one vertex per corner", "[render]") {
  const Mesh band = build_mesh(test::mobius_band(24, 3));
  const render::MeshDisplayData data = render::build_display_data(band);
  Index mobius = 0, border = 0, triangles = 0;
  for (const Edge& e : band.edges()) mobius += e.is_mobius, border += e.is_boundary();
  for (Index f = 0; f < band.num_faces(); ++f) triangles += band.face_degree(f) - 2;
  REQUIRE(mobius > 0);
  CHECK(data.all_edges.count == band.num_edges());  // quads: no diagonal among the wire segments
  CHECK(data.mobius_edges.count == mobius);
  CHECK(data.border_edges.count == border);
  CHECK(data.segments.size() == 2 * std::size_t(band.num_edges() + mobius + border));
  CHECK(data.triangles.size() == 3 * std::size_t(triangles));
  CHECK(data.corner_positions.size() == band.num_corners());
  std::set<std::pair<std::uint32_t, std::uint32_t>> mobius_pairs;
  for (const Edge& e : band.edges())
    if (e.is_mobius) mobius_pairs.insert({e.vertices[0], e.vertices[1]});
  for (std::uint32_t s = data.mobius_edges.first; s < data.mobius_edges.first + data.mobius_edges.count; ++s)
    CHECK(mobius_pairs.count({data.segments[2 * s], data.segments[2 * s + 1]}) == 1);
}

TEST_CASE("smooth normals follow each face's own orientation across Möbius edges", "[render]") {
  // Averaging normals without the corner signs would cancel or flip them next to a Möbius edge;
  // with the signs, each corner's smooth normal leans the same way as its face's normal.
  for (const PolygonSoup& soup : {test::mobius_band(32, 4), test::klein_bottle(24, 12), test::torus(16, 8)}) {
    const Mesh mesh = build_mesh(soup);
    const render::MeshDisplayData data = render::build_display_data(mesh);
    for (Index c = 0; c < mesh.num_corners(); ++c) {
      REQUIRE(glm::length(data.smooth_normals[c]) == Approx(1.0f));
      REQUIRE(glm::dot(data.smooth_normals[c], data.flat_normals[c]) > 0.5f);
    }
  }
}

TEST_CASE("face colours become an RGBA table, alpha 0 where the mesh has none", "[render]") {
  PolygonSoup soup = test::cube();
  CHECK(render::build_display_data(build_mesh(soup)).face_colors[0][3] == 0);
  soup.face_colors.assign(soup.num_faces(), Color(1.0f, 0.5f, 0.0f));
  const auto colors = render::build_display_data(build_mesh(soup)).face_colors;
  REQUIRE(colors.size() == 6);
  CHECK(colors[5] == std::array<std::uint8_t, 4>{255, 128, 0, 255});
}
