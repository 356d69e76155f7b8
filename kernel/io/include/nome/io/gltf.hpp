#pragma once

#include <filesystem>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/polygon_soup.hpp"

namespace nome {

// Writes the mesh as binary glTF 2.0 (.glb) with tinygltf: the triangles it is drawn with
// (display_triangles), one primitive and one material (its baseColorFactor) per face colour, smooth
// normals (the Möbius-aware vertex normals, each corner's turned to its face's side, so a vertex is
// written once per side and colour it shows). Atomic (write_file_atomically). Throws IoError.
void write_glb(const std::filesystem::path& path, const Mesh& mesh);

// The triangles of a .glb or .gltf file (every mesh primitive of mode TRIANGLES, node transforms not
// applied), corners at the same position welded into one vertex, each triangle coloured with its
// material's baseColorFactor when the file has materials. Throws IoError naming the file.
PolygonSoup read_gltf(const std::filesystem::path& path);

}  // namespace nome
