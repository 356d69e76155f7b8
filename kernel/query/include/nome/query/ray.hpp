#pragma once

#include <array>

#include "nome/mesh/types.hpp"

namespace nome {

// A ray origin + t * direction, t in [t_min, t_max]. The direction need not be unit length: depths are
// in units of t, so a ray through a pixel with direction = far point - near point gives t in [0, 1].
struct Ray {
  Vec3 origin{0.0};
  Vec3 direction{0.0, 0.0, -1.0};
  double t_min = 0.0;
  double t_max = 1e300;
};

// The per-ray constants of the watertight ray/triangle test (Woop, Benthin, Wald, JCGT 2013): the
// axis permutation and shear that map the ray to +z. Computed once per ray, shared by all triangles.
struct ShearedRay {
  explicit ShearedRay(const Ray& ray);

  Ray ray;
  std::array<int, 3> axes{0, 1, 2};  // kx, ky, kz
  double shear_x = 0.0, shear_y = 0.0, shear_z = 0.0;
};

// Where a ray meets one triangle: depth t and barycentric weights of (a, b, c), each >= 0, summing to 1.
struct TriangleHit {
  double depth = 0.0;
  std::array<double, 3> barycentric{0.0, 0.0, 0.0};
};

// Watertight, two-sided ray/triangle test: a ray through an edge or a vertex shared by several
// triangles hits at least one of them (no cracks), the edge functions of a shared edge being computed
// bit-identically on both sides. Barycentric weights of exactly 0 mean the hit lies on that edge.
bool intersect_triangle(const ShearedRay& ray, const Vec3& a, const Vec3& b, const Vec3& c, TriangleHit& hit);

}  // namespace nome
