#include "nome/io/stl.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>

#include <glm/geometric.hpp>

#include "nome/atomic_file.hpp"
#include "nome/mesh/normals.hpp"

namespace nome {
namespace {

void put_float(std::ostream& out, double value) {
  const float f = static_cast<float>(value);
  char bytes[4];
  std::memcpy(bytes, &f, 4);  // STL is little-endian, as is every machine we target
  out.write(bytes, 4);
}

Vec3 unit_or_zero(const Vec3& n) {
  const double len = glm::length(n);
  return len > 0.0 ? n / len : Vec3(0.0);
}

}  // namespace

void write_stl(const std::filesystem::path& path, const Mesh& mesh, StlFormat format,
               const Progress& progress) {
  write_file_atomically(path, [&](std::ostream& out) {
    std::uint32_t triangles = 0;
    for (Index f = 0; f < mesh.num_faces(); ++f) triangles += mesh.face_degree(f) - 2;
    if (format == StlFormat::binary) {
      char header[80] = {};
      std::snprintf(header, sizeof header, "nome binary STL");
      out.write(header, 80);
      out.write(reinterpret_cast<const char*>(&triangles), 4);
    } else {
      out << "solid nome\n";
    }
    char buf[160];
    for (Index f = 0; f < mesh.num_faces(); ++f) {
      if (f % (Index(1) << 16) == 0) progress("writing STL", double(f) / mesh.num_faces());
      const Vec3 n = unit_or_zero(face_area_normal(mesh, f));
      const auto vs = mesh.face_vertices(f);
      for (size_t i = 1; i + 1 < vs.size(); ++i) {
        const Vec3* corners[3] = {&mesh.position(vs[0]), &mesh.position(vs[i]), &mesh.position(vs[i + 1])};
        if (format == StlFormat::binary) {
          for (int k = 0; k < 3; ++k) put_float(out, n[k]);
          for (const Vec3* p : corners)
            for (int k = 0; k < 3; ++k) put_float(out, (*p)[k]);
          out.write("\0\0", 2);
        } else {
          std::snprintf(buf, sizeof buf, "  facet normal %.9g %.9g %.9g\n    outer loop\n", n.x, n.y, n.z);
          out << buf;
          for (const Vec3* p : corners) {
            std::snprintf(buf, sizeof buf, "      vertex %.9g %.9g %.9g\n", p->x, p->y, p->z);
            out << buf;
          }
          out << "    endloop\n  endfacet\n";
        }
      }
    }
    if (format == StlFormat::ascii) out << "endsolid nome\n";
  });
}

}  // namespace nome
