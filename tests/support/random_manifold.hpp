#pragma once

#include <random>
#include <vector>

#include "nome/mesh/polygon_soup.hpp"

// Random valid 2-manifolds for property tests, with their topology known from how they were made.
namespace nome::test {

// Topology of one connected part as the gluing defines it (not measured on the mesh).
struct ExpectedPart {
  long long vertices = 0, edges = 0, faces = 0;
  long long chi = 0;
  bool orientable = true;
  long long borders = 0;
};

struct RandomManifold {
  PolygonSoup soup;
  // Parts in the order of their first face in `soup` (the order a topology report lists them).
  std::vector<ExpectedPart> parts;
  int refinement_levels = 0;  // quad refinements applied to the glued polygons
};

struct RandomManifoldOptions {
  int max_polygons = 8;        // triangles and quads glued edge to edge
  double closed_chance = 0.4;  // chance that every side is glued (no border)
  double twist_chance = 0.3;   // chance that a glued pair is a Möbius (orientation-reversing) join
};

// Triangles and quads whose sides are paired at random (each pair regular or twisted; unpaired sides
// become borders), which makes random handles, cross-caps and borders. Any such gluing is a
// 2-manifold; quad refinement (each n-gon -> n quads) then makes it a mesh without repeated vertices
// or doubled edges, and a few quads are split into triangles. Faces are reversed, vertices renumbered
// and corners rotated at random. Positions are random points in [-1, 1]^3.
RandomManifold random_manifold(std::mt19937& rng, const RandomManifoldOptions& options = {});

// The first seed of the property tests' runs: NOME_SEED from the environment (0 when unset), so that a run
// over other manifolds is `NOME_SEED=1000 nome_kernel_tests "[kernel]"`; failures print the seed.
unsigned seed_base();

}  // namespace nome::test
