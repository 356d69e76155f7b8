#pragma once

#include <filesystem>
#include <string>

#include "nome/mesh/types.hpp"

namespace nome {

// Where face `face` of the polygons read_polygons made from `path` was written: `path:line:col` of its
// `f` line (OBJ) or `facet` keyword (ASCII STL), `path: byte N` of its record (binary STL); empty for other
// formats or a face past the file's end. Rescans the file: meant for error messages, not for every face.
std::string locate_face_in_file(const std::filesystem::path& path, Index face);

}  // namespace nome
