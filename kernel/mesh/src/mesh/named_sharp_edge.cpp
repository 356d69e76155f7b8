#include "nome/mesh/named_sharp_edge.hpp"

#include <charconv>

namespace nome {

std::string sharpness_text(float weight) {
  if (weight >= infinite_sharpness) return "infinite";
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, weight).ptr);
}

}  // namespace nome
