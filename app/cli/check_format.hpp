#pragma once

#include <string>

#include "nome/query/print_check.hpp"

namespace nome::cli {

// How many places `nome check` and `nome export` list.
inline constexpr std::size_t listed_places = 10;

// The verdict, the counts and the worst places, for people.
std::string check_text(const PrintCheck& check);
// One line for `nome export`: the verdict and the counts.
std::string check_summary(const PrintCheck& check);
// The same as one JSON object: printable, offset, min_wall, fold_overs, crossing_pairs, crossing_curves,
// near_misses, places[{kind, position, face, other_face, distance, size}].
std::string check_json(const PrintCheck& check);

}  // namespace nome::cli
