#pragma once

#include <cstdint>
#include <filesystem>

#include "nome/mesh/polygon_soup.hpp"

namespace nome::viewer {

// The file open in a window (DESIGN.md "App": the document side): what it says, as the scene's polygons,
// and whether it has unsaved changes. The stages after the scene are the StagePipeline's.
class Session {
 public:
  // Reads a file (.obj, .stl). Throws nome::Error with `file:line:col: message` when it cannot.
  static Session open(const std::filesystem::path& path);

  const std::filesystem::path& path() const { return path_; }
  // The scene's polygons: every top-level instance as one part of one soup.
  const PolygonSoup& scene_soup() const { return soup_; }
  // Changes whenever scene_soup() does.
  std::uint64_t version() const { return version_; }
  // Unsaved changes (edits or slider moves since the last save or load).
  bool is_modified() const { return is_modified_; }

  // Reads the file again; on an error the session keeps what it had and rethrows.
  void reload();

 private:
  std::filesystem::path path_;
  PolygonSoup soup_;
  std::uint64_t version_ = 0;
  bool is_modified_ = false;
};

}  // namespace nome::viewer
