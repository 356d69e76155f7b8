#pragma once

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/polygon_soup.hpp"

namespace nome {

// The length a model unit stands for in a 3MF file (the slicer scales by it).
enum class LengthUnit { millimeter, centimeter, inch, meter };

// "mm", "cm", "in", "m"; none for anything else.
std::optional<LengthUnit> parse_length_unit(std::string_view name);
const char* to_string(LengthUnit unit);

struct ThreeMfOptions {
  LengthUnit unit = LengthUnit::millimeter;
  double scale = 1.0;  // positions are multiplied by it
};

// Writes the mesh as a 3MF package with lib3mf (Debian's 1.8.1, its C API): one mesh object per connected
// component, named "part N", each polygon as the triangles it is drawn with (query/display_triangles), each
// triangle coloured with its face's colour when the mesh has face colours. Positions are stored as
// floats, as 3MF's readers take them. Atomic (write_file_atomically). Throws IoError.
void write_3mf(const std::filesystem::path& path, const Mesh& mesh, const ThreeMfOptions& options = {});

// What a 3MF package holds, read back with lib3mf: every mesh object (build transforms are not applied).
struct ThreeMfModel {
  LengthUnit unit = LengthUnit::millimeter;
  struct Object {
    std::vector<Vec3> vertices;
    std::vector<std::array<Index, 3>> triangles;
    std::vector<Color> colors;  // one per triangle (its first corner's), or empty when it has none
    // Numbers named in the triangles' base materials ("material=3;region=1", as write_3mf names them).
    Attributes numbers;
  };
  std::vector<Object> objects;
};

ThreeMfModel read_3mf(const std::filesystem::path& path);

// The objects' triangles as one soup (objects after each other), coloured where the file colours them: what
// `nome info` and the pipeline read. Corners at the same position in one object are one vertex already.
PolygonSoup three_mf_polygons(const ThreeMfModel& model);

}  // namespace nome
