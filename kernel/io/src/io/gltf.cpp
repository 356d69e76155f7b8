#include "nome/io/gltf.hpp"

#include <array>
#include <cstring>
#include <map>
#include <sstream>
#include <unordered_map>

#include <tiny_gltf.h>

#include <glm/geometric.hpp>

#include "nome/atomic_file.hpp"
#include "nome/error.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/query/display_triangles.hpp"

namespace nome {
namespace {

using ColorKey = std::array<float, 3>;

// One primitive being written: its vertices (a mesh vertex once per side it shows) and triangles.
struct GltfPrimitiveData {
  std::vector<float> positions;
  std::vector<float> normals;
  std::vector<std::uint32_t> indices;
  std::unordered_map<std::uint64_t, std::uint32_t> written;  // (vertex, side) -> index
};

// Appends `bytes` to the buffer (4-byte aligned) as a view and an accessor over it; returns the accessor.
int add_gltf_accessor(tinygltf::Model& model, const void* bytes, std::size_t size, std::size_t count,
                      int component, int type, int target) {
  std::vector<unsigned char>& data = model.buffers[0].data;
  const std::size_t offset = data.size();
  data.resize(offset + size);
  std::memcpy(data.data() + offset, bytes, size);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = offset;
  view.byteLength = size;
  view.target = target;
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = int(model.bufferViews.size() - 1);
  accessor.componentType = component;
  accessor.count = count;
  accessor.type = type;
  model.accessors.push_back(accessor);
  return int(model.accessors.size() - 1);
}

void add_gltf_primitive(tinygltf::Model& model, const GltfPrimitiveData& p, const ColorKey& color) {
  tinygltf::Material material;
  material.pbrMetallicRoughness.baseColorFactor = {color[0], color[1], color[2], 1.0};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.8;
  material.doubleSided = true;  // a one-sided surface shows both of its sides
  model.materials.push_back(material);

  const std::size_t count = p.positions.size() / 3;
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = int(model.materials.size() - 1);
  const int position =
      add_gltf_accessor(model, p.positions.data(), p.positions.size() * 4, count,
                        TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
  std::vector<double> low(3, 1e300), high(3, -1e300);
  for (std::size_t i = 0; i < p.positions.size(); ++i) {
    low[i % 3] = std::min(low[i % 3], double(p.positions[i]));
    high[i % 3] = std::max(high[i % 3], double(p.positions[i]));
  }
  model.accessors[std::size_t(position)].minValues = low;
  model.accessors[std::size_t(position)].maxValues = high;
  primitive.attributes["POSITION"] = position;
  primitive.attributes["NORMAL"] =
      add_gltf_accessor(model, p.normals.data(), p.normals.size() * 4, count, TINYGLTF_COMPONENT_TYPE_FLOAT,
                        TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
  primitive.indices = add_gltf_accessor(model, p.indices.data(), p.indices.size() * 4, p.indices.size(),
                                        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                        TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  model.meshes[0].primitives.push_back(primitive);
}

// The unit normal a corner is drawn with: its vertex's, turned to its face's side; the face's own where
// the vertex normal vanished (the validator wants unit normals).
Vec3 gltf_corner_normal(const Mesh& mesh, const Normals& normals, Index corner) {
  const Vec3 n = double(mesh.corner_sign(corner)) * normals.vertices[mesh.corner_vertex(corner)];
  if (glm::length(n) > 0.5) return n;
  const Vec3 f = normals.faces[mesh.corner_face(corner)];
  return glm::length(f) > 0.5 ? f : Vec3(0.0, 0.0, 1.0);
}

tinygltf::Model gltf_model(const Mesh& mesh) {
  const DisplayTriangles triangles = display_triangles(mesh);
  const Normals normals = compute_normals(mesh);
  std::map<ColorKey, GltfPrimitiveData> by_color;
  for (Index t = 0; t < triangles.size(); ++t) {
    const Index f = triangles.faces[t];
    const Color c = written_face_color(face_color(mesh.face_attributes(), f));
    GltfPrimitiveData& p = by_color[{c.r, c.g, c.b}];
    for (Index corner : triangles.corners[t]) {
      const Index v = mesh.corner_vertex(corner);
      const Vec3 n = gltf_corner_normal(mesh, normals, corner);
      const std::uint64_t key = (std::uint64_t(v) << 1) | (mesh.corner_sign(corner) < 0 ? 1u : 0u);
      const auto [it, is_new] = p.written.emplace(key, std::uint32_t(p.positions.size() / 3));
      if (is_new)
        for (int k = 0; k < 3; ++k) {
          p.positions.push_back(float(mesh.position(v)[k]));
          p.normals.push_back(float(n[k]));
        }
      p.indices.push_back(it->second);
    }
  }
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "nome";
  model.buffers.resize(1);
  model.meshes.resize(1);
  for (const auto& [color, p] : by_color) add_gltf_primitive(model, p, color);
  tinygltf::Node node;
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
}

}  // namespace

void write_glb(const std::filesystem::path& path, const Mesh& mesh) {
  if (mesh.num_faces() == 0) throw IoError(path.string() + ": write_glb: the mesh has no faces");
  const tinygltf::Model model = gltf_model(mesh);
  write_file_atomically(path, [&](std::ostream& out) {
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, false, true))
      throw IoError(path.string() + ": write_glb: tinygltf could not write the file");
  });
}

}  // namespace nome
