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

// The one face through `positions`, once starting at each of its corners.
std::vector<Mesh> face_rotations(const std::vector<Vec3>& positions) {
  PolygonSoup soup;
  soup.positions.assign(positions.begin(), positions.end());
  soup.face_offsets = {0, Index(soup.positions.size())};
  for (Index v = 0; v < soup.positions.size(); ++v) soup.face_vertices.push_back(v);
  std::vector<Mesh> meshes;
  for (std::size_t rotation = 0; rotation < soup.positions.size(); ++rotation) {
    std::rotate(soup.face_vertices.begin(), soup.face_vertices.begin() + 1, soup.face_vertices.end());
    meshes.push_back(build_mesh(soup));
  }
  return meshes;
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
  for (const Mesh& mesh :
       face_rotations({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}})) {
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

TEST_CASE("a concave quad is split along its inner diagonal, whichever corner is the reflex one",
          "[kernel]") {
  // A dart: corner 2 at (1, 0.5) points into the quad.
  for (const Mesh& mesh : face_rotations({{0, 0, 0}, {2, 0, 0}, {1, 0.5, 0}, {0, 2, 0}})) {
    const DisplayTriangles tri = display_triangles(mesh);
    check_covers_faces(mesh, tri);
    // Both triangles counter-clockwise: the diagonal through the reflex corner.
    for (const auto& t : tri.corners) CHECK(triangle_area_normal(mesh, t).z > 0.0);
  }
}

TEST_CASE("display triangles on two threads are those made on one", "[kernel]") {
  // Enough faces for two parts, with concave faces and triangles among the quads.
  PolygonSoup soup = test::grid(300, 250);
  for (std::size_t v = 0; v < soup.positions.size(); v += 7) soup.positions[v] += Vec3(0.6, 0.45, 0.0);
  const Mesh mesh = build_mesh(test::disjoint_union(soup, test::tetrahedron()));
  const DisplayTriangles one = display_triangles(mesh, 1);
  const DisplayTriangles two = display_triangles(mesh, 2);
  CHECK(two.corners == one.corners);
  CHECK(two.faces == one.faces);
  check_covers_faces(mesh, two);
}
