#pragma once

// The generators of the 2016 report, of NOME 2.x and of JIPCAD, each declared in its own header.
#include "nome/scene/generators/circle.hpp"
#include "nome/scene/generators/curves.hpp"
#include "nome/scene/generators/cylinder.hpp"
#include "nome/scene/generators/disk.hpp"
#include "nome/scene/generators/dupin.hpp"
#include "nome/scene/generators/funnel.hpp"
#include "nome/scene/generators/hyperboloid.hpp"
#include "nome/scene/generators/mobius_strip.hpp"
#include "nome/scene/generators/sphere.hpp"
#include "nome/scene/generators/torus.hpp"
#include "nome/scene/generators/torus_knot.hpp"
#include "nome/scene/generators/tunnel.hpp"
