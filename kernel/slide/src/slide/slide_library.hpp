#pragma once

#include <string_view>

namespace nome::slide {

// SLIDE's predefined variables: $SLF_PI and the SLF_* flags its statements take (shading, LOD, solid,
// projection, light types), with SLIDE's values.
std::string_view slide_constants_script();

// Nome's own version of SLIDE's Tcl library (slideui: SLIDEUI.tcl, MATH.tcl, MOVIE.tcl), for scenes that
// call it without a copy beside them: every procedure their files call, written from what it does.
std::string_view slide_library_script();

}  // namespace nome::slide
