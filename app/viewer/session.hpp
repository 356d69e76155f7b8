#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome::viewer {

// The file open in a window and the meshes derived from it (DESIGN.md "App": the document side). The
// viewer draws display_mesh(); the kernel computes everything.
class Session {
 public:
  // Reads a file (.obj, .stl). Throws nome::Error with `file:line:col: message` when it cannot.
  static Session open(const std::filesystem::path& path);

  const std::filesystem::path& path() const { return path_; }
  const Mesh& display_mesh() const { return *display_; }
  // Changes whenever display_mesh() changes; topology_version() only when its connectivity does.
  std::uint64_t geometry_version() const { return geometry_version_; }
  std::uint64_t topology_version() const { return topology_version_; }
  // Unsaved changes (edits or slider moves since the last save or load).
  bool is_modified() const { return is_modified_; }

  // Reloads the file from disk; on an error the session keeps its last good geometry and rethrows.
  void reload();

 private:
  void set_display(Mesh mesh, bool is_new_topology);

  std::filesystem::path path_;
  std::shared_ptr<const Mesh> display_;
  std::uint64_t geometry_version_ = 0;
  std::uint64_t topology_version_ = 0;
  bool is_modified_ = false;
};

}  // namespace nome::viewer
