#pragma once

#include "nome/scene/scene.hpp"
#include "render/camera.hpp"

namespace nome::render {

// The lens a scene's first camera asks for, where it says: NOME_ORTHOGRAPHIC (or NOME_ORTHOGONAL)
// projects orthographically; NOME_PERSPECTIVE takes its frustum's first number as the vertical field of
// view in degrees; NOME_FRUSTUM (JIPCAD's reference spells it NOME_FRUTUM) the field of view its
// bottom, top and near values make. What it does not say, or says out of range, keeps `lens`.
Lens scene_lens(const scene::RenderDefaults& defaults, Lens lens = {});

}  // namespace nome::render
