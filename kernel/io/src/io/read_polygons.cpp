#include "nome/io/read_polygons.hpp"

#include "nome/error.hpp"
#include "nome/io/file_extension.hpp"
#include "nome/io/gltf.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/ply.hpp"
#include "nome/io/sif.hpp"
#include "nome/io/stl.hpp"

namespace nome {

PolygonSoup read_polygons(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  PolygonSoup soup;
  if (ext == ".obj")
    soup = read_obj(path);
  else if (ext == ".stl")
    soup = read_stl(path);
  else if (ext == ".sif")
    soup = read_sif(path);
  else if (ext == ".glb" || ext == ".gltf")
    soup = read_gltf(path);
  else if (ext == ".ply")
    soup = read_ply(path);
  else
    throw IoError(path.string() + ": unknown file type '" + ext +
                  "' (expected .obj, .stl, .sif, .glb, .gltf or .ply)");
  if (soup.num_faces() == 0) throw IoError(path.string() + ": no faces: there is no surface in this file");
  return soup;
}

}  // namespace nome
