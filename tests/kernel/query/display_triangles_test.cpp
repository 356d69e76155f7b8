#include <catch2/catch.hpp>

#include <algorithm>

#include <glm/geometric.hpp>

#include "nome/mesh/normals.hpp"
#include "nome/query/display_triangles.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

Vec3 triangle_area_normal(const Mesh& mesh, const std::array<Index, 3>& t) {
  const Vec3& a = mesh.position(mesh.corner_vertex(t[0]));
  const Vec3& b = mesh.position(mesh.corner_vertex(t[1]));
  const Vec3& c = mesh.position(mesh.corner_vertex(t[2]));
  return glm::cross(b - a, c - a);
}

// Every triangle's corners belong to its face, and the triangles of a face add up to the face's own
// Newell area vector (same orientation, no overlap).
void check_covers_faces(const Mesh& mesh, const DisplayTriangles& tri) {
  std::vector<Vec3> sums(mesh.num_faces(), Vec3(0.0));
  std::vector<Index> counts(mesh.num_faces(), 0);
  for (size_t i = 0; i < tri.corners.size(); ++i) {
    const Index f = tri.faces[i];
    for (Index c : tri.corners[i]) REQUIRE(mesh.corner_face(c) == f);
    sums[f] += triangle_area_normal(mesh, tri.corners[i]);
    ++counts[f];
  }
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    CHECK(counts[f] == mesh.face_degree(f) - 2);
    const Vec3 newell = face_area_normal(mesh, f);
    CHECK(glm::length(sums[f] - newell) < 1e-9 * (1.0 + glm::length(newell)));
  }
}

}  // namespace

TEST_CASE("display triangles of procedural shapes keeps each face's orientation", "[kernel]") {
  for (const PolygonSoup& soup :
       {test::cube(), test::torus(8, 5), test::mobius_band(16, 4), test::grid(3, 2)}) {
    const Mesh mesh = build_mesh(soup);
    check_covers_faces(mesh, display_triangles(mesh));
  }
}

TEST_CASE("a concave face is ear-clipped, never fanned across its notch", "[kernel]") {
  // An L-shape whose fan from corner 0 would cover the notch; each triangle must lie inside the L.
  PolygonSoup soup;
  soup.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  soup.face_vertices = {0, 1, 2, 3, 4, 5};
  soup.face_offsets = {0, 6};
  for (int rotation = 0; rotation < 6; ++rotation) {
    std::rotate(soup.face_vertices.begin(), soup.face_vertices.begin() + 1, soup.face_vertices.end());
    const Mesh mesh = build_mesh(soup);
    const DisplayTriangles tri = display_triangles(mesh);
    check_covers_faces(mesh, tri);
    for (const auto& t : tri.corners) {
      // All-positive areas: a triangle over the notch would be clockwise or overlap another.
      CHECK(triangle_area_normal(mesh, t).z > 0.0);
      Vec3 centroid(0.0);
      for (Index c : t) centroid += mesh.position(mesh.corner_vertex(c)) / 3.0;
      CHECK_FALSE((centroid.x > 1.0 && centroid.y > 1.0));
    }
  }
}
