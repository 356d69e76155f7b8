#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "io/lib3mf_handle.hpp"
#include "nome/error.hpp"
#include "nome/io/three_mf.hpp"

namespace nome {
namespace {

using namespace NMR;

LengthUnit unit_of(DWORD unit) {
  switch (unit) {
    case MODELUNIT_CENTIMETER:
      return LengthUnit::centimeter;
    case MODELUNIT_INCH:
      return LengthUnit::inch;
    case MODELUNIT_METER:
      return LengthUnit::meter;
    default:
      return LengthUnit::millimeter;
  }
}

std::string material_name(PLib3MFModelBaseMaterial* group, DWORD index, const std::filesystem::path& path) {
  ULONG needed = 0;
  check_lib3mf(lib3mf_basematerial_getnameutf8(group, index, nullptr, 0, &needed), group, path, "materials");
  std::string name(needed + 1, '\0');
  check_lib3mf(lib3mf_basematerial_getnameutf8(group, index, name.data(), ULONG(name.size()), &needed), group,
               path, "materials");
  name.resize(std::strlen(name.c_str()));
  return name;
}

// "name=value;..." as write_3mf names a material: whole numbers become integers, others floats; a name
// of another form (another program's "PLA") carries no numbers.
void add_material_numbers(const std::string& name, Index triangle, Attributes& numbers) {
  std::size_t start = 0;
  while (start < name.size()) {
    const std::size_t end = std::min(name.find(';', start), name.size());
    const std::string pair = name.substr(start, end - start);
    start = end + 1;
    const std::size_t equals = pair.find('=');
    if (equals == std::string::npos || equals == 0) continue;
    const std::string key = pair.substr(0, equals), text = pair.substr(equals + 1);
    char* rest = nullptr;
    if (text.find_first_of(".eEn") == std::string::npos) {
      const long v = std::strtol(text.c_str(), &rest, 10);
      if (rest != text.c_str() && *rest == '\0')
        numbers.add<std::int32_t>(key, 0).set(triangle, std::int32_t(v));
    } else {
      const float v = std::strtof(text.c_str(), &rest);
      if (rest != text.c_str() && *rest == '\0') numbers.add<float>(key, 0.0f).set(triangle, v);
    }
  }
}

// A triangle's base material: its display colour, and the numbers its name holds.
void read_material(PLib3MFModel* model, PLib3MFPropertyHandler* handler, DWORD t,
                   ThreeMfModel::Object& object, const std::filesystem::path& path) {
  DWORD group_id = 0, index = 0;
  check_lib3mf(lib3mf_propertyhandler_getbasematerial(handler, t, &group_id, &index), handler, path,
               "materials");
  PLib3MFModelBaseMaterial* group = nullptr;
  check_lib3mf(lib3mf_model_getbasematerialbyid(model, group_id, &group), model, path, "materials");
  const Lib3mfHandle owned(group);
  BYTE r = 0, g = 0, b = 0, a = 0;
  check_lib3mf(lib3mf_basematerial_getdisplaycolor(group, index, &r, &g, &b, &a), group, path, "materials");
  object.colors[t] = Color(r / 255.0f, g / 255.0f, b / 255.0f);
  add_material_numbers(material_name(group, index, path), Index(t), object.numbers);
}

ThreeMfModel::Object read_object(PLib3MFModel* model, PLib3MFModelMeshObject* mesh,
                                 const std::filesystem::path& path) {
  ThreeMfModel::Object object;
  DWORD vertex_count = 0, triangle_count = 0;
  check_lib3mf(lib3mf_meshobject_getvertexcount(mesh, &vertex_count), mesh, path, "counting vertices");
  check_lib3mf(lib3mf_meshobject_gettrianglecount(mesh, &triangle_count), mesh, path, "counting triangles");
  std::vector<MODELMESHVERTEX> vertices(vertex_count);
  std::vector<MODELMESHTRIANGLE> triangles(triangle_count);
  check_lib3mf(lib3mf_meshobject_getvertices(mesh, vertices.data(), vertex_count, nullptr), mesh, path,
               "vertices");
  check_lib3mf(lib3mf_meshobject_gettriangleindices(mesh, triangles.data(), triangle_count, nullptr), mesh,
               path, "triangles");
  for (const MODELMESHVERTEX& v : vertices)
    object.vertices.emplace_back(v.m_fPosition[0], v.m_fPosition[1], v.m_fPosition[2]);
  for (const MODELMESHTRIANGLE& t : triangles) {
    for (const DWORD i : t.m_nIndices)
      if (i >= vertex_count)
        throw IoError(path.string() + ": reading 3MF: a triangle names a missing vertex");
    object.triangles.push_back({Index(t.m_nIndices[0]), Index(t.m_nIndices[1]), Index(t.m_nIndices[2])});
  }
  PLib3MFPropertyHandler* handler = nullptr;
  check_lib3mf(lib3mf_meshobject_createpropertyhandler(mesh, &handler), mesh, path, "colours");
  const Lib3mfHandle owned(handler);
  for (DWORD t = 0; t < triangle_count; ++t) {
    eModelPropertyType type = MODELPROPERTYTYPE_NONE;
    check_lib3mf(lib3mf_propertyhandler_getpropertytype(handler, t, &type), handler, path, "colours");
    if (type != MODELPROPERTYTYPE_COLOR && type != MODELPROPERTYTYPE_BASEMATERIALS) continue;
    if (object.colors.empty()) object.colors.assign(triangle_count, no_face_color);
    if (type == MODELPROPERTYTYPE_BASEMATERIALS) {
      read_material(model, handler, t, object, path);
      continue;
    }
    MODELMESH_TRIANGLECOLOR_SRGB color{};
    check_lib3mf(lib3mf_propertyhandler_getcolor(handler, t, &color), handler, path, "colours");
    const MODELMESHCOLOR_SRGB& c = color.m_Colors[0];
    object.colors[t] = Color(c.m_Red / 255.0f, c.m_Green / 255.0f, c.m_Blue / 255.0f);
  }
  return object;
}

}  // namespace

ThreeMfModel read_3mf(const std::filesystem::path& path) {
  PLib3MFModel* raw = nullptr;
  check_lib3mf(lib3mf_createmodel(&raw), nullptr, path, "creating a model");
  const Lib3mfHandle model(raw);
  PLib3MFModelReader* reader_raw = nullptr;
  check_lib3mf(lib3mf_model_queryreader(raw, "3mf", &reader_raw), raw, path, "making a reader");
  const Lib3mfHandle reader(reader_raw);
  check_lib3mf(lib3mf_reader_readfromfileutf8(reader_raw, path.string().c_str()), reader_raw, path,
               "the package");
  ThreeMfModel result;
  DWORD unit = MODELUNIT_MILLIMETER;
  check_lib3mf(lib3mf_model_getunit(raw, &unit), raw, path, "the unit");
  result.unit = unit_of(unit);
  PLib3MFModelResourceIterator* iterator_raw = nullptr;
  check_lib3mf(lib3mf_model_getmeshobjects(raw, &iterator_raw), raw, path, "the objects");
  const Lib3mfHandle iterator(iterator_raw);
  BOOL has_next = false;
  while (lib3mf_resourceiterator_movenext(iterator_raw, &has_next) == LIB3MF_OK && has_next) {
    PLib3MFModelResource* resource = nullptr;
    check_lib3mf(lib3mf_resourceiterator_getcurrent(iterator_raw, &resource), iterator_raw, path,
                 "an object");
    const Lib3mfHandle owned(resource);
    result.objects.push_back(read_object(raw, resource, path));
  }
  if (std::all_of(result.objects.begin(), result.objects.end(),
                  [](const ThreeMfModel::Object& o) { return o.triangles.empty(); }))
    throw IoError(path.string() + ": reading 3MF: the package holds no triangles");
  return result;
}

}  // namespace nome
