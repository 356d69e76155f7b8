#include "nome/query/triangle_proximity.hpp"

#include <glm/geometric.hpp>

namespace nome {
namespace {

// Signed distances (times the normal's length) of a's corners from b's plane.
std::array<double, 3> sides_of_plane(const Triangle& a, const Triangle& b) {
  const Vec3 normal = glm::cross(b[1] - b[0], b[2] - b[0]);
  return {glm::dot(normal, a[0] - b[0]), glm::dot(normal, a[1] - b[0]), glm::dot(normal, a[2] - b[0])};
}

bool is_all_on_one_side(const std::array<double, 3>& s) {
  return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
}

bool lies_in_triangle(const Vec3& p, const Triangle& t) {
  const Vec3 normal = glm::cross(t[1] - t[0], t[2] - t[0]);
  for (int i = 0; i < 3; ++i)
    if (glm::dot(glm::cross(t[(i + 1) % 3] - t[i], p - t[i]), normal) < 0.0) return false;
  return true;
}

// Adds the points where a's sides cross b's plane inside b.
void add_side_cuts(const Triangle& a, const std::array<double, 3>& side, const Triangle& b, Vec3* points,
                   int& count) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if ((side[i] > 0 && side[j] > 0) || (side[i] < 0 && side[j] < 0)) continue;
    if (side[i] == side[j]) continue;  // both zero: the side lies in the plane
    const Vec3 p = a[i] + (a[j] - a[i]) * (side[i] / (side[i] - side[j]));
    if (lies_in_triangle(p, b) && count < 6) points[count++] = p;
  }
}

}  // namespace

bool triangles_cross(const Triangle& a, const Triangle& b, CrossingSegment& segment) {
  const std::array<double, 3> a_sides = sides_of_plane(a, b);
  if (is_all_on_one_side(a_sides)) return false;
  const std::array<double, 3> b_sides = sides_of_plane(b, a);
  if (is_all_on_one_side(b_sides)) return false;
  // Coplanar, or one of them degenerate (a zero normal puts everything on its plane).
  if (a_sides == std::array<double, 3>{0, 0, 0} || b_sides == std::array<double, 3>{0, 0, 0}) return false;
  Vec3 points[6];
  int count = 0;
  add_side_cuts(a, a_sides, b, points, count);
  add_side_cuts(b, b_sides, a, points, count);
  if (count == 0) return false;
  segment.from = points[0];
  segment.to = points[0];
  double longest = 0.0;
  for (int i = 1; i < count; ++i) {
    const double length = glm::distance(points[0], points[i]);
    if (length > longest) {
      longest = length;
      segment.to = points[i];
    }
  }
  return true;
}

Vec3 closest_point_on_triangle(const Vec3& p, const Triangle& t) {
  const Vec3 &a = t[0], &b = t[1], &c = t[2];
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

}  // namespace nome
