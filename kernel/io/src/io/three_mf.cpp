#include "nome/io/three_mf.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include "io/lib3mf_handle.hpp"
#include "nome/atomic_file.hpp"
#include "nome/error.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "nome/query/display_triangles.hpp"

namespace nome {
namespace {

using namespace NMR;

DWORD lib3mf_unit(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::millimeter:
      return MODELUNIT_MILLIMETER;
    case LengthUnit::centimeter:
      return MODELUNIT_CENTIMETER;
    case LengthUnit::inch:
      return MODELUNIT_INCH;
    case LengthUnit::meter:
      return MODELUNIT_METER;
  }
  return MODELUNIT_MILLIMETER;
}

BYTE color_byte(float channel) {
  return BYTE(std::lround(std::clamp(channel, 0.0f, 1.0f) * 255.0f));
}

// The vertices and triangles of one component, with each mesh vertex numbered where it is first used, and
// each triangle's colour or material.
struct ObjectArrays {
  std::vector<MODELMESHVERTEX> vertices;
  std::vector<MODELMESHTRIANGLE> triangles;
  std::vector<MODELMESHCOLOR_SRGB> colors;
  std::vector<DWORD> materials;  // into Materials::names
};

// Faces that carry numbers (a material, a region) are written as 3MF base materials: one per distinct set
// of numbers and colour, named "name=value;..." (read_3mf reads them back), shown in the face's colour.
struct Materials {
  std::vector<std::string> names;
  std::vector<Color> colors;
  std::map<std::pair<std::string, std::array<float, 3>>, DWORD> index;

  DWORD of(const Mesh& mesh, Index f) {
    std::string name;
    for (const Attributes::Entry& e : mesh.face_attributes().entries()) {
      if (e.column->scalar_kind() == ScalarKind::none) continue;
      name += (name.empty() ? "" : ";") + e.name + "=" + number_text(*e.column, f);
    }
    const Color c = written_face_color(face_color(mesh.face_attributes(), f));
    const auto [it, is_new] = index.emplace(std::pair(name, std::array{c.r, c.g, c.b}), DWORD(names.size()));
    if (is_new) {
      names.push_back(name);
      colors.push_back(c);
    }
    return it->second;
  }

