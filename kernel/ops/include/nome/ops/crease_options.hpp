#pragma once

#include <optional>
#include <string_view>

namespace nome {

// How semi-sharp crease weights decay from level to level (OpenSubdiv's Sdc::Options::CreasingMethod).
enum class CreaseMethod {
  uniform,  // each weight drops by 1 per level (OpenSubdiv's default)
  chaikin,  // a child edge's weight also averages in the other semi-sharp edges at its end vertex
};

// The subdivision options that weigh on creases (OpenSubdiv's OBJ tags `t creasemethod`,
// `t smoothtriangles`).
struct CreaseOptions {
  CreaseMethod method = CreaseMethod::uniform;
  // OpenSubdiv's TRI_SUB_SMOOTH: the edge points beside a base triangle lean towards its face point.
  bool smooth_triangles = false;
  bool operator==(const CreaseOptions&) const = default;
};

// "uniform", "chaikin".
const char* to_string(CreaseMethod method);
// Either name; nothing for any other word.
std::optional<CreaseMethod> parse_crease_method(std::string_view word);

}  // namespace nome
