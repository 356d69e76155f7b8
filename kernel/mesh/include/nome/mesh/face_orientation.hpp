#pragma once

#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {

// An orientation sign per face, relative to the first face of its component: a walk from face to face
// across edges that flips the sign at every Möbius edge. A component is orientable when no face is
// reached with both signs; then flipping its faces of sign -1 orients it consistently.
struct FaceOrientation {
  std::vector<signed char> face_signs;     // +1 or -1
  std::vector<char> component_orientable;  // per component of the mesh
};

FaceOrientation face_orientation(const Mesh& mesh);

}  // namespace nome
