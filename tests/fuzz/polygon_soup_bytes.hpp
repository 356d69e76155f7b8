#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>

#include "nome/mesh/polygon_soup.hpp"

namespace nome::fuzz {

// Arbitrary bytes as a polygon soup. Byte 0: the vertex count (1..24); three bytes per position (255 is
// NaN, 254 infinity, others k/8 as a signed byte); then faces as a degree byte (1..6, so too-small faces
// occur) followed by that many vertex bytes (index == count is out of range).
inline PolygonSoup polygon_soup_from_bytes(const uint8_t* data, size_t size) {
  PolygonSoup soup;
  size_t i = 0;
  auto next = [&] { return i < size ? data[i++] : uint8_t(0); };
  const Index nv = 1 + next() % 24;
  for (Index v = 0; v < nv; ++v) {
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      const uint8_t b = next();
      p[k] = b == 255   ? std::numeric_limits<double>::quiet_NaN()
             : b == 254 ? std::numeric_limits<double>::infinity()
                        : double(int8_t(b)) / 8.0;
    }
    soup.add_vertex(p);
  }
  while (i < size) {
    const int degree = 1 + next() % 6;
    for (int k = 0; k < degree; ++k) soup.face_vertices.push_back(next() % (nv + 1));
    soup.face_offsets.push_back(Index(soup.face_vertices.size()));
  }
  return soup;
}

}  // namespace nome::fuzz
