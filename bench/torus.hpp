#pragma once

#include <cmath>

#include "nome/mesh/mesh.hpp"

namespace nome::bench {

// A u x v quad torus (major radius 1, minor 0.3): the benchmarks' mesh of any size.
inline Mesh torus(Index u, Index v) {
  PolygonSoup s;
  const double two_pi = 6.283185307179586;
  for (Index i = 0; i < u; ++i)
    for (Index j = 0; j < v; ++j) {
      const double a = two_pi * i / u, b = two_pi * j / v;
      s.add_vertex({(1.0 + 0.3 * std::cos(b)) * std::cos(a), (1.0 + 0.3 * std::cos(b)) * std::sin(a),
                    0.3 * std::sin(b)});
    }
  auto id = [&](Index i, Index j) { return (i % u) * v + (j % v); };
  for (Index i = 0; i < u; ++i)
    for (Index j = 0; j < v; ++j) s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return build_mesh(std::move(s));
}

}  // namespace nome::bench
