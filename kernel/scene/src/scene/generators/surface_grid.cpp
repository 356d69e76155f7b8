#include "scene/generators/surface_grid.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace nome::scene {
namespace {

// Where grid vertex (i, j) is stored: a closed direction folds its last index onto 0, a pole row onto
// its column 0.
struct GridFold {
  const SurfaceGrid& g;
  bool is_pole(int j) const { return (j == 0 && g.has_first_pole) || (j == g.along && g.has_last_pole); }
  std::pair<int, int> operator()(int i, int j) const {
    if (g.is_across_closed && i == g.across) i = 0;
    if (g.is_along_closed && j == g.along) j = 0;
    if (is_pole(j)) i = 0;
    return {i, j};
  }
};

}  // namespace

GridVertices add_surface_grid(Piece& piece, const SurfaceGrid& g,
                              const std::function<Vec3(int i, int j)>& point) {
  const GridFold fold{g};
  std::vector<Index> ids(size_t(g.across + 1) * size_t(g.along + 1), no_index);
  auto slot = [&](int i, int j) { return size_t(j) * size_t(g.across + 1) + size_t(i); };
  for (int j = 0; j <= g.along; ++j)
    for (int i = 0; i <= g.across; ++i) {
      const auto [fi, fj] = fold(i, j);
      if (fi != i || fj != j) continue;
      std::string name = g.prefix + (fold.is_pole(j) ? (j == 0 ? g.first_pole_name : g.last_pole_name)
                                                     : "v" + std::to_string(i) + "_" + std::to_string(j));
      ids[slot(i, j)] = piece.add_vertex(point(i, j), std::move(name));
    }
  for (int j = 0; j <= g.along; ++j)
    for (int i = 0; i <= g.across; ++i) {
      const auto [fi, fj] = fold(i, j);
      ids[slot(i, j)] = ids[slot(fi, fj)];
    }
  GridVertices grid(g.across, std::move(ids));
  for (int j = 0; j < g.along; ++j)
    for (int i = 0; i < g.across; ++i) {
      std::vector<Index> face{grid(i, j), grid(i + 1, j), grid(i + 1, j + 1), grid(i, j + 1)};
      // A pole row gives the quad two equal corners: the face is the triangle that remains.
      face.erase(std::unique(face.begin(), face.end()), face.end());
      if (face.size() > 1 && face.front() == face.back()) face.pop_back();
      if (g.is_reversed) std::reverse(face.begin(), face.end());
      if (face.size() >= 3)
        piece.add_face(face, g.prefix + "f" + std::to_string(i) + "_" + std::to_string(j));
    }
  return grid;
}

double sample_angle(int i, int segs, double degrees) {
  return degrees * std::numbers::pi / 180 * i / segs;
}

bool is_whole_turn(double degrees) {
  return std::abs(degrees - 360) < 1e-9;
}

}  // namespace nome::scene
