#include <catch2/catch.hpp>

#include <random>

#include <glm/geometric.hpp>

#include "nome/error.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/offset_normals.hpp"
#include "support/shapes.hpp"

using namespace nome;

TEST_CASE("an offset of two parallel copies is drawn with its surface's normals", "[kernel]") {
  const Mesh torus = build_mesh(test::torus(24, 12));
  const Normals normals = compute_normals(torus);
  Buffer<PackedNormal> faces, vertices;
  REQUIRE(is_two_copy_offset(torus));
  REQUIRE(offset_packed_normals(torus, normals, faces, vertices, 2));
  const Mesh solid = offset(torus, normals, {0.02});
  REQUIRE(faces.size() == solid.num_faces());
  REQUIRE(vertices.size() == solid.num_vertices());
  const Index nf = torus.num_faces();
  for (Index f = 0; f < nf; ++f) {
    CHECK(faces[f] == pack_normal(glm::vec3(normals.faces[f])));
    CHECK(faces[nf + f] == pack_normal(-glm::vec3(normals.faces[f])));
  }
  for (Index v = 0; v < torus.num_vertices(); ++v) {
    CHECK(vertices[2 * v] == pack_normal(glm::vec3(normals.vertices[v])));
    CHECK(vertices[2 * v + 1] == pack_normal(-glm::vec3(normals.vertices[v])));
  }
  // The solid's own polygons give nearly the same directions (a new estimate of the same surface).
  Buffer<PackedNormal> own_faces, own_vertices;
  compute_packed_normals(solid, own_faces, own_vertices, 1);
  for (Index f = 0; f < solid.num_faces(); ++f)
    CHECK(glm::dot(unpack_normal(faces[f]), unpack_normal(own_faces[f])) > 0.995f);
  for (Index v = 0; v < solid.num_vertices(); ++v)
    CHECK(glm::dot(unpack_normal(vertices[v]), unpack_normal(own_vertices[v])) > 0.995f);
}

TEST_CASE("an offset with rims or Möbius crossings leaves its display normals to the solid", "[kernel]") {
  std::mt19937 rng{42};
  const PolygonSoup cases[] = {test::grid(3, 2), test::mobius_band(12, 2), test::klein_bottle(12, 8),
                               test::reverse_random_faces(test::torus(8, 6), 0.5, rng)};
  for (const PolygonSoup& soup : cases) {
    const Mesh mesh = build_mesh(soup);
    Buffer<PackedNormal> faces(1, 7u), vertices(2, 7u);
    CHECK_FALSE(is_two_copy_offset(mesh));
    CHECK_FALSE(offset_packed_normals(mesh, compute_normals(mesh), faces, vertices));
    CHECK(faces == Buffer<PackedNormal>(1, 7u));
    CHECK(vertices == Buffer<PackedNormal>(2, 7u));
  }
  // A vertex without faces has no copies: the solid's vertices are no longer 2v and 2v + 1.
  PolygonSoup lone = test::cube();
  lone.add_vertex({5, 5, 5});
  CHECK_FALSE(is_two_copy_offset(build_mesh(lone)));
}

TEST_CASE("offset_packed_normals refuses normals of another mesh", "[kernel]") {
  const Mesh torus = build_mesh(test::torus(8, 6));
  Buffer<PackedNormal> faces, vertices;
  CHECK_THROWS_AS(offset_packed_normals(torus, compute_normals(build_mesh(test::cube())), faces, vertices),
                  InvalidInputError);
}
