#pragma once

// Internal to subdivision: the steps of the classic rule's tiled position pass
// (refine_child_positions_by_tile) over ranges of G's faces, edges and vertices, in baseline instructions
// and, where the CPU has them, in AVX2 ones (a position in one register, a lane to spare): the same sums in
// the same order, so the same bits.

#include "ops/subdivision/child_pass.hpp"

namespace nome {

using LevelPass = ChildPass<Refinement::Level>;

struct TileSteps {
  void (*faces)(const LevelPass& pass, Index first, Index last);
  void (*edges)(const LevelPass& pass, Index first, Index last, ReadyCorners ready);
  // The vertex points of G's vertices [first, last), which are P's vertex points.
  void (*vertices)(const LevelPass& pass, Index first, Index last, VertexRules rules, ReadyCorners ready);
};

// The AVX2 steps when `is_vector_allowed`, this program has them and the CPU runs them; else the baseline
// ones. The AVX2 steps read each position of pass.in with the 8 bytes after it: one more Vec3 after
// pass.in must be readable.
const TileSteps& tile_steps(bool is_vector_allowed);

// The AVX2 steps, or null in a program built for another architecture (tile_steps_avx2.cpp).
const TileSteps* avx2_tile_steps();

}  // namespace nome
