#pragma once

// The generators of the 2016 report and of NOME 2.x, each declared in its own header.
#include "nome/scene/generators/circle.hpp"
#include "nome/scene/generators/funnel.hpp"
#include "nome/scene/generators/mobius_strip.hpp"
#include "nome/scene/generators/tunnel.hpp"
