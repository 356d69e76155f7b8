#include "nome/io/read_polygons.hpp"

#include <algorithm>
#include <cctype>

#include "nome/error.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/sif.hpp"
#include "nome/io/stl.hpp"

namespace nome {

PolygonSoup read_polygons(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".obj" && ext != ".stl" && ext != ".sif")
    throw IoError(path.string() + ": unknown file type '" + ext + "' (expected .obj, .stl or .sif)");
  PolygonSoup soup = ext == ".obj" ? read_obj(path) : ext == ".stl" ? read_stl(path) : read_sif(path);
  if (soup.num_faces() == 0) throw IoError(path.string() + ": no faces: there is no surface in this file");
  return soup;
}

}  // namespace nome
