#include "support/point_sets.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <vector>

#include <glm/geometric.hpp>

namespace nome::test {

std::string compare_point_sets(std::span<const Vec3> a, std::span<const Vec3> b, double relative_tolerance,
                               int multiplicity) {
  std::ostringstream out;
  if (a.size() * size_t(multiplicity) != b.size()) {
    out << a.size() << " points against " << b.size() << " (multiplicity " << multiplicity << ")";
    return out.str();
  }
  if (b.empty()) return "";
  Vec3 lo = b.front(), hi = b.front();
  for (const Vec3& p : b) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double tol = relative_tolerance * std::max(glm::length(hi - lo), 1e-300);
  const auto sorted_by_x = [](std::span<const Vec3> points) {
    std::vector<size_t> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return points[i].x < points[j].x; });
    return order;
  };
  const auto count_near = [&](std::span<const Vec3> points, const std::vector<size_t>& order, const Vec3& q) {
    const auto first = std::lower_bound(order.begin(), order.end(), q.x - tol,
                                        [&](size_t j, double x) { return points[j].x < x; });
    int found = 0;
    for (auto it = first; it != order.end() && points[*it].x <= q.x + tol; ++it)
      if (glm::length(points[*it] - q) <= tol) ++found;
    return found;
  };
  const std::vector<size_t> a_order = sorted_by_x(a), b_order = sorted_by_x(b);
  for (size_t i = 0; i < a.size(); ++i) {
    // Points that coincide in `a` (an immersion may put two vertices at one place) count together.
    const int wanted = multiplicity * count_near(a, a_order, a[i]);
    const int found = count_near(b, b_order, a[i]);
    if (found != wanted) {
      out << "point " << i << " (" << a[i].x << ", " << a[i].y << ", " << a[i].z << ") has " << found
          << " matches within " << tol << " (wanted " << wanted << ")";
      return out.str();
    }
  }
  return "";
}

}  // namespace nome::test
