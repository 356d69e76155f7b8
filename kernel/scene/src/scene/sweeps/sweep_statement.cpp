// `sweep NAME crosssection C ... endcrosssection path P ... endpath [brep ...] endsweep`: a cross-section
// swept along a path (kernel sweep(), nome/scene/sweep.hpp).
#include "scene/sweeps/sweep_syntax.hpp"

namespace nome::scene {

StatementKind sweep_statement() {
  return with_sweep_syntax(
      {.keyword = "sweep",
       .end_keyword = "endsweep",
       .dialect = StatementDialect::successor,
       .example = "crosssection c endcrosssection path pl mintorsion twist (90) endpath endsweep\n"
                  "circle c (4 0.2) endcircle\npolyline pl (p0 p1 p2 p3) endpolyline\n"
                  "sweep z crosssection c endcrosssection path pl endpath"});
}

// `sweepmorph NAME [begincap] [endcap] [reverse] path P ... endpath endsweepmorph`: the cross-sections its
// path's control points give, blended between them.
StatementKind sweep_morph_statement() {
  return with_sweep_syntax({.keyword = "sweepmorph",
                            .end_keyword = "endsweepmorph",
                            .dialect = StatementDialect::successor,
                            .example = "begincap path pl endpath endsweepmorph\ncircle c (4 0.2) endcircle\n"
                                       "controlpoint q point p1 crosssection c endcontrolpoint\n"
                                       "polyline pl (p0 q p2) endpolyline\nsweepmorph z path pl endpath"});
}

}  // namespace nome::scene
