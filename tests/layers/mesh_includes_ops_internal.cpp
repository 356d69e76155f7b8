// A mesh source including an internal header of ops: above mesh, so this must not compile.
#include "ops/subdivision/refinement_level.hpp"
