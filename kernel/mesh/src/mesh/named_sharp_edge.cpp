#include "nome/mesh/named_sharp_edge.hpp"

#include "nome/number_text.hpp"

namespace nome {

std::string sharpness_text(float weight) {
  if (weight >= infinite_sharpness) return "infinite";
  char text[32];
  return std::string(text, shortest_to_chars(text, text + sizeof text, weight).ptr);
}

}  // namespace nome
