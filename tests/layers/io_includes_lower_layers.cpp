// An io source including headers of every layer below io, public and internal: this compiles.
#include "mesh/normal_passes.hpp"
#include "nome/error.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/query/ray.hpp"
#include "nome/scene/scene.hpp"
#include "support/parallel_for.hpp"
