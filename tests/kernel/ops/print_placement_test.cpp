#include <catch2/catch.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "nome/error.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/ops/print_placement.hpp"
#include "support/shapes.hpp"

using namespace nome;
using namespace nome::test;

namespace {

// A 6 x 4 x 1 slab, turned and moved off the origin so that no face starts out level.
Mesh tilted_slab() {
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), Vec3(5.0, -2.0, 7.0));
  m = glm::rotate(m, 0.7, glm::normalize(Vec3(1.0, 2.0, 0.5)));
  m = glm::scale(m, Vec3(3.0, 2.0, 0.5));
  return transformed(build_mesh(cube()), m);
}

double placed_lowest_z(const Mesh& mesh) {
  double z = mesh.position(0).z;
  for (const Vec3& p : mesh.positions()) z = std::min(z, p.z);
  return z;
}

double placed_height(const Mesh& mesh) {
  double high = mesh.position(0).z;
  for (const Vec3& p : mesh.positions()) high = std::max(high, p.z);
  return high - placed_lowest_z(mesh);
}

// The unit normal of face f pointing away from the mesh's centre.
Vec3 placed_outward(const Mesh& mesh, Index f) {
  Vec3 centre(0.0), at(0.0);
  for (const Vec3& p : mesh.positions()) centre += p;
  centre /= double(mesh.num_vertices());
  for (Index v : mesh.face_vertices(f)) at += mesh.position(v);
  at /= double(mesh.face_degree(f));
  const Vec3 n = glm::normalize(face_area_normal(mesh, f));
  return glm::dot(n, at - centre) > 0 ? n : -n;
}

}  // namespace

TEST_CASE("Resting on the flattest face turns the slab's largest side down onto z = 0", "[kernel]") {
  const Mesh slab = tilted_slab();
  const Index f = flattest_face(slab);
  CHECK((f == 0 || f == 1));  // the cube's z faces became the 6 x 4 sides
  const Mesh placed = placed_for_print(slab, {.rest = RestOn::flattest});
  CHECK(placed_lowest_z(placed) == Approx(0.0).margin(1e-9));
  CHECK(placed_height(placed) == Approx(1.0));
  CHECK(placed_outward(placed, f).z == Approx(-1.0));
  for (Index v : placed.face_vertices(f)) CHECK(placed.position(v).z == Approx(0.0).margin(1e-9));
}

TEST_CASE("Resting on a chosen face puts that face down", "[kernel]") {
  const Mesh slab = tilted_slab();
  const PrintPlacement placement = print_placement(slab, {.rest = RestOn::face, .rest_face = 4});
  CHECK(placement.rest_face == 4);
  const Mesh placed = transformed(slab, placement.transform);
  CHECK(placed_outward(placed, 4).z == Approx(-1.0));
  CHECK(placed_lowest_z(placed) == Approx(0.0).margin(1e-9));
  CHECK(placed_height(placed) == Approx(6.0));  // standing on its 4 x 1 end
}

TEST_CASE("Fitting scales the height or the largest dimension to the size asked for", "[kernel]") {
  const Mesh torus = build_mesh(test::torus(24, 12, 1.0, 0.3));
  const Mesh tall = placed_for_print(torus, {.fit = FitTarget::height, .fit_size = 60.0});
  CHECK(placed_height(tall) == Approx(60.0));
  const Mesh wide = placed_for_print(torus, {.fit = FitTarget::largest, .fit_size = 60.0});
  double x_low = wide.position(0).x, x_high = x_low;
  for (const Vec3& p : wide.positions()) x_low = std::min(x_low, p.x), x_high = std::max(x_high, p.x);
  CHECK(x_high - x_low == Approx(60.0));
  const Mesh both =
      placed_for_print(tilted_slab(), {.fit = FitTarget::height, .fit_size = 60.0, .rest = RestOn::flattest});
  CHECK(placed_height(both) == Approx(60.0));
  CHECK(placed_lowest_z(both) == Approx(0.0).margin(1e-9));
}

TEST_CASE("Print placement refuses a missing face and a size that is not positive", "[kernel]") {
  const Mesh slab = tilted_slab();
  CHECK_THROWS_AS(print_placement(slab, {.rest = RestOn::face, .rest_face = 6}), InvalidInputError);
  CHECK_THROWS_AS(print_placement(slab, {.fit = FitTarget::height, .fit_size = -1.0}), InvalidInputError);
  CHECK(placed_for_print(slab, {}).positions() == slab.positions());
}
