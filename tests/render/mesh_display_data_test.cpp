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
  const render::DisplayTopology& t = *data.topology;
  CHECK(t.all_edges.count == band.num_edges());  // quads: no diagonal among the wire segments
  CHECK(t.mobius_edges.count == mobius);
  CHECK(t.border_edges.count == border);
  CHECK(t.segments.size() == 2 * std::size_t(band.num_edges() + mobius + border));
  CHECK(t.triangles.size() == 3 * std::size_t(triangles));
  REQUIRE(t.corner_vertices.size() == band.num_corners());
  CHECK(data.positions->vertices.size() == band.num_vertices());
  CHECK(data.positions->face_normals.size() == band.num_faces());
  std::set<std::pair<std::uint32_t, std::uint32_t>> mobius_pairs;
  for (const Edge& e : band.edges())
    if (e.is_mobius) mobius_pairs.insert({e.vertices[0], e.vertices[1]});
  for (std::uint32_t s = t.mobius_edges.first; s < t.mobius_edges.first + t.mobius_edges.count; ++s)
    CHECK(mobius_pairs.count({t.segments[2 * s], t.segments[2 * s + 1]}) == 1);
  // Each corner names its vertex and carries its sign: a Möbius band has corners of both signs.
  int negative = 0;
  for (Index c = 0; c < band.num_corners(); ++c) {
    CHECK((t.corner_vertices[c] & ~render::corner_sign_bit) == band.corner_vertex(c));
    negative += (t.corner_vertices[c] & render::corner_sign_bit) != 0;
    CHECK(((t.corner_vertices[c] & render::corner_sign_bit) != 0) == (band.corner_sign(c) < 0));
  }
  CHECK(negative > 0);
}

TEST_CASE("smooth normals follow each face's own orientation across Möbius edges", "[render]") {
  // Averaging normals without the corner signs would cancel or flip them next to a Möbius edge;
  // with the signs, each corner's smooth normal leans the same way as its face's normal.
  for (const PolygonSoup& soup : {test::mobius_band(32, 4), test::klein_bottle(24, 12), test::torus(16, 8)}) {
    const Mesh mesh = build_mesh(soup);
    const render::MeshDisplayData data = render::build_display_data(mesh);
    // The shader's smooth normal: the corner's sign times its vertex normal.
    for (Index c = 0; c < mesh.num_corners(); ++c) {
      const std::uint32_t corner = data.topology->corner_vertices[c];
      const float sign = (corner & render::corner_sign_bit) ? -1.0f : 1.0f;
      const glm::vec3 smooth = sign * data.positions->vertex_normals[corner & ~render::corner_sign_bit];
      REQUIRE(glm::length(smooth) == Approx(1.0f));
      REQUIRE(glm::dot(smooth, data.positions->face_normals[data.topology->corner_faces[c]]) > 0.5f);
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
