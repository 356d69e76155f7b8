#include "nome/io/three_mf.hpp"
#include "nome/mesh/color_attribute.hpp"

namespace nome {

PolygonSoup three_mf_polygons(const ThreeMfModel& model) {
  PolygonSoup soup;
  for (const ThreeMfModel::Object& object : model.objects) {
    const Index first = soup.num_vertices(), first_face = soup.num_faces();
    for (const Vec3& p : object.vertices) soup.add_vertex(p);
    for (Index t = 0; t < object.triangles.size(); ++t) {
      const auto& c = object.triangles[t];
      soup.add_face({first + c[0], first + c[1], first + c[2]});
      if (!object.colors.empty())
        add_colors(soup.face_attributes).set(soup.num_faces() - 1, object.colors[t]);
    }
    soup.face_attributes.append(object.numbers, first_face);
  }
  return soup;
}

}  // namespace nome
