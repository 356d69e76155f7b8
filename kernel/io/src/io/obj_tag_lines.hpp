#pragma once

// Internal to the OBJ reader: OpenSubdiv's tag lines, parsed.

#include <string>
#include <vector>

#include "nome/mesh/polygon_soup.hpp"

namespace nome {

struct ObjTag {
  int line = 0;
  std::string name;
  std::vector<long long> ints;
  std::vector<float> floats;
  std::vector<std::string> strings;
};

// `t NAME I/F/S` followed by I whole numbers, F numbers and S words. Throws IoError with
// file:line:col when the line does not hold what its counts say.
ObjTag parse_obj_tag(const std::string& file, int line, const std::string& text);

// The crease, corner and hole tags into the soup (its vertices and faces already read). Throws IoError
// with file:line for an index out of range.
void apply_obj_tags(const std::string& file, const std::vector<ObjTag>& tags, PolygonSoup& soup);

}  // namespace nome
