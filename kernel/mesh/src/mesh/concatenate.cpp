#include "nome/mesh/concatenate.hpp"

namespace nome {

PolygonSoup concatenate(std::span<const Mesh> parts) {
  PolygonSoup soup;
  for (const Mesh& part : parts) append_soup(soup, to_soup(part));
  return soup;
}

}  // namespace nome
