#pragma once

#include <filesystem>
#include <functional>

#include "nome/mesh/polygon_soup.hpp"

namespace nome::slide {

// Reads the polygons of a mesh file (STL, SIF, ...): how a SLIDE scene's Tcl (`CreateSTLObject`) reaches
// the file readers of the layer above. Empty: such files are refused.
using PolygonFileReader = std::function<PolygonSoup(const std::filesystem::path&)>;

}  // namespace nome::slide
