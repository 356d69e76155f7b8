#include <charconv>
#include <ostream>

#include "io/surface_views.hpp"
#include "nome/atomic_file.hpp"
#include "nome/io/obj.hpp"
#include "nome/number_text.hpp"

namespace nome {
namespace {

// Room for a vertex line: "v", three numbers of up to 32 bytes, spaces, newline.
constexpr std::size_t longest_line = 104;

// Positions as printf's %.17g.
char* put_double(char* at, double value) {
  return general_to_chars(at, at + 32, value, 17).ptr;
}

char* put_index(char* at, Index value) {
  return std::to_chars(at, at + 16, value).ptr;
}

// Any surface with num_vertices(), num_faces(), face_vertices(f) and position(v) (surface_views.hpp).
template <class Surface>
void write_obj_surface(FileBlocks& file, const Surface& surface) {
  std::ostream(&file) << "# written by nome: " << surface.num_vertices() << " vertices, "
                      << surface.num_faces() << " faces\n";
  for (Index v = 0; v < surface.num_vertices(); ++v) {
    const Vec3 p = surface.position(v);
    char* at = file.room(longest_line);
    *at++ = 'v';
    for (int k = 0; k < 3; ++k) {
      *at++ = ' ';
      at = put_double(at, p[k]);
    }
    *at++ = '\n';
    file.commit(at);
  }
  // Each corner " index" takes at most 11 bytes; a face of more corners than fit is written in pieces.
  for (Index f = 0; f < surface.num_faces(); ++f) {
    char* at = file.room(2);
    *at++ = 'f';
    for (Index v : surface.face_vertices(f)) {
      file.commit(at);
      at = file.room(12);
      *at++ = ' ';
      at = put_index(at, v + 1);
    }
    *at++ = '\n';
    file.commit(at);
  }
}

}  // namespace

void write_obj(const std::filesystem::path& path, const Mesh& mesh, const ObjSubdivisionTags& tags) {
  write_file_in_blocks(path, [&](FileBlocks& file) {
    if (mesh.vertex_origins().empty())
      write_obj_surface(file, MeshSurface(mesh));
    else
      write_obj_surface(file, JoinedMeshSurface(mesh));
    std::ostream out(&file);
    write_obj_tags(out, mesh, tags);
  });
}

void write_obj(const std::filesystem::path& path, const QuadSurface& surface) {
  write_file_in_blocks(path, [&](FileBlocks& file) { write_obj_surface(file, surface); });
}

void write_obj(const std::filesystem::path& path, const OffsetSurface& solid) {
  write_file_in_blocks(path, [&](FileBlocks& file) { write_obj_surface(file, solid); });
}

}  // namespace nome
