#pragma once

#include <filesystem>

#include "nome/mesh/polygon_soup.hpp"

namespace nome {

// Reads a polygon file by its extension: .obj, .stl, .sif, .glb, .gltf or .ply (case-insensitive). Throws
// IoError for an unknown extension, a malformed file or a file without faces.
PolygonSoup read_polygons(const std::filesystem::path& path);

}  // namespace nome
