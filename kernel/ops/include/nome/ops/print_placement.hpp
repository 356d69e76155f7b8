#pragma once

#include <glm/mat4x4.hpp>

#include "nome/mesh/mesh.hpp"

namespace nome {

// Which dimension a print is scaled to.
enum class FitTarget { none, height, largest };
// What the print rests on: nothing (placed as modelled), the flattest large face, or a given face.
enum class RestOn { none, flattest, face };

// Print preparation: a target size in model units (the export unit: mm unless told otherwise) and the
// face the solid stands on.
struct PrintPlacementOptions {
  FitTarget fit = FitTarget::none;
  double fit_size = 0.0;  // positive and finite when fit is not none
  RestOn rest = RestOn::none;
  Index rest_face = no_index;  // the face when rest is RestOn::face

  bool is_identity() const { return fit == FitTarget::none && rest == RestOn::none; }
  bool operator==(const PrintPlacementOptions&) const = default;
};

// Where a mesh goes for printing: x' = transform * x. With a rest face its outward normal points down
// (-z) and the lowest point lies at z = 0; with a fit the solid's height (or largest dimension) after
// the rotation is fit_size.
struct PrintPlacement {
  glm::dmat4 transform{1.0};
  Index rest_face = no_index;  // the face it stands on, if any
  Vec3 rest_normal{0.0};       // that face's outward unit normal before the placement
  double scale = 1.0;
};

// The face a solid stands on best: faces are grouped into planes (normals within 1 degree, the same
// plane within 1e-6 of the mesh's size); among the planes that touch the convex hull (nothing of the
// mesh lies beyond them) the one of largest total area wins, and its largest face stands for it.
// Throws InvalidInputError for a mesh without a face of positive area.
Index flattest_face(const Mesh& mesh);

// The rotation, scale and translation of print preparation. Throws InvalidInputError (message
// prefixed "print_placement:") for an unknown rest face, a degenerate rest face, a fit size that is
// not positive and finite, or an empty or flat mesh that cannot be scaled.
PrintPlacement print_placement(const Mesh& mesh, const PrintPlacementOptions& options);

// The mesh placed for printing (a copy; `mesh` is not changed).
Mesh placed_for_print(const Mesh& mesh, const PrintPlacementOptions& options);

}  // namespace nome
