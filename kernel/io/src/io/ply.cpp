#include "nome/io/ply.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
#include <ostream>

#include "nome/atomic_file.hpp"
#include "nome/error.hpp"
#include "nome/mesh/color_attribute.hpp"

namespace nome {
namespace {

template <typename T>
void put_little_endian(std::ostream& out, T value) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  out.write(reinterpret_cast<const char*>(bytes), sizeof(T));
}

// The face attributes a PLY face property can hold (numbers), under names PLY can spell.
struct PlyFaceProperty {
  std::string name;
  const AttributeColumn* column;
};

std::vector<PlyFaceProperty> ply_face_properties(const Attributes& faces) {
  std::vector<PlyFaceProperty> out;
  for (const Attributes::Entry& e : faces.entries()) {
    if (e.column->scalar_kind() == ScalarKind::none || e.name.empty() || e.name == "vertex_indices") continue;
    std::string name = e.name;
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    out.push_back({std::move(name), e.column.get()});
  }
  return out;
}

unsigned char ply_channel(float c) {
  return static_cast<unsigned char>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

void write_ply(const std::filesystem::path& path, const Mesh& mesh) {
  if (mesh.num_faces() == 0) throw IoError(path.string() + ": write_ply: the mesh has no faces");
  // A vertex once per colour around it: (vertex, colour) -> written index.
  using Key = std::pair<Index, std::array<unsigned char, 3>>;
  std::map<Key, std::uint32_t> written;
  std::vector<Key> order;
  std::vector<std::uint32_t> corners(mesh.num_corners());
  Index max_degree = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Color c = written_face_color(face_color(mesh.face_attributes(), f));
    const std::array<unsigned char, 3> rgb{ply_channel(c.r), ply_channel(c.g), ply_channel(c.b)};
    max_degree = std::max(max_degree, mesh.face_degree(f));
    for (Index corner = mesh.face_first_corner(f); corner < mesh.face_first_corner(f) + mesh.face_degree(f);
         ++corner) {
      const Key key{mesh.corner_vertex(corner), rgb};
      const auto [it, is_new] = written.emplace(key, std::uint32_t(order.size()));
      if (is_new) order.push_back(key);
      corners[corner] = it->second;
    }
  }
  const bool is_short_list = max_degree <= 255;
  const std::vector<PlyFaceProperty> properties = ply_face_properties(mesh.face_attributes());
  write_file_atomically(path, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\ncomment written by nome\nelement vertex " << order.size()
        << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face " << mesh.num_faces()
        << "\nproperty list " << (is_short_list ? "uchar" : "uint") << " uint vertex_indices\n";
    for (const PlyFaceProperty& p : properties)
      out << "property " << (p.column->scalar_kind() == ScalarKind::int32 ? "int " : "float ") << p.name
          << "\n";
    out << "end_header\n";
    for (const auto& [v, rgb] : order) {
      for (int k = 0; k < 3; ++k) put_little_endian(out, float(mesh.position(v)[k]));
      out.write(reinterpret_cast<const char*>(rgb.data()), 3);
    }
    for (Index f = 0; f < mesh.num_faces(); ++f) {
      if (is_short_list)
        put_little_endian(out, static_cast<unsigned char>(mesh.face_degree(f)));
      else
        put_little_endian(out, std::uint32_t(mesh.face_degree(f)));
      for (Index i = 0; i < mesh.face_degree(f); ++i)
        put_little_endian(out, corners[mesh.face_first_corner(f) + i]);
      for (const PlyFaceProperty& p : properties) {
        if (p.column->scalar_kind() == ScalarKind::int32)
          put_little_endian(out, std::int32_t(p.column->scalar(f)));
        else
          put_little_endian(out, float(p.column->scalar(f)));
      }
    }
  });
}

}  // namespace nome
