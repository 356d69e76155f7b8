#pragma once

#include "cli/input.hpp"
#include "nome/query/print_check.hpp"

namespace nome::cli {

// The print check of what `loaded` made: the surface before the offset with the offset's distance, or the
// result itself when there is no offset (then only crossings, and near misses given a wall, are found).
// Runs the pipeline up to that surface (a cached stage), so an earlier result of it is gone.
PrintCheck check_loaded_input(LoadedInput& loaded, double min_wall, const Progress& progress);

// The surface the check ran on, coloured by what it found: faces in a crossing red, fold-over faces
// magenta, faces at a vertex closer than the wall to another sheet orange, the others light grey. What
// `nome render --print-check` draws.
Mesh marked_surface(LoadedInput& loaded, const PrintCheck& check);

// Triangles the renderer and the check would make of the mesh: sum over faces of (degree - 2).
std::uint64_t triangle_count(const Mesh& mesh);

}  // namespace nome::cli
