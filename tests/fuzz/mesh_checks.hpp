#pragma once

#include "nome/mesh/mesh.hpp"

namespace nome::fuzz {

// Everything downstream of a reader that must hold for any mesh build_mesh accepted: the topology
// report and normals run, the soup round trip rebuilds the same counts, a boundary merge gives a
// 2-manifold that passes the same checks, one Catmull-Clark level keeps every part's chi, orientability
// and borders, and its offset is a closed, orientable solid with twice its chi. Aborts on a violation
// (libFuzzer records the input).
void check_downstream(const Mesh& mesh);

// build_mesh on a soup a reader accepted: refusal by TopologyError is fine (a reader does not check
// manifoldness); InvalidInputError means the reader handed on an inconsistent soup, a bug (the exception
// escapes: libFuzzer reports it); anything accepted goes through check_downstream.
void build_and_check(PolygonSoup soup);

}  // namespace nome::fuzz
