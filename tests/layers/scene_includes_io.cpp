// A scene source including an io header: io is above scene, so this must not compile.
#include "nome/io/obj.hpp"
