#pragma once

#include <filesystem>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/polygon_soup.hpp"
#include "nome/mesh/quad_surface.hpp"
#include "nome/ops/offset_surface.hpp"
#include "nome/progress.hpp"

namespace nome {

enum class StlFormat { binary, ascii };

// Writes each polygon as a triangle fan from its first corner, facet normal from the polygon's
// orientation (Newell). Atomic (see write_file_atomically).
void write_stl(const std::filesystem::path& path, const Mesh& mesh, StlFormat format = StlFormat::binary,
               const Progress& progress = {});
// The same bytes from the last level of a subdivision, without its Mesh (Pipeline::run_quads).
void write_stl(const std::filesystem::path& path, const QuadSurface& surface,
               StlFormat format = StlFormat::binary, const Progress& progress = {});
// The same bytes from an offset solid computed as it is written (as Pipeline::run_surface gives it).
void write_stl(const std::filesystem::path& path, const OffsetSurface& solid,
               StlFormat format = StlFormat::binary, const Progress& progress = {});

}  // namespace nome

namespace nome {

// Reads binary or ASCII STL; corners with bit-identical coordinates become one vertex, so a closed
// solid written by write_stl reads back as a closed mesh. Throws IoError with the line (ASCII) or the
// byte offset (binary) of a malformed record.
PolygonSoup read_stl(const std::filesystem::path& path);

}  // namespace nome
