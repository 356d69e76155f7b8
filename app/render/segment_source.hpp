#pragma once

#include "render/gl.hpp"
#include "render/mesh_display_data.hpp"

namespace nome::render {

// Segments as Renderer draws them: one instanced quad each (shaders/lines.vert), its two ends a
// per-instance pair of point ids, the points a table of vec3 (render/table_texture.hpp). Ids rather than
// positions per instance: a mesh's edges share its vertices, which a slider moves.
struct SegmentSource {
  GLuint vao = 0;     // from make_segment_vao()
  GLuint ends = 0;    // the buffer of point id pairs
  GLuint points = 0;  // the texture of points
  SegmentRange range;
};

// A vertex array whose attribute 0 reads a pair of point ids per instance from `ends` (re-pointed at each
// draw's first segment) and whose attribute 1, a colour per instance, is off: it reads the constant the
// renderer sets. Bound on return.
GLuint make_segment_vao(GLuint ends);

}  // namespace nome::render
