#include <charconv>
#include <vector>

#include "nome/atomic_file.hpp"
#include "nome/io/obj.hpp"

namespace nome {
namespace {

// Lines gathered into blocks of about this many bytes, one stream write each.
constexpr std::size_t obj_block = std::size_t(1) << 20;
constexpr std::size_t longest_line = 96;

// Positions as printf's %.17g (to_chars with a precision is specified to match it), integers in decimal.
char* put_double(char* at, double value) {
  return std::to_chars(at, at + 32, value, std::chars_format::general, 17).ptr;
}
char* put_index(char* at, Index value) {
  return std::to_chars(at, at + 16, value).ptr;
}

class BlockWriter {
 public:
  explicit BlockWriter(std::ostream& out) : out_(out), block_(obj_block + longest_line), at_(block_.data()) {}
  ~BlockWriter() { flush(); }
  // Room for one line of up to longest_line bytes (a face of more corners flushes between corners).
  char*& at() {
    if (size_t(at_ - block_.data()) >= obj_block) flush();
    return at_;
  }
  void flush() {
    out_.write(block_.data(), at_ - block_.data());
    at_ = block_.data();
  }

 private:
  std::ostream& out_;
  std::vector<char> block_;
  char* at_;
};

// Any surface with num_vertices(), num_faces(), face_vertices(f) and position(v): a Mesh or a QuadSurface.
template <class Surface>
void write_obj_surface(std::ostream& out, const Surface& surface) {
  out << "# written by nome: " << surface.num_vertices() << " vertices, " << surface.num_faces()
      << " faces\n";
  BlockWriter writer(out);
  for (Index v = 0; v < surface.num_vertices(); ++v) {
    const Vec3& p = surface.position(v);
    char*& at = writer.at();
    *at++ = 'v';
    for (int k = 0; k < 3; ++k) {
      *at++ = ' ';
      at = put_double(at, p[k]);
    }
    *at++ = '\n';
  }
  for (Index f = 0; f < surface.num_faces(); ++f) {
    *writer.at()++ = 'f';
    for (Index v : surface.face_vertices(f)) {
      char*& at = writer.at();
      *at++ = ' ';
      at = put_index(at, v + 1);
    }
    *writer.at()++ = '\n';
  }
}

}  // namespace

void write_obj(const std::filesystem::path& path, const Mesh& mesh, const ObjSubdivisionTags& tags) {
  write_file_atomically(path, [&](std::ostream& out) {
    write_obj_surface(out, mesh);
    write_obj_tags(out, mesh, tags);
  });
}

void write_obj(const std::filesystem::path& path, const QuadSurface& surface) {
  write_file_atomically(path, [&](std::ostream& out) { write_obj_surface(out, surface); });
}

}  // namespace nome
