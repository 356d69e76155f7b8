// Reading glTF 2.0 (.glb, .gltf) with tinygltf: the triangles of every primitive, welded by position.
#include <array>
#include <cstring>
#include <map>
#include <string>

#include <tiny_gltf.h>

#include "nome/error.hpp"
#include "nome/io/gltf.hpp"
#include "nome/mesh/color_attribute.hpp"

namespace nome {
namespace {

// The bytes of element i of an accessor, checked against its buffer.
const unsigned char* gltf_element(const tinygltf::Model& model, const tinygltf::Accessor& accessor,
                                  std::size_t i, const std::string& file) {
  if (accessor.bufferView < 0 || std::size_t(accessor.bufferView) >= model.bufferViews.size())
    throw IoError(file + ": an accessor without a buffer view");
  const tinygltf::BufferView& view = model.bufferViews[std::size_t(accessor.bufferView)];
  const tinygltf::Buffer& buffer = model.buffers.at(std::size_t(view.buffer));
  const int stride = accessor.ByteStride(view);
  const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(accessor.componentType)) *
                   tinygltf::GetNumComponentsInType(std::uint32_t(accessor.type));
  if (stride <= 0 || size <= 0) throw IoError(file + ": an accessor of an unknown type");
  const std::size_t at = view.byteOffset + accessor.byteOffset + i * std::size_t(stride);
  if (at + std::size_t(size) > buffer.data.size() ||
      at + std::size_t(size) > view.byteOffset + view.byteLength)
    throw IoError(file + ": an accessor runs past its buffer");
  return buffer.data.data() + at;
}

std::uint32_t gltf_index(const tinygltf::Model& model, const tinygltf::Accessor& accessor, std::size_t i,
                         const std::string& file) {
  const unsigned char* p = gltf_element(model, accessor, i, file);
  switch (accessor.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
  throw IoError(file + ": indices must be unsigned byte, short or int");
}

// Adds one TRIANGLES primitive's triangles to the soup; `welded` maps positions to soup vertices.
void read_gltf_primitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                         std::map<std::array<float, 3>, Index>& welded, PolygonSoup& soup,
                         const std::string& file) {
  const auto position = primitive.attributes.find("POSITION");
  if (position == primitive.attributes.end()) throw IoError(file + ": a primitive without positions");
  const tinygltf::Accessor& positions = model.accessors.at(std::size_t(position->second));
  if (positions.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || positions.type != TINYGLTF_TYPE_VEC3)
    throw IoError(file + ": positions must be float VEC3");
  std::vector<Index> vertex(positions.count);
  for (std::size_t i = 0; i < positions.count; ++i) {
    std::array<float, 3> p;
    std::memcpy(p.data(), gltf_element(model, positions, i, file), 12);
    const auto [it, is_new] = welded.emplace(p, soup.num_vertices());
    if (is_new) soup.add_vertex(Vec3(p[0], p[1], p[2]));
    vertex[i] = it->second;
  }
  const bool is_indexed = primitive.indices >= 0;
  const tinygltf::Accessor* indices =
      is_indexed ? &model.accessors.at(std::size_t(primitive.indices)) : nullptr;
  const std::size_t corners = is_indexed ? indices->count : positions.count;
  Color color = no_face_color;
  if (primitive.material >= 0) {
    const auto& factor =
        model.materials.at(std::size_t(primitive.material)).pbrMetallicRoughness.baseColorFactor;
    if (factor.size() >= 3) color = Color(float(factor[0]), float(factor[1]), float(factor[2]));
  }
  for (std::size_t t = 0; t + 2 < corners; t += 3) {
    std::array<Index, 3> face;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t i = is_indexed ? gltf_index(model, *indices, t + k, file) : t + k;
      if (i >= vertex.size()) throw IoError(file + ": an index past the primitive's vertices");
      face[k] = vertex[i];
    }
    soup.add_face(face);
    if (!model.materials.empty()) add_colors(soup.face_attributes).set(soup.num_faces() - 1, color);
  }
}

}  // namespace

PolygonSoup read_gltf(const std::filesystem::path& path) {
  const std::string file = path.string();
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  const bool is_binary = path.extension() == ".glb" || path.extension() == ".GLB";
  const bool is_read = is_binary ? loader.LoadBinaryFromFile(&model, &error, &warning, file)
                                 : loader.LoadASCIIFromFile(&model, &error, &warning, file);
  if (!is_read) throw IoError(file + ": " + (error.empty() ? "not a glTF file" : error));
  PolygonSoup soup;
  std::map<std::array<float, 3>, Index> welded;
  for (const tinygltf::Mesh& mesh : model.meshes)
    for (const tinygltf::Primitive& primitive : mesh.primitives)
      if (primitive.mode == TINYGLTF_MODE_TRIANGLES || primitive.mode == -1)
        read_gltf_primitive(model, primitive, welded, soup, file);
  return soup;
}

}  // namespace nome
