#pragma once

// The one way the app includes OpenGL: glad's 3.3 core loader on the desktop (before any system GL
// header), Emscripten's OpenGL ES 3.0 header on the web (WebGL2). The renderer uses only what both have.
#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>
#else
#include <glad/gl.h>
#endif
