#include "nome/ops/crease_options.hpp"

namespace nome {

const char* to_string(CreaseMethod method) {
  return method == CreaseMethod::chaikin ? "chaikin" : "uniform";
}

std::optional<CreaseMethod> parse_crease_method(std::string_view word) {
  for (CreaseMethod method : {CreaseMethod::uniform, CreaseMethod::chaikin})
    if (word == to_string(method)) return method;
  return std::nullopt;
}

}  // namespace nome
