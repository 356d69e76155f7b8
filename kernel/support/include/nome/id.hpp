#pragma once

#include <compare>
#include <cstddef>
#include <functional>

#include "nome/index.hpp"

namespace nome {

// A 4-byte id of one kind of element: a parameter id is not a placement id, and neither becomes the other
// or an integer without saying so (the explicit constructor, index()). The default id names no element.
// Arrays stay indexed by plain integers inside tight loops; ids are what public functions take and give.
template <class Kind>
class Id {
 public:
  constexpr Id() = default;
  constexpr explicit Id(Index index) : index_(index) {}

  constexpr Index index() const { return index_; }
  constexpr bool is_valid() const { return index_ != no_index; }
  constexpr auto operator<=>(const Id&) const = default;

 private:
  Index index_ = no_index;
};

}  // namespace nome

template <class Kind>
struct std::hash<nome::Id<Kind>> {
  std::size_t operator()(nome::Id<Kind> id) const noexcept { return std::hash<nome::Index>()(id.index()); }
};
