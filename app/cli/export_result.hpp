#pragma once

#include <cstdint>
#include <filesystem>

#include "cli/input.hpp"
#include "nome/io/stl.hpp"
#include "nome/io/three_mf.hpp"
#include "nome/ops/print_placement.hpp"

namespace nome::cli {

// How `nome export` writes a .obj, .stl, .3mf, .glb or .ply.
struct ExportFormat {
  StlFormat stl = StlFormat::binary;
  ThreeMfOptions three_mf;
  PrintPlacementOptions placement;  // scaled and stood on a face before writing, unless the identity
};

// What was written, for the command's summary line and its print check.
struct ExportCounts {
  std::uint64_t vertices = 0, faces = 0, triangles = 0;
};

// True when an export to `path` can write the last stage without its Mesh (.stl or .obj, not scaled or
// placed): a subdivision level from its quads, an offset from its polygons; run_input need not build it.
bool streams_last_level(const std::filesystem::path& path, const ExportFormat& format);

// Writes the result of `loaded`'s settings to `path` (.obj, .stl, .3mf, .glb or .ply), placed for printing
// when format.placement says so. Where streams_last_level says
// so, the last stage goes from Pipeline::run_surface's quads or polygons to the file (the same bytes at
// about a fifth of the memory); otherwise from the pipeline's Mesh.
ExportCounts write_result(LoadedInput& loaded, const std::filesystem::path& path, const ExportFormat& format,
                          const Progress& progress);

}  // namespace nome::cli
