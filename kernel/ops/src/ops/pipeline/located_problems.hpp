#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nome/error.hpp"
#include "nome/mesh/mesh.hpp"

namespace nome {

// build_mesh's error with each problem about a face located at the statement that made the face
// (`file:line:col: build_mesh: not a 2-manifold: face j_a repeats vertex j_i_hc1`, one line each);
// nothing when the soup knows the origin of none of those faces.
std::optional<TopologyError> located_error(const TopologyError& error, const PolygonSoup& soup);

// A warning per face of `mesh` with two corners at one position (at most `max_listed`, then a count),
// located at the statement that made the face; `soup` is what the mesh was built from, face for face.
std::vector<std::string> coinciding_vertex_warnings(const Mesh& mesh, const PolygonSoup& soup,
                                                    size_t max_listed = 8);

}  // namespace nome
