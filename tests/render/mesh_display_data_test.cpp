#include <catch2/catch.hpp>

#include <set>

#include <glm/geometric.hpp>

#include "nome/error.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "nome/query/display_triangles.hpp"
#include "render/mesh_display_data.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

// What GL vertex u of `t` repeats: a mesh vertex, with corner_sign_bit where its normal turns round.
std::uint32_t key(const render::DisplayTopology& t, std::uint32_t u) {
  return u < t.num_vertices ? u : t.extra_vertices[u - t.num_vertices];
}

std::uint32_t corner_key(const Mesh& mesh, Index c) {
  return mesh.corner_vertex(c) | (mesh.corner_sign(c) < 0 ? render::corner_sign_bit : 0u);
}

}  // namespace

TEST_CASE("display data: real edges, Möbius and border edges, triangles over shared vertices", "[render]") {
  const Mesh band = build_mesh(test::mobius_band(24, 3));
  const render::MeshDisplayData data = render::build_display_data(band);
  Index mobius = 0, border = 0;
  for (const Edge& e : band.edges()) mobius += e.is_mobius, border += e.is_boundary();
  REQUIRE(mobius > 0);
  const render::DisplayTopology& t = *data.topology;
  CHECK(t.all_edges.count == band.num_edges());  // quads: no diagonal among the wire segments
  CHECK(t.mobius_edges.count == mobius);
  CHECK(t.border_edges.count == border);
  CHECK(t.segments.size() == 2 * std::size_t(band.num_edges() + mobius + border));
  CHECK(data.positions->vertices.size() == band.num_vertices());
  CHECK(data.positions->face_normals.size() == band.num_faces());
  std::set<std::pair<std::uint32_t, std::uint32_t>> mobius_pairs;
  for (const Edge& e : band.edges())
    if (e.is_mobius) mobius_pairs.insert({e.vertices[0], e.vertices[1]});
  for (std::uint32_t s = t.mobius_edges.first; s < t.mobius_edges.first + t.mobius_edges.count; ++s)
    CHECK(mobius_pairs.count({t.segments[2 * s], t.segments[2 * s + 1]}) == 1);
  // Each triangle is the picking triangle's corners, turned so that its last vertex carries its face;
  // each vertex carries the corner's sign: a Möbius band has vertices of both signs.
  const DisplayTriangles triangles = display_triangles(band);
  REQUIRE(t.triangles.size() == 3 * std::size_t(triangles.size()));
  REQUIRE(t.vertex_faces.size() == t.num_gl_vertices());
  for (Index k = 0; k < triangles.size(); ++k) {
    const std::uint32_t* gl = &t.triangles[3 * std::size_t(k)];
    CHECK(t.vertex_faces[gl[2]] == triangles.faces[k]);
    int matching_turns = 0;
    for (int turn = 0; turn < 3; ++turn) {
      bool same = true;
      for (int i = 0; i < 3; ++i)
        same = same && key(t, gl[(i + turn) % 3]) == corner_key(band, triangles.corners[k][i]);
      matching_turns += same;
    }
    CHECK(matching_turns >= 1);
  }
  int negative = 0;
  for (std::uint32_t e : t.extra_vertices) negative += (e & render::corner_sign_bit) != 0;
  CHECK(negative > 0);
  // Shared: no more GL vertices than one per vertex and sign and one per face.
  CHECK(t.num_gl_vertices() < std::uint32_t(band.num_corners()));
}

