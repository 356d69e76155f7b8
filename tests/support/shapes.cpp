#include "support/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace nome::test {
namespace {
constexpr double two_pi = 6.283185307179586;
}

PolygonSoup tetrahedron() {
  PolygonSoup s;
  s.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  s.add_face({0, 1, 2});
  s.add_face({0, 3, 1});
  s.add_face({0, 2, 3});
  s.add_face({1, 3, 2});
  return s;
}

PolygonSoup cube() {
  PolygonSoup s;
  for (int i = 0; i < 8; ++i) s.add_vertex(Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  s.add_face({0, 2, 3, 1});  // z = -1
  s.add_face({4, 5, 7, 6});  // z = +1
  s.add_face({0, 1, 5, 4});  // y = -1
  s.add_face({2, 6, 7, 3});  // y = +1
  s.add_face({0, 4, 6, 2});  // x = -1
  s.add_face({1, 3, 7, 5});  // x = +1
  return s;
}

PolygonSoup grid(Index nx, Index ny) {
  PolygonSoup s;
  for (Index j = 0; j <= ny; ++j)
    for (Index i = 0; i <= nx; ++i) s.add_vertex(Vec3(double(i), double(j), 0.0));
  auto id = [&](Index i, Index j) { return j * (nx + 1) + i; };
  for (Index j = 0; j < ny; ++j)
    for (Index i = 0; i < nx; ++i) s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return s;
}

PolygonSoup torus(Index u, Index v, double major, double minor) {
  PolygonSoup s;
  for (Index i = 0; i < u; ++i)
    for (Index j = 0; j < v; ++j) {
      const double a = two_pi * i / u, b = two_pi * j / v;
      s.add_vertex(Vec3((major + minor * std::cos(b)) * std::cos(a),
                        (major + minor * std::cos(b)) * std::sin(a), minor * std::sin(b)));
    }
  auto id = [&](Index i, Index j) { return (i % u) * v + (j % v); };
  for (Index i = 0; i < u; ++i)
    for (Index j = 0; j < v; ++j) s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return s;
}

PolygonSoup mobius_band(Index segments, Index width, Index twists) {
  PolygonSoup s;
  for (Index i = 0; i < segments; ++i)
    for (Index j = 0; j <= width; ++j) {
      const double a = two_pi * i / segments, t = (double(j) / width - 0.5) * 0.6, phi = 0.5 * twists * a;
      s.add_vertex(Vec3((1 + t * std::cos(phi)) * std::cos(a), (1 + t * std::cos(phi)) * std::sin(a),
                        t * std::sin(phi)));
    }
  auto id = [&](Index i, Index j) {
    if (i == segments && twists % 2 == 1) return width - j;  // across the seam the strip comes back flipped
    return (i % segments) * (width + 1) + j;
  };
  for (Index i = 0; i < segments; ++i)
    for (Index j = 0; j < width; ++j) s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return s;
}

PolygonSoup klein_bottle(Index u, Index v) {
  PolygonSoup s;
  for (Index i = 0; i < u; ++i)
    for (Index j = 0; j < v; ++j) {
      const double a = two_pi * i / u, b = two_pi * j / v, r = 2.0;
      const double w = r + std::cos(a / 2) * std::sin(b) - std::sin(a / 2) * std::sin(2 * b);
      s.add_vertex(Vec3(w * std::cos(a), w * std::sin(a),
                        std::sin(a / 2) * std::sin(b) + std::cos(a / 2) * std::sin(2 * b)));
    }
  // Going once around in a, the figure-8 comes back mirrored: (2 pi, b) = (0, -b).
  auto id = [&](Index i, Index j) { return i == u ? (v - j % v) % v : i * v + j % v; };
  for (Index i = 0; i < u; ++i)
    for (Index j = 0; j < v; ++j) s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return s;
}

PolygonSoup projective_plane() {
  PolygonSoup s;
  // Classes of antipodal cube corners: A=(+++), B=(++-), C=(+-+), D=(-++).
  s.positions = {{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
  const Index A = 0, B = 1, C = 2, D = 3;
  s.add_face({A, C, D, B});  // x = +1 and x = -1
  s.add_face({A, B, C, D});  // y = +1 and y = -1
  s.add_face({A, D, B, C});  // z = +1 and z = -1
  return s;
}

PolygonSoup reverse_random_faces(PolygonSoup s, double fraction, std::mt19937& rng) {
  std::bernoulli_distribution flip(fraction);
  for (Index f = 0; f < s.num_faces(); ++f)
    if (flip(rng))
      std::reverse(s.face_vertices.begin() + s.face_offsets[f],
                   s.face_vertices.begin() + s.face_offsets[f + 1]);
  return s;
}

PolygonSoup renumber_vertices(PolygonSoup s, std::mt19937& rng) {
  std::vector<Index> perm(s.num_vertices());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  Buffer<Vec3> positions(s.positions.size());
  for (Index v = 0; v < s.num_vertices(); ++v) positions[perm[v]] = s.positions[v];
  s.positions = std::move(positions);
  for (Index& v : s.face_vertices) v = perm[v];
  for (auto& [a, b] : s.sharp_edges) a = perm[a], b = perm[b];
  return s;
}

PolygonSoup rotate_corners(PolygonSoup s, std::mt19937& rng) {
  for (Index f = 0; f < s.num_faces(); ++f) {
    const auto b = s.face_vertices.begin() + s.face_offsets[f],
               e = s.face_vertices.begin() + s.face_offsets[f + 1];
    std::rotate(b, b + std::uniform_int_distribution<long>(0, (e - b) - 1)(rng), e);
  }
  return s;
}

PolygonSoup disjoint_union(const PolygonSoup& a, const PolygonSoup& b) {
  PolygonSoup s = a;
  const Index base = a.num_vertices();
  s.positions.insert(s.positions.end(), b.positions.begin(), b.positions.end());
  for (Index f = 0; f < b.num_faces(); ++f) {
    for (Index c = b.face_offsets[f]; c < b.face_offsets[f + 1]; ++c)
      s.face_vertices.push_back(b.face_vertices[c] + base);
    s.face_offsets.push_back(Index(s.face_vertices.size()));
  }
  return s;
}

std::vector<PolygonSoup> split_faces(const PolygonSoup& soup, const std::vector<Index>& part_of_face) {
  const Index num_parts =
      part_of_face.empty() ? 0 : *std::max_element(part_of_face.begin(), part_of_face.end()) + 1;
  std::vector<PolygonSoup> parts(num_parts);
  std::vector<std::vector<Index>> copies(num_parts, std::vector<Index>(soup.num_vertices(), no_index));
  std::vector<std::vector<Index>> part_faces(num_parts);
  for (Index f = 0; f < soup.num_faces(); ++f) {
    PolygonSoup& part = parts[part_of_face[f]];
    std::vector<Index>& copy = copies[part_of_face[f]];
    std::vector<Index> face;
    for (Index c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
      const Index v = soup.face_vertices[c];
      if (copy[v] == no_index) {
        copy[v] = part.add_vertex(soup.positions[v]);
        if (!soup.vertex_names.empty()) part.vertex_names.push_back(soup.vertex_names[v]);
      }
      face.push_back(copy[v]);
    }
    part.add_face(face);
    if (!soup.face_names.empty()) part.face_names.push_back(soup.face_names[f]);
    part_faces[part_of_face[f]].push_back(f);
  }
  for (size_t i = 0; i < parts.size(); ++i)
    parts[i].face_attributes = carried(soup.face_attributes, part_faces[i]);
  return parts;
}

}  // namespace nome::test
