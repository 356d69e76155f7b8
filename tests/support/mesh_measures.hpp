#pragma once

#include "nome/mesh/mesh.hpp"

namespace nome::test {

// Signed volume by the divergence theorem over a fan triangulation of each face: positive when a closed
// surface's faces are oriented outward.
double signed_volume(const Mesh& mesh);

// The mean of face f's corners.
Vec3 face_centre(const PolygonSoup& soup, Index f);

}  // namespace nome::test
