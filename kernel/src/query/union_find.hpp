#pragma once

#include <numeric>
#include <vector>

#include "nome/mesh/types.hpp"

namespace nome {

// Disjoint sets with path halving: how the print check groups findings into places.
class UnionFind {
 public:
  explicit UnionFind(Index n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), Index(0)); }
  Index find(Index x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(Index a, Index b) { parent_[find(a)] = find(b); }

 private:
  std::vector<Index> parent_;
};

}  // namespace nome
