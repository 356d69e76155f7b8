#pragma once

#include <string>

#include "nome/mesh/types.hpp"

namespace nome {

// An edge given by its two vertices' names (the smaller name first where edits keep them), with its crease
// weight: OpenSubdiv's sharpness, from infinite_sharpness up infinitely sharp.
struct NamedSharpEdge {
  std::string a, b;
  float weight = infinite_sharpness;

  bool operator==(const NamedSharpEdge&) const = default;
};

// A weight as users read and write it: the shortest decimal that reads back as it ("2.5"), or "infinite"
// from infinite_sharpness up.
std::string sharpness_text(float weight);

}  // namespace nome
