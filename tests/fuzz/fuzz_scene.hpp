#pragma once

#include <string_view>

namespace nome::fuzz {

// The funnel cube of report 004 (assets/funnel_cube.nome), inline so that the fuzz programs need no files:
// the scene the slider, .anom and pipeline targets work on.
inline constexpr std::string_view funnel_cube_scene = R"(bank fp
  set n 8 3 10 1
  set ro 0.4 0.1 1.0 0.1
  set ratio -0.2 -0.5 0.5 0.1
  set h 0.2 0.1 1.5 0.1
  set z -0.8 -1.5 -0.1 0.1
endbank
funnel fun ({expr $fp_n} {expr $fp_ro} {expr $fp_ratio} {expr $fp_h}) endfunnel
group cubeMadeByFunnel
  instance fun1 fun translate (0 0 {expr $fp_z}) endinstance
  instance fun2 fun translate (0 0 {expr $fp_z}) rotate (1 0 0) (180) endinstance
  instance fun3 fun translate (0 0 {expr $fp_z}) rotate (1 0 0) (90) endinstance
  instance fun4 fun translate (0 0 {expr $fp_z}) rotate (1 0 0) (-90) endinstance
  instance fun5 fun translate (0 0 {expr $fp_z}) rotate (0 1 0) (90) endinstance
  instance fun6 fun translate (0 0 {expr $fp_z}) rotate (0 1 0) (-90) endinstance
endgroup
instance cf cubeMadeByFunnel endinstance
)";

}  // namespace nome::fuzz
