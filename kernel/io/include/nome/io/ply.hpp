#pragma once

#include <filesystem>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/polygon_soup.hpp"

namespace nome {

// Writes the mesh as binary little-endian PLY: its polygons as they are (no triangulation), float
// positions and 8-bit vertex colours. A vertex is written once per face colour around it, so that every
// face's corners carry its colour. Atomic (write_file_atomically). Throws IoError.
void write_ply(const std::filesystem::path& path, const Mesh& mesh);

// A PLY file (ascii, binary_little_endian or binary_big_endian) with vertices x y z (float or double),
// optional red green blue (uchar or float) and faces as a vertex index list. Vertices at the same position
// become one; each face takes the colour of its first corner when the file has vertex colours. Throws
// IoError `path:line: ...` (ascii) or `path: ...` for a malformed file.
PolygonSoup read_ply(const std::filesystem::path& path);

}  // namespace nome
