#include <catch2/catch.hpp>

#include "nome/mesh/mesh.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

MeshArrays arrays_of(const Mesh& m) {
  MeshArrays a;
  a.positions = m.positions();
  a.face_offsets = m.face_offsets();
  a.corner_vertices = m.corner_vertices();
  a.corner_edges = m.corner_edges();
  a.corner_signs = m.corner_signs();
  a.edges = m.edges();
  a.fan_corner_offsets = m.fan_corner_offsets();
  a.fan_corners = m.fan_corners();
  a.fan_edge_offsets = m.fan_edge_offsets();
  a.fan_edges = m.fan_edges();
  return a;
}

}  // namespace

TEST_CASE("build_mesh gives valid meshes and assemble_mesh rebuilds them from their arrays", "[kernel]") {
  for (const PolygonSoup& soup :
       {test::cube(), test::grid(3, 2), test::mobius_band(7, 2), test::klein_bottle(6, 4),
        test::projective_plane(), test::disjoint_union(test::torus(5, 3), test::cube())}) {
    const Mesh m = build_mesh(soup);
    CHECK(validate(m).empty());
    const Mesh again = assemble_mesh(arrays_of(m));
    CHECK(validate(again).empty());
    CHECK(again.num_boundary_loops() == m.num_boundary_loops());
    CHECK(again.num_components() == m.num_components());
    for (Index f = 0; f < m.num_faces(); ++f) CHECK(again.face_component(f) == m.face_component(f));
  }
}

TEST_CASE("validate names each broken invariant", "[kernel]") {
  const Mesh band = build_mesh(test::mobius_band(7, 2));
  auto broken = [&](auto&& damage) {
    MeshArrays a = arrays_of(band);
    damage(a);
    return validate(assemble_mesh(std::move(a)));
  };
  Index mobius = 0;
  while (!band.edge(mobius).is_mobius) ++mobius;
  CHECK_THAT(broken([&](MeshArrays& a) { a.edges[mobius].is_mobius = false; }).front(),
             Catch::Contains("Möbius flag"));
  CHECK_THAT(broken([](MeshArrays& a) { std::swap(a.fan_corners[0], a.fan_corners[1]); }).front(),
             Catch::Contains("vertex 0:"));
  CHECK_THAT(broken([](MeshArrays& a) { a.corner_signs[a.fan_corners[1]] *= -1; }).front(),
             Catch::Contains("sign"));
  CHECK_THAT(broken([](MeshArrays& a) { std::swap(a.edges[0].vertices[0], a.edges[0].vertices[1]); }).front(),
             Catch::Contains("direction"));
  CHECK_THAT(broken([](MeshArrays& a) { a.corner_edges[0] = a.corner_edges[1]; }).front(),
             Catch::Contains("corner 0"));
  CHECK_FALSE(broken([](MeshArrays& a) { a.face_offsets[1] = 2; }).empty());
}
