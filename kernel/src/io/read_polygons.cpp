#include "nome/io/read_polygons.hpp"

#include "nome/error.hpp"
#include "nome/io/file_extension.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/sif.hpp"
#include "nome/io/stl.hpp"

namespace nome {

PolygonSoup read_polygons(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext != ".obj" && ext != ".stl" && ext != ".sif")
    throw IoError(path.string() + ": unknown file type '" + ext + "' (expected .obj, .stl or .sif)");
  PolygonSoup soup = ext == ".obj" ? read_obj(path) : ext == ".stl" ? read_stl(path) : read_sif(path);
  if (soup.num_faces() == 0) throw IoError(path.string() + ": no faces: there is no surface in this file");
  return soup;
}

}  // namespace nome
