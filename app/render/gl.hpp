#pragma once

// The one way the app includes OpenGL: glad's 3.3 core loader, before any system GL header.
#include <glad/gl.h>
