#include "viewer/session.hpp"

#include "nome/io/read_polygons.hpp"

namespace nome::viewer {

Session Session::open(const std::filesystem::path& path) {
  Session session;
  session.path_ = path;
  session.soup_ = read_polygons(path);
  return session;
}

void Session::reload() {
  soup_ = read_polygons(path_);
  ++version_;
}

}  // namespace nome::viewer
