#pragma once

#include <functional>
#include <string>
#include <vector>

#include "nome/scene/piece.hpp"

namespace nome::scene {

// A surface sampled on a grid of parameters: columns i in [0, across] and rows j in [0, along]. A closed
// direction shares its last column (row) with the first, and a pole row is one vertex, so that a whole
// sphere or torus has no coincident copies. Vertices are named `v{i}_{j}` (poles `pole_name`), faces
// `f{i}_{j}`: quads, triangles at a pole.
struct SurfaceGrid {
  int across = 1, along = 1;
  bool is_across_closed = false;
  bool is_along_closed = false;
  bool has_first_pole = false;  // row 0 is one vertex
  bool has_last_pole = false;   // row `along` is one vertex
  std::string first_pole_name = "south", last_pole_name = "north";
  std::string prefix;        // before every name: two grids in one piece
  bool is_reversed = false;  // faces turn from row j to j+1 first: normal d/dj x d/di
};

// The ids of a grid's vertices in the piece, by (i, j).
class GridVertices {
 public:
  GridVertices(int across, std::vector<Index> ids) : across_(across), ids_(std::move(ids)) {}
  Index operator()(int i, int j) const { return ids_[size_t(j) * size_t(across_ + 1) + size_t(i)]; }

 private:
  int across_;
  std::vector<Index> ids_;
};

// Adds the grid's vertices (point(i, j), evaluated once per distinct vertex) and faces to `piece`. The
// faces turn from column i to i+1 and then from row j to j+1: their normal is d/di x d/dj.
GridVertices add_surface_grid(Piece& piece, const SurfaceGrid& grid,
                              const std::function<Vec3(int i, int j)>& point);

// The angle of sample i of `segs` over [0, degrees], in radians.
double sample_angle(int i, int segs, double degrees);
// A sweep of `degrees` is a whole turn (and then closes on itself).
bool is_whole_turn(double degrees);

}  // namespace nome::scene
