#include "nome/io/three_mf.hpp"

namespace nome {

std::optional<LengthUnit> parse_length_unit(std::string_view name) {
  if (name == "mm") return LengthUnit::millimeter;
  if (name == "cm") return LengthUnit::centimeter;
  if (name == "in") return LengthUnit::inch;
  if (name == "m") return LengthUnit::meter;
  return std::nullopt;
}

const char* to_string(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::millimeter:
      return "mm";
    case LengthUnit::centimeter:
      return "cm";
    case LengthUnit::inch:
      return "in";
    case LengthUnit::meter:
      return "m";
  }
  return "mm";
}

}  // namespace nome
