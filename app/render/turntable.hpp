#pragma once

#include <vector>

#include "nome/mesh/mesh.hpp"
#include "render/image.hpp"
#include "render/snapshot.hpp"

namespace nome::render {

// `frames` pictures of the mesh turning once about the vertical axis (azimuths 360/frames apart from the
// first view's, its elevation), all with one framing: the target and distance that fit every azimuth, so
// the model turns in place. A given target or distance in `options` wins. Needs a current context.
std::vector<Image> render_turntable(const Mesh& mesh, const SnapshotOptions& options, int frames);

// The frames side by side, row by row, in a sheet as near square as the count allows.
Image contact_sheet(const std::vector<Image>& frames);

}  // namespace nome::render
