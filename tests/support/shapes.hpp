#pragma once

#include <random>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/polygon_soup.hpp"

// Small procedural surfaces shared by every test (pmp-library / geometry-central style).
namespace nome::test {

PolygonSoup tetrahedron();
PolygonSoup cube();
PolygonSoup grid(Index nx, Index ny);  // open quad grid in z = 0
PolygonSoup torus(Index u, Index v, double major = 1.0, double minor = 0.3);
PolygonSoup mobius_band(Index segments, Index width, Index twists = 1);  // width quads across
PolygonSoup klein_bottle(Index u, Index v);                              // figure-8 immersion
PolygonSoup projective_plane();  // cube with antipodal points identified: 4 vertices, 6 edges, 3 quads

// Reverses the corner order of each face with probability `fraction`.
PolygonSoup reverse_random_faces(PolygonSoup soup, double fraction, std::mt19937& rng);
// Applies a random permutation to the vertex ids.
PolygonSoup renumber_vertices(PolygonSoup soup, std::mt19937& rng);
// Rotates each face's corner list by a random amount (same polygon, same orientation).
PolygonSoup rotate_corners(PolygonSoup soup, std::mt19937& rng);
// Concatenates two soups as separate parts.
PolygonSoup disjoint_union(const PolygonSoup& a, const PolygonSoup& b);
// Cuts a soup into parts (face f goes to part part_of_face[f]), each with its own copies of the
// vertices it uses, names and colours carried along.
std::vector<PolygonSoup> split_faces(const PolygonSoup& soup, const std::vector<Index>& part_of_face);

}  // namespace nome::test
