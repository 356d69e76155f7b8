#include "nome/io/read_polygons.hpp"

#include <algorithm>
#include <cctype>

#include "nome/error.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/stl.hpp"

namespace nome {

PolygonSoup read_polygons(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".obj") return read_obj(path);
  if (ext == ".stl") return read_stl(path);
  throw IoError(path.string() + ": unknown file type '" + ext + "' (expected .obj or .stl)");
}

}  // namespace nome
