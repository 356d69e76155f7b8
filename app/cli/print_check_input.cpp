#include "cli/print_check_input.hpp"

namespace nome::cli {

namespace {

const Mesh& checked_surface(LoadedInput& loaded) {
  PipelineSettings surface_settings = loaded.settings;
  if (loaded.settings.distance() > 0.0) surface_settings.stage = Stage::subdivided;
  return loaded.pipeline.run(surface_settings);
}

}  // namespace

PrintCheck check_loaded_input(LoadedInput& loaded, double min_wall, const Progress& progress) {
  const double distance = loaded.settings.distance();
  const Mesh& surface = checked_surface(loaded);
  PrintCheckOptions options;
  options.offset_distance = distance;
  options.min_wall = min_wall;
  options.threads = loaded.settings.threads;
  options.progress = progress;
  return check_printability(surface, options);
}

Mesh marked_surface(LoadedInput& loaded, const PrintCheck& check) {
  Mesh surface = checked_surface(loaded);
  std::vector<Color>& colors = add_colors(surface.face_attributes()).values();
  colors.assign(surface.num_faces(), Color(0.8f, 0.8f, 0.78f));
  for (const NearMiss& miss : check.near_misses)
    for (const Index c : surface.vertex_corners(miss.vertex))
      colors[surface.corner_face(c)] = Color(1.0f, 0.55f, 0.0f);
  for (const Index f : check.crossings.faces) colors[f] = Color(0.9f, 0.05f, 0.05f);
  for (const Index f : check.fold_over_faces) colors[f] = Color(0.85f, 0.0f, 0.85f);
  return surface;
}

std::uint64_t triangle_count(const Mesh& mesh) {
  return std::uint64_t(mesh.num_corners()) - 2 * std::uint64_t(mesh.num_faces());
}

}  // namespace nome::cli
#include "nome/mesh/color_attribute.hpp"
