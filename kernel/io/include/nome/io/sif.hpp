#pragma once

#include <filesystem>
#include <string_view>

#include "nome/mesh/polygon_soup.hpp"

namespace nome {

struct SifOptions {
  // Report 7.1: join two triangles sharing an edge into a quad where the quad is convex and nearly planar,
  // best pairs first, to reduce extraordinary points in Catmull-Clark subdivision. Topology is kept.
  bool pair_triangles = false;
  double max_fold_degrees = 20;  // the largest angle between the two triangles' normals
};

// Reads SIF_SFF text (Berkeley SLIDE's solid interchange format): `(SIF_SFF major minor (units u)
// (solid (shell (vertices n (v x y z)...) (triangles n (t a b c)...))...))`, `(* ... *)` comments. Each
// shell becomes a separate part of the soup; units are read and ignored. Throws IoError with
// `file:line:col: expected X, found Y` for malformed text, wrong counts or indices out of range.
PolygonSoup parse_sif(std::string_view text, const std::string& file, const SifOptions& options = {});
PolygonSoup read_sif(const std::filesystem::path& path, const SifOptions& options = {});

// The triangle pairing of SifOptions on any soup: faces that are not triangles are kept as they are.
PolygonSoup pair_triangles(const PolygonSoup& soup, double max_fold_degrees);

}  // namespace nome
