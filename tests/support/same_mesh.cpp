#include "support/same_mesh.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

namespace nome::test {

void check_same_mesh(const Mesh& a, const Mesh& b) {
  CHECK(validate(a).empty());
  CHECK(a.positions() == b.positions());
  CHECK(a.face_offsets() == b.face_offsets());
  CHECK(a.corner_vertices() == b.corner_vertices());
  CHECK(a.corner_edges() == b.corner_edges());
  CHECK(a.corner_faces() == b.corner_faces());
  CHECK(a.corner_signs() == b.corner_signs());
  REQUIRE(a.num_edges() == b.num_edges());
  for (Index e = 0; e < a.num_edges(); ++e) {
    const Edge &x = a.edge(e), &y = b.edge(e);
    CHECK((x.vertices == y.vertices && x.faces == y.faces && x.corners == y.corners &&
           x.is_mobius == y.is_mobius && x.is_sharp == y.is_sharp));
  }
  CHECK(a.fan_corner_offsets() == b.fan_corner_offsets());
  CHECK(a.fan_corners() == b.fan_corners());
  CHECK(a.fan_edge_offsets() == b.fan_edge_offsets());
  CHECK(a.fan_edges() == b.fan_edges());
  REQUIRE(a.num_boundary_loops() == b.num_boundary_loops());
  for (Index l = 0; l < a.num_boundary_loops(); ++l) {
    CHECK(std::ranges::equal(a.loop_edges(l), b.loop_edges(l)));
    CHECK(std::ranges::equal(a.loop_vertices(l), b.loop_vertices(l)));
  }
  CHECK(a.num_components() == b.num_components());
  for (Index f = 0; f < a.num_faces(); ++f) CHECK(a.face_component(f) == b.face_component(f));
  CHECK(a.face_attributes() == b.face_attributes());
}

}  // namespace nome::test
