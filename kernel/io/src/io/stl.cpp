#include "nome/io/stl.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ostream>

#include <glm/geometric.hpp>

#include "io/surface_views.hpp"
#include "mesh/normal_passes.hpp"
#include "nome/atomic_file.hpp"

namespace nome {
namespace {

Vec3 unit_or_zero(const Vec3& n) {
  const double len = glm::length(n);
  return len > 0.0 ? n / len : Vec3(0.0);
}

constexpr std::size_t header_bytes = 84, record_bytes = 50;

char* put_vec(char* at, const Vec3& v) {
  const float f[3] = {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
  std::memcpy(at, f, 12);  // STL is little-endian, as is every machine we target
  return at + 12;
}

void put_ascii_facet(std::ostream& out, const Vec3& n, const Vec3 (&corners)[3]) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "  facet normal %.9g %.9g %.9g\n    outer loop\n", n.x, n.y, n.z);
  out << buf;
  for (const Vec3& p : corners) {
    std::snprintf(buf, sizeof buf, "      vertex %.9g %.9g %.9g\n", p.x, p.y, p.z);
    out << buf;
  }
  out << "    endloop\n  endfacet\n";
}

// polygon_area_normal of a face of any surface, in the same order of operations.
template <class Surface>
Vec3 area_normal(const Surface& surface, std::span<const Index> vertices) {
  Vec3 n(0.0);
  Vec3 a = surface.position(vertices.back());
  for (Index v : vertices) {
    const Vec3 b = surface.position(v);
    n += normal_passes::newell_term(a, b);
    a = b;
  }
  return n;
}

// Any surface with num_faces(), face_degree(f), face_vertices(f) and position(v) (surface_views.hpp).
// Binary records go straight into the file's blocks; ASCII goes through a stream over them.
template <class Surface>
void write_stl_surface(FileBlocks& file, const Surface& surface, StlFormat format, const Progress& progress) {
  std::uint32_t triangles = 0;
  for (Index f = 0; f < surface.num_faces(); ++f) triangles += surface.face_degree(f) - 2;
  std::ostream ascii(&file);
  if (format == StlFormat::binary) {
    char* at = file.room(header_bytes);
    std::memset(at, 0, header_bytes);
    std::snprintf(at, 80, "nome binary STL");
    std::memcpy(at + 80, &triangles, 4);
    file.commit(at + header_bytes);
  } else {
    ascii << "solid nome\n";
  }
  for (Index f = 0; f < surface.num_faces(); ++f) {
    if (f % (Index(1) << 16) == 0) progress("writing STL", double(f) / surface.num_faces());
    const auto vs = surface.face_vertices(f);
    const Vec3 n = unit_or_zero(area_normal(surface, vs));
    for (size_t i = 1; i + 1 < vs.size(); ++i) {
      const Vec3 corners[3] = {surface.position(vs[0]), surface.position(vs[i]), surface.position(vs[i + 1])};
      if (format == StlFormat::ascii) {
        put_ascii_facet(ascii, n, corners);
        continue;
      }
      char* at = put_vec(file.room(record_bytes), n);
      for (const Vec3& p : corners) at = put_vec(at, p);
      *at++ = 0;
      *at++ = 0;
      file.commit(at);
    }
  }
  if (format == StlFormat::ascii) ascii << "endsolid nome\n";
}

}  // namespace

void write_stl(const std::filesystem::path& path, const Mesh& mesh, StlFormat format,
               const Progress& progress) {
  write_file_in_blocks(path,
                       [&](FileBlocks& out) { write_stl_surface(out, MeshSurface(mesh), format, progress); });
}

void write_stl(const std::filesystem::path& path, const QuadSurface& surface, StlFormat format,
               const Progress& progress) {
  write_file_in_blocks(path, [&](FileBlocks& out) { write_stl_surface(out, surface, format, progress); });
}

void write_stl(const std::filesystem::path& path, const OffsetSurface& solid, StlFormat format,
               const Progress& progress) {
  write_file_in_blocks(path, [&](FileBlocks& out) { write_stl_surface(out, solid, format, progress); });
}

}  // namespace nome
