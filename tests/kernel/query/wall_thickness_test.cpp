#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "nome/ops/offset.hpp"
#include "nome/ops/subdivide.hpp"
#include "nome/query/wall_thickness.hpp"
#include "support/shapes.hpp"

using namespace nome;
using namespace nome::test;

namespace {

// The middle of face f.
Vec3 wall_face_centre(const Mesh& mesh, Index f) {
  Vec3 c(0.0);
  for (Index v : mesh.face_vertices(f)) c += mesh.position(v);
  return c / double(mesh.face_degree(f));
}

}  // namespace

TEST_CASE("The wall of an offset solid of distance d measures 2d within 1 %", "[kernel]") {
  const double d = 0.04;
  for (const auto& [name, soup] :
       {std::pair{"torus", torus(32, 16, 1.0, 0.3)}, std::pair{"mobius", mobius_band(48, 4)}}) {
    INFO(name);
    const Mesh surface = subdivide(build_mesh(soup), {.levels = 1});
    const Mesh solid = offset(surface, OffsetOptions{.distance = d});
    const TriangleBvh bvh(solid);
    int measured = 0;
    for (Index f = 0; f < solid.num_faces(); f += 37) {
      const auto wall = wall_thickness(solid, bvh, f, wall_face_centre(solid, f));
      if (!wall) continue;
      ++measured;
      // The rims' ribbon faces of an open surface measure along the rim: only the sheets count here.
      if (f >= 2 * surface.num_faces()) continue;
      CHECK(wall->thickness == Approx(2 * d).epsilon(0.01));
    }
    CHECK(measured > 10);
  }
  // An open surface has no inside.
  const Mesh band = build_mesh(mobius_band(24, 2));
  CHECK_FALSE(wall_thickness(band, TriangleBvh(band), 0, wall_face_centre(band, 0)));
}
