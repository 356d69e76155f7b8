#include "cli/export_result.hpp"

#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include "cli/print_check_input.hpp"
#include "nome/io/gltf.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/ply.hpp"

namespace nome::cli {

bool streams_last_level(const std::filesystem::path& path, const ExportFormat& format) {
  const std::string ext = path.extension().string();
  return format.placement.is_identity() && (ext == ".obj" || (ext == ".stl" && format.three_mf.scale == 1.0));
}

ExportCounts write_result(LoadedInput& loaded, const std::filesystem::path& path, const ExportFormat& format,
                          const Progress& progress) {
  const std::string ext = path.extension().string();
  if (streams_last_level(path, format)) {
    // An OBJ keeps the sharp edges as tags, which only a Mesh has.
    const PipelineSurface surface = loaded.pipeline.run_surface(loaded.settings, ext == ".obj");
    print_warnings(loaded.pipeline.warnings());
    auto write = [&](const auto& streamed) {
      if (ext == ".obj")
        write_obj(path, streamed);
      else
        write_stl(path, streamed, format.stl, progress);
    };
    if (surface.solid) {
      write(*surface.solid);
      // Each polygon is a fan of its corner count less two triangles.
      return {surface.solid->num_vertices(), surface.solid->num_faces(),
              surface.solid->num_corners() - 2 * std::uint64_t(surface.solid->num_faces())};
    }
    if (surface.quads) {
      write(*surface.quads);
      return {surface.quads->num_vertices(), surface.quads->num_faces(),
              2 * std::uint64_t(surface.quads->num_faces())};
    }
  }
  const Mesh& result = loaded.pipeline.run(loaded.settings);
  std::optional<Mesh> placed;
  if (!format.placement.is_identity()) placed = placed_for_print(result, format.placement);
  const Mesh& mesh = placed ? *placed : result;
  if (ext == ".obj")
    write_obj(path, mesh, loaded.kept_tags);
  else if (ext == ".glb")
    write_glb(path, mesh);
  else if (ext == ".ply")
    write_ply(path, mesh);
  else if (ext == ".3mf")
    write_3mf(path, mesh, format.three_mf);
  else if (format.three_mf.scale != 1.0)
    write_stl(path, transformed(mesh, glm::scale(glm::dmat4(1.0), Vec3(format.three_mf.scale))), format.stl,
              progress);
  else
    write_stl(path, mesh, format.stl, progress);
  // An OBJ holds a vertex that holes split into one per fan once (Mesh::vertex_origins).
  std::uint64_t vertices = mesh.num_vertices();
  if (ext == ".obj" && !mesh.vertex_origins().empty()) {
    vertices = 0;
    for (Index v = 0; v < mesh.num_vertices(); ++v) vertices += mesh.vertex_origins()[v] == v ? 1 : 0;
  }
  return {vertices, mesh.num_faces(), triangle_count(mesh)};
}

}  // namespace nome::cli
