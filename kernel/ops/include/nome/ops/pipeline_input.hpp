#pragma once

#include <functional>
#include <string>
#include <vector>

#include "nome/mesh/polygon_soup.hpp"

namespace nome {

// How the scene stage joins the input's polygons into a mesh.
enum class Joining {
  // build_mesh: the polygons must form a 2-manifold; anything else is a TopologyError naming the part.
  manifold,
  // glue_faces: faces join across shared edges only, so faces that merely touch at a vertex keep
  // separate vertices there (what deleting faces leaves behind) and an edge of three faces joins none.
  across_edges,
};

// One part of the input (a file, a scene, an editing layer): the next `faces` faces of the soup.
struct InputPart {
  std::string name;  // named in topology errors: the file it came from, or what it is
  Index faces = 0;
  // Manifold joining only: where this part's faces touch at a vertex without sharing an edge there (a
  // scene's pieces meeting at a point), the vertex is split, one copy per fan, with a warning naming it,
  // instead of refusing the input. Edges of three or more faces are refused all the same.
  bool may_touch_at_vertices = false;
  // Where the part's face k was written (`file:line:col`), or empty: topology errors then point at it.
  std::function<std::string(Index)> locate_face = {};
};

// The pipeline's input: the scene stage's polygons, part after part.
struct PipelineInput {
  PolygonSoup soup;
  std::vector<InputPart> parts;  // empty: one part
  Joining joining = Joining::manifold;
};

}  // namespace nome
