#include "viewer/session.hpp"

#include "nome/io/read_polygons.hpp"

namespace nome::viewer {

Session Session::open(const std::filesystem::path& path) {
  Session session;
  session.path_ = path;
  session.set_display(build_mesh(read_polygons(path)), true);
  return session;
}

void Session::reload() {
  Mesh mesh = build_mesh(read_polygons(path_));
  const bool same_topology = mesh.num_vertices() == display_->num_vertices() &&
                             mesh.face_offsets() == display_->face_offsets() &&
                             mesh.corner_vertices() == display_->corner_vertices();
  set_display(std::move(mesh), !same_topology);
}

void Session::set_display(Mesh mesh, bool is_new_topology) {
  display_ = std::make_shared<const Mesh>(std::move(mesh));
  ++geometry_version_;
  if (is_new_topology) ++topology_version_;
}

}  // namespace nome::viewer
