#pragma once

#include "nome/mesh/mesh.hpp"

namespace nome::test {

// Every array of the two meshes compared (Catch checks, one per array): what a rebuild or a fast path must
// reproduce exactly. `a` must also be valid.
void check_same_mesh(const Mesh& a, const Mesh& b);

}  // namespace nome::test
