// A mesh source including its own layer's headers and support's, public and internal: this compiles.
#include "nome/buffer.hpp"
#include "nome/mesh/mesh.hpp"
#include "support/parallel_for.hpp"
#include "support/union_find.hpp"

namespace nome {

Index first_root(Index n) {
  UnionFind sets(n);
  return sets.find(0);
}

}  // namespace nome
