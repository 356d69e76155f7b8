#pragma once

#include <filesystem>

#include "nome/io/obj_tags.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/mesh/polygon_soup.hpp"
#include "nome/mesh/quad_surface.hpp"
#include "nome/ops/offset_surface.hpp"

namespace nome {

// Reads a Wavefront OBJ through tinyobjloader, keeping polygons as polygons. Faces with fewer than 3
// vertices and vertex indices out of range are errors with `file:line:col`; other parse failures are
// reported with the line tinyobjloader names. OpenSubdiv's `t crease`, `t corner` and `t hole` lines
// become the soup's crease weights, corner weights and holes (see obj_tags.hpp). Throws IoError.
PolygonSoup read_obj(const std::filesystem::path& path);

// Writes positions with full double precision (`%.17g`), so reading the file back is exact; faces in
// their orientation. Vertex names become comments. Atomic (see write_file_atomically).
// OpenSubdiv's tag lines follow the faces: the mesh's crease and corner weights and holes, and `tags`.
void write_obj(const std::filesystem::path& path, const Mesh& mesh, const ObjSubdivisionTags& tags = {});
// The same bytes from the last level of a subdivision, without its Mesh (Pipeline::run_quads with
// creases: the surface's mesh would have no tags to write).
void write_obj(const std::filesystem::path& path, const QuadSurface& surface);
// The same bytes from an offset solid computed as it is written (as Pipeline::run_surface gives it, when
// the surface under it has no sharp edges to tag).
void write_obj(const std::filesystem::path& path, const OffsetSurface& solid);

}  // namespace nome
