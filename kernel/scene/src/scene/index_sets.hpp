#pragma once

#include <algorithm>
#include <vector>

#include "nome/mesh/polygon_soup.hpp"

namespace nome::scene {

// Sorts the ids and drops repeats: the set of sliders a placement reads, or of instances to rebuild.
template <class IdType>
void sort_unique(std::vector<IdType>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace nome::scene