TEST_CASE("smooth normals follow each face's own orientation across Möbius edges", "[render]") {
  // Averaging normals without the corner signs would cancel or flip them next to a Möbius edge;
  // with the signs, each triangle vertex's smooth normal leans the same way as its face's normal.
  for (const PolygonSoup& soup : {test::mobius_band(32, 4), test::klein_bottle(24, 12), test::torus(16, 8)}) {
    const Mesh mesh = build_mesh(soup);
    const render::MeshDisplayData data = render::build_display_data(mesh);
    const render::DisplayTopology& t = *data.topology;
    const DisplayTriangles triangles = display_triangles(mesh);
    // The shader's smooth normal: the GL vertex's, an extra vertex's turned round where it has the sign
    // bit; its position the mesh vertex's.
    const render::DisplayPositions& p = *data.positions;
    REQUIRE(p.extra_normals.size() == t.extra_vertices.size());
    REQUIRE(p.extra_vertices.size() == t.extra_vertices.size());
    for (Index k = 0; k < triangles.size(); ++k)
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t g = t.triangles[3 * std::size_t(k) + i];
        const bool is_extra = g >= t.num_vertices;
        const glm::vec3 smooth =
            unpack_normal(is_extra ? p.extra_normals[g - t.num_vertices] : p.vertex_normals[g]);
        const glm::vec3 position = is_extra ? p.extra_vertices[g - t.num_vertices] : p.vertices[g];
        REQUIRE(position == glm::vec3(mesh.position(key(t, g) & ~render::corner_sign_bit)));
        REQUIRE(glm::length(smooth) == Approx(1.0f).margin(3e-3));
        REQUIRE(glm::dot(smooth, unpack_normal(p.face_normals[triangles.faces[k]])) > 0.5f);
      }
  }
}

TEST_CASE("face colours become an RGBA table, none where the mesh has none", "[render]") {
  PolygonSoup soup = test::cube();
  CHECK(render::build_display_data(build_mesh(soup)).face_colors.empty());
  add_colors(soup.face_attributes).values().assign(soup.num_faces(), Color(1.0f, 0.5f, 0.0f));
  const auto colors = render::build_display_data(build_mesh(soup)).face_colors;
  REQUIRE(colors.size() == 6);
  CHECK(colors[5] == std::array<std::uint8_t, 4>{255, 128, 0, 255});
}

TEST_CASE("display positions take normals given with the mesh as they are", "[render]") {
  // A Möbius band: extra vertices whose normals are the given ones, turned round where so marked; over
  // 65,536 vertices, so that two threads round half the positions each.
  const Mesh band = build_mesh(test::mobius_band(1024, 64));
  REQUIRE(band.num_vertices() > (1u << 16));
  const render::MeshDisplayData computed = render::build_display_data(band);
  const render::DisplayTopology& t = *computed.topology;
  for (const int threads : {1, 2}) {
    render::DisplayPositions given;
    given.face_normals = computed.positions->face_normals;
    given.vertex_normals = computed.positions->vertex_normals;
    // Not what the mesh gives: taken all the same.
    for (PackedNormal& n : given.vertex_normals) n = negated(n);
    render::build_display_positions(band, t, given, threads, render::DisplayNormals::given);
    CHECK(given.vertices == computed.positions->vertices);
    CHECK(given.extra_vertices == computed.positions->extra_vertices);
    CHECK(given.bounds.min == computed.positions->bounds.min);
    CHECK(given.bounds.max == computed.positions->bounds.max);
    REQUIRE(given.extra_normals.size() == t.extra_vertices.size());
    for (std::size_t i = 0; i < t.extra_vertices.size(); ++i)
      CHECK(given.extra_normals[i] == negated(computed.positions->extra_normals[i]));
  }
  render::DisplayPositions missing;
  CHECK_THROWS_AS(render::build_display_positions(band, t, missing, 1, render::DisplayNormals::given),
                  InvalidInputError);
}

TEST_CASE("the display topology made on two threads is the one made on one", "[render]") {
  // Enough faces for two parts, with Möbius and border edges.
  const Mesh mesh = build_mesh(test::disjoint_union(test::grid(300, 250), test::mobius_band(24, 3)));
  const render::DisplayTopology one = render::build_display_topology(mesh, 1);
  const render::DisplayTopology two = render::build_display_topology(mesh, 2);
  CHECK(two.triangles == one.triangles);
  CHECK(two.vertex_faces == one.vertex_faces);
  CHECK(two.extra_vertices == one.extra_vertices);
  CHECK(two.segments == one.segments);
  CHECK(two.mobius_edges.first == one.mobius_edges.first);
  CHECK(two.mobius_edges.count == 3);  // the band's seam
  CHECK(two.border_edges.count == one.border_edges.count);
}
