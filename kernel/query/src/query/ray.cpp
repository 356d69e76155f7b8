#include "nome/query/ray.hpp"

#include <cmath>
#include <utility>

namespace nome {

ShearedRay::ShearedRay(const Ray& r) : ray(r) {
  const Vec3& d = r.direction;
  int kz = 0;
  if (std::abs(d.y) > std::abs(d[kz])) kz = 1;
  if (std::abs(d.z) > std::abs(d[kz])) kz = 2;
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  // Keep the winding of the sheared triangle independent of the sign of the dominant axis.
  if (d[kz] < 0.0) std::swap(kx, ky);
  axes = {kx, ky, kz};
  shear_x = d[kx] / d[kz];
  shear_y = d[ky] / d[kz];
  shear_z = 1.0 / d[kz];
}

namespace {

// Edge functions in extended precision, used only when the double ones are exactly zero (the ray
// passes through an edge or vertex to double precision) so that the sign decision is exact enough.
template <typename Real>
void edge_functions(const ShearedRay& r, const Vec3& a, const Vec3& b, const Vec3& c, Real& u, Real& v,
                    Real& w) {
  const auto [kx, ky, kz] = r.axes;
  const Real ax = Real(a[kx] - r.ray.origin[kx]) - Real(r.shear_x) * Real(a[kz] - r.ray.origin[kz]);
  const Real ay = Real(a[ky] - r.ray.origin[ky]) - Real(r.shear_y) * Real(a[kz] - r.ray.origin[kz]);
  const Real bx = Real(b[kx] - r.ray.origin[kx]) - Real(r.shear_x) * Real(b[kz] - r.ray.origin[kz]);
  const Real by = Real(b[ky] - r.ray.origin[ky]) - Real(r.shear_y) * Real(b[kz] - r.ray.origin[kz]);
  const Real cx = Real(c[kx] - r.ray.origin[kx]) - Real(r.shear_x) * Real(c[kz] - r.ray.origin[kz]);
  const Real cy = Real(c[ky] - r.ray.origin[ky]) - Real(r.shear_y) * Real(c[kz] - r.ray.origin[kz]);
  u = cx * by - cy * bx;
  v = ax * cy - ay * cx;
  w = bx * ay - by * ax;
}

}  // namespace

bool intersect_triangle(const ShearedRay& r, const Vec3& a, const Vec3& b, const Vec3& c, TriangleHit& hit) {
  double u, v, w;
  edge_functions<double>(r, a, b, c, u, v, w);
  if (u == 0.0 || v == 0.0 || w == 0.0) {
    long double lu, lv, lw;
    edge_functions<long double>(r, a, b, c, lu, lv, lw);
    u = double(lu);
    v = double(lv);
    w = double(lw);
  }
  // Two-sided: all edge functions of one sign (zero allowed) is a hit.
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
  const double det = u + v + w;
  if (det == 0.0) return false;
  const int kz = r.axes[2];
  const double az = r.shear_z * (a[kz] - r.ray.origin[kz]);
  const double bz = r.shear_z * (b[kz] - r.ray.origin[kz]);
  const double cz = r.shear_z * (c[kz] - r.ray.origin[kz]);
  const double t = (u * az + v * bz + w * cz) / det;
  if (!(t >= r.ray.t_min && t <= r.ray.t_max)) return false;
  hit.depth = t;
  hit.barycentric = {u / det, v / det, w / det};
  return true;
}

}  // namespace nome
