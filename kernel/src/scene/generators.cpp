#include "nome/scene/generators.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "nome/error.hpp"

namespace nome::scene {
namespace {

// Appends an n-gon ring of named vertices; returns the id of its first vertex.
Index ring(Piece& piece, int n, double radius, double z, const char* prefix) {
  const Index first = piece.soup.num_vertices();
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    piece.add_vertex({radius * std::cos(a), radius * std::sin(a), z}, prefix + std::to_string(i));
  }
  return first;
}

// Quads joining ring `lower` to ring `upper` (each n vertices), normals pointing away from the axis.
void band(Piece& piece, int n, Index lower, Index upper, const char* prefix) {
  for (int i = 0; i < n; ++i) {
    const Index j = Index((i + 1) % n);
    const std::array<Index, 4> quad{lower + Index(i), lower + j, upper + j, upper + Index(i)};
    piece.add_face(quad, prefix + std::to_string(i));
  }
}

void require(bool ok, const char* message) {
  if (!ok) throw InvalidInputError(message);
}

}  // namespace

Piece funnel(const FunnelParams& p) {
  require(p.n >= 3, "funnel: n must be at least 3");
  Piece piece;
  const Index base = ring(piece, p.n, p.ro, 0, "bc");
  const Index high = ring(piece, p.n, p.ro * (1 + p.ratio), p.h, "hc");
  band(piece, p.n, base, high, "f");
  return piece;
}

Piece tunnel(const TunnelParams& p) {
  require(p.n >= 3, "tunnel: n must be at least 3");
  Piece piece;
  const Index base = ring(piece, p.n, p.ro, 0, "bc");
  const Index high = ring(piece, p.n, p.ro * (1 + p.ratio), p.h, "hc");
  const Index low = ring(piece, p.n, p.ro * (1 + p.ratio_low), -p.h_low, "lc");
  band(piece, p.n, base, high, "hf");
  band(piece, p.n, low, base, "lf");
  return piece;
}

Piece circle(int n, double r) {
  require(n >= 3, "circle: n must be at least 3");
  Piece piece;
  ring(piece, n, r, 0, "c");
  RimLine rim{"", {}, true};
  for (Index v = 0; v < Index(n); ++v) rim.vertices.push_back(v);
  piece.rims.push_back(std::move(rim));
  return piece;
}

Piece mobius_strip(const MobiusStripParams& p) {
  require(p.segs >= 3 && p.cuts >= 1 && p.twists >= 0,
          "mobius_strip: needs segs >= 3, cuts >= 1, twists >= 0");
  Piece piece;
  const int across = p.cuts + 1;
  const double half_width = p.radius / 4;
  for (int i = 0; i < p.segs; ++i) {
    const double around = 2 * std::numbers::pi * i / p.segs;
    const double turn = std::numbers::pi * p.twists * i / p.segs;
    const Vec3 radial{std::cos(around), std::sin(around), 0};
    const Vec3 across_dir = std::cos(turn) * radial + std::sin(turn) * Vec3(0, 0, 1);
    for (int j = 0; j < across; ++j) {
      const double t = -half_width + 2 * half_width * j / p.cuts;
      piece.add_vertex(p.radius * radial + t * across_dir, "v" + std::to_string(i) + "_" + std::to_string(j));
    }
  }
  // After a full turn the cross-section has turned by twists*180 degrees: odd twists reverse it.
  const bool reversed = p.twists % 2 == 1;
  auto vertex = [&](int i, int j) {
    if (i == p.segs) {
      i = 0;
      if (reversed) j = p.cuts - j;
    }
    return Index(i * across + j);
  };
  for (int i = 0; i < p.segs; ++i)
    for (int j = 0; j < p.cuts; ++j) {
      const std::array<Index, 4> quad{vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
      piece.add_face(quad, "f" + std::to_string(i) + "_" + std::to_string(j));
    }
  return piece;
}

}  // namespace nome::scene
