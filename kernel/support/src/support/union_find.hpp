#pragma once

#include <numeric>
#include <vector>

#include "nome/index.hpp"

namespace nome {

// Disjoint sets with path halving: how the print check groups findings into places, and a mesh's faces
// into components.
class UnionFind {
 public:
  explicit UnionFind(Index n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), Index(0)); }
  Index find(Index x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  // The larger root goes under the smaller: sets grown in index order (faces of a grid) stay shallow.
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a < b)
      parent_[b] = a;
    else
      parent_[a] = b;
  }

 private:
  std::vector<Index> parent_;
};

}  // namespace nome
