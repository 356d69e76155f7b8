#include <algorithm>

#include "nome/io/three_mf.hpp"

namespace nome {

PolygonSoup three_mf_polygons(const ThreeMfModel& model) {
  PolygonSoup soup;
  const bool has_colors = std::any_of(model.objects.begin(), model.objects.end(),
                                      [](const ThreeMfModel::Object& o) { return !o.colors.empty(); });
  for (const ThreeMfModel::Object& object : model.objects) {
    const Index first = soup.num_vertices();
    for (const Vec3& p : object.vertices) soup.add_vertex(p);
    for (Index t = 0; t < object.triangles.size(); ++t) {
      const auto& c = object.triangles[t];
      soup.add_face({first + c[0], first + c[1], first + c[2]});
      if (has_colors) soup.face_colors.push_back(object.colors.empty() ? no_face_color : object.colors[t]);
    }
  }
  return soup;
}

}  // namespace nome
