#include "nome/scene/scene_rim_lines.hpp"

namespace nome::scene {

RimLines scene_rim_lines(const Scene& scene) {
  RimLines rims;
  std::vector<Vec3> points;
  std::vector<std::string> names;
  for (const SceneInstance& instance : scene.instances()) {
    const PolygonSoup& soup = instance.geometry.soup;
    for (const RimLine& rim : instance.geometry.rims) {
      points.clear();
      names.clear();
      for (Index v : rim.vertices) {
        points.push_back(soup.positions[v]);
        names.push_back(v < soup.vertex_names.size() ? soup.vertex_names[v]
                                                     : rim.name + "_" + std::to_string(v));
      }
      rims.add_line(points, names, rim.is_loop, rim.color);
    }
  }
  return rims;
}

std::vector<Vec3> scene_rim_positions(const Scene& scene) {
  std::vector<Vec3> positions;
  for (const SceneInstance& instance : scene.instances())
    for (const RimLine& rim : instance.geometry.rims)
      for (Index v : rim.vertices) positions.push_back(instance.geometry.soup.positions[v]);
  return positions;
}

}  // namespace nome::scene
