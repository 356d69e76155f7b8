// A support source including a mesh header: mesh is above support, so this must not compile.
#include "nome/mesh/types.hpp"