  // Integers as integers; other numbers always with a point or an exponent, so that they read back as such.
  static std::string number_text(const AttributeColumn& column, Index f) {
    const double v = column.scalar(f);
    if (column.scalar_kind() == ScalarKind::int32) return std::to_string(std::int64_t(v));
    std::ostringstream text;
    text << std::setprecision(9) << v;
    std::string s = text.str();
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
  }
};

bool has_numbers(const Mesh& mesh) {
  const auto& entries = mesh.face_attributes().entries();
  return std::any_of(entries.begin(), entries.end(),
                     [](const Attributes::Entry& e) { return e.column->scalar_kind() != ScalarKind::none; });
}

std::vector<ObjectArrays> split_components(const Mesh& mesh, double scale, Materials& materials) {
  std::vector<ObjectArrays> objects(mesh.num_components());
  std::vector<DWORD> local(mesh.num_vertices(), DWORD(-1));
  const DisplayTriangles triangles = display_triangles(mesh);
  const Column<Color>* colors = find_colors(mesh.face_attributes());
  const bool has_materials = has_numbers(mesh);
  const bool has_colors = !has_materials && colors && !colors->values().empty();
  // A face's triangles come one after another: its material is named once.
  Index material_face = no_index;
  DWORD material = 0;
  for (Index t = 0; t < triangles.size(); ++t) {
    const Index f = triangles.faces[t];
    ObjectArrays& object = objects[mesh.face_component(f)];
    MODELMESHTRIANGLE triangle{};
    for (int i = 0; i < 3; ++i) {
      const Index v = mesh.corner_vertex(triangles.corners[t][i]);
      if (local[v] == DWORD(-1)) {
        local[v] = DWORD(object.vertices.size());
        const Vec3 p = mesh.position(v) * scale;
        object.vertices.push_back({{float(p.x), float(p.y), float(p.z)}});
      }
      triangle.m_nIndices[i] = local[v];
    }
    object.triangles.push_back(triangle);
    if (has_colors) {
      const Color c = written_face_color((*colors)[f]);
      object.colors.push_back({color_byte(c.r), color_byte(c.g), color_byte(c.b), 255});
    }
    if (has_materials) {
      if (f != material_face) material = materials.of(mesh, f);
      material_face = f;
      object.materials.push_back(material);
    }
  }
  return objects;
}

// The materials as one base material group; returns its resource id (0: none).
ModelResourceID add_materials(PLib3MFModel* model, const Materials& materials,
                              const std::filesystem::path& path) {
  if (materials.names.empty()) return 0;
  PLib3MFModelBaseMaterial* raw = nullptr;
  check_lib3mf(lib3mf_model_addbasematerialgroup(model, &raw), model, path, "adding materials");
  const Lib3mfHandle group(raw);
  for (size_t i = 0; i < materials.names.size(); ++i) {
    const Color& c = materials.colors[i];
    DWORD index = 0;
    check_lib3mf(lib3mf_basematerial_addmaterialutf8(raw, materials.names[i].c_str(), color_byte(c.r),
                                                     color_byte(c.g), color_byte(c.b), &index),
                 raw, path, "adding a material");
  }
  DWORD id = 0;
  check_lib3mf(lib3mf_resource_getresourceid(raw, &id), raw, path, "adding materials");
  return id;
}

void set_materials(PLib3MFModelMeshObject* object, ModelResourceID group, std::vector<DWORD>& materials,
                   const std::filesystem::path& path) {
  PLib3MFPropertyHandler* handler = nullptr;
  check_lib3mf(lib3mf_meshobject_createpropertyhandler(object, &handler), object, path, "materials");
  const Lib3mfHandle owned(handler);
  std::vector<ModelResourceID> groups(materials.size(), group);
  check_lib3mf(lib3mf_propertyhandler_setbasematerialarray(handler, groups.data(), materials.data()), handler,
               path, "materials");
  PLib3MFDefaultPropertyHandler* fallback = nullptr;
  check_lib3mf(lib3mf_object_createdefaultpropertyhandler(object, &fallback), object, path, "materials");
  const Lib3mfHandle owned_fallback(fallback);
  check_lib3mf(lib3mf_defaultpropertyhandler_setbasematerial(fallback, group, materials.front()), fallback,
               path, "materials");
}

void add_object(PLib3MFModel* model, ObjectArrays& arrays, ModelResourceID materials, Index number,
                const std::filesystem::path& path) {
  PLib3MFModelMeshObject* raw = nullptr;
  check_lib3mf(lib3mf_model_addmeshobject(model, &raw), model, path, "adding an object");
  const Lib3mfHandle object(raw);
  check_lib3mf(lib3mf_object_setnameutf8(raw, ("part " + std::to_string(number + 1)).c_str()), raw, path,
               "naming");
  check_lib3mf(lib3mf_meshobject_setgeometry(raw, arrays.vertices.data(), DWORD(arrays.vertices.size()),
                                             arrays.triangles.data(), DWORD(arrays.triangles.size())),
               raw, path, "setting the geometry");
  if (!arrays.colors.empty()) {
    PLib3MFPropertyHandler* handler = nullptr;
    check_lib3mf(lib3mf_meshobject_createpropertyhandler(raw, &handler), raw, path, "colouring");
    const Lib3mfHandle owned(handler);
    check_lib3mf(lib3mf_propertyhandler_setsinglecolorarray(handler, arrays.colors.data()), handler, path,
                 "colouring");
    // 3MF wants an object with coloured triangles to name a colour of its own as well.
    PLib3MFDefaultPropertyHandler* fallback = nullptr;
    check_lib3mf(lib3mf_object_createdefaultpropertyhandler(raw, &fallback), raw, path, "colouring");
    const Lib3mfHandle owned_fallback(fallback);
    MODELMESHCOLOR_SRGB first = arrays.colors.front();
    check_lib3mf(lib3mf_defaultpropertyhandler_setcolor(fallback, &first), fallback, path, "colouring");
  }
  if (!arrays.materials.empty()) set_materials(raw, materials, arrays.materials, path);
  PLib3MFModelBuildItem* item = nullptr;
  check_lib3mf(lib3mf_model_addbuilditem(model, raw, nullptr, &item), model, path, "adding a build item");
  lib3mf_release(item);
}

}  // namespace

void write_3mf(const std::filesystem::path& path, const Mesh& mesh, const ThreeMfOptions& options) {
  PLib3MFModel* raw = nullptr;
  check_lib3mf(lib3mf_createmodel(&raw), nullptr, path, "creating a model");
  const Lib3mfHandle model(raw);
  check_lib3mf(lib3mf_model_setunit(raw, lib3mf_unit(options.unit)), raw, path, "setting the unit");
  Materials materials;
  std::vector<ObjectArrays> objects = split_components(mesh, options.scale, materials);
  const ModelResourceID group = add_materials(raw, materials, path);
  for (Index i = 0; i < objects.size(); ++i) add_object(raw, objects[i], group, i, path);
  PLib3MFModelWriter* writer_raw = nullptr;
  check_lib3mf(lib3mf_model_querywriter(raw, "3mf", &writer_raw), raw, path, "making a writer");
  const Lib3mfHandle writer(writer_raw);
  ULONG64 size = 0;
  check_lib3mf(lib3mf_writer_getstreamsize(writer_raw, &size), writer_raw, path, "sizing the package");
  std::vector<BYTE> bytes(size);
  check_lib3mf(lib3mf_writer_writetobuffer(writer_raw, bytes.data(), size), writer_raw, path,
               "writing the package");
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  });
}

}  // namespace nome
