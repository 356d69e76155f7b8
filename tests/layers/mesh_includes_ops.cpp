// A mesh source including an ops header: ops is above mesh, so this must not compile.
#include "nome/ops/subdivide.hpp"
