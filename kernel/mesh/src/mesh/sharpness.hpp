#pragma once

// Internal to the mesh builders: a soup's crease weights, corner weights and holes onto a mesh and back.

#include "nome/mesh/mesh.hpp"

namespace nome {

// The soup's sharp edges (with their weights), sharp vertices and holes onto the built mesh `m`. Throws
// TopologyError naming a sharp pair that is not an edge, or a vertex or face out of range.
void apply_soup_features(Mesh& m, const PolygonSoup& soup);
// The mesh's sharp edges (weights only when some is finite), corner weights and holes into `soup`.
void add_features_to_soup(const Mesh& mesh, PolygonSoup& soup);

}  // namespace nome
