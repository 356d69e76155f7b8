#include "slide/slide_library.hpp"

namespace nome::slide {

std::string_view slide_constants_script() {
  return R"tcl(
set SLF_PI 3.14159265358979323846
foreach {name value} {
  SLF_OFF 0 SLF_ON 1
  SLF_SOLID 0 SLF_HOLLOW 1
  SLF_INHERIT 0 SLF_WIRE 1 SLF_FLAT 2 SLF_GOURAUD 3 SLF_PHONG 4
  SLF_BOUND 1 SLF_EDGES 2 SLF_FULL 3
  SLF_PARALLEL 0 SLF_PERSPECTIVE 1
  SLF_AMBIENT 0 SLF_DIRECTIONAL 1 SLF_POINT 2 SLF_SPOT 3
  SLF_NULL 0 SLF_TEXMAP 1 SLF_QUADRILATERALS 1
  SLF_SUBDIVISION_CATMULL_CLARK 0 SLF_SUBDIVISION_CORNER_ROUNDING_TESSELATE 1
  SLF_OFFSET_ANGULAR 0 SLF_OFFSET_PERFORATED 1
} { set $name $value }
unset name value
)tcl";
}

// Sliders: a procedure sets the global variable a scale is bound to (NAME_THIS, or the one it is given) to
// its default and makes the scale; the scene turns each scale into a slider. Choice frames set their
// variable to the default choice and make one radio button per choice.
std::string_view slide_library_script() {
  return R"tcl(
namespace eval nome {}
proc DegToRad {degrees} { expr {$degrees * $::SLF_PI / 180.0} }
proc RadToDeg {radians} { expr {$radians * 180.0 / $::SLF_PI} }
proc Min {a b} { expr {$b < $a ? $b : $a} }
proc Max {a b} { expr {$b > $a ? $b : $a} }
proc Oscillate {} { expr {(cos($::SLF_TIME) + 1) / 2.0} }

proc CalculateTickInterval {min max ticks} { expr {($max - $min) / $ticks} }

proc nome::bound_scale {path variable label default min max resolution command} {
  upvar #0 $variable value
  if {$default ne ""} { set value $default }
  set options [list -label $label -from $min -to $max -resolution $resolution -variable $variable]
  if {$command ne ""} { lappend options -command $command }
  scale $path {*}$options
  return $path
}

# Two spellings: SLIDE's `CreateScale name parent this label default min max resolution ticks orient`
# (variable name_this) and the slideui package's `CreateScale parent this variable label min max resolution`
# (the variable already holds its default), with a command as its eighth argument.
proc CreateScale {args} {
  switch [llength $args] {
    10 {
      lassign $args name parent this label default min max resolution
      return [nome::bound_scale $parent.$this ${name}_$this $label $default $min $max $resolution ""]
    }
    7 - 8 {
      lassign $args parent this variable label min max resolution command
      return [nome::bound_scale $parent.$this $variable $label "" $min $max $resolution $command]
    }
    default {
      error "wrong # args: should be \"CreateScale name parent this label default min max resolution ticks orient\" or \"CreateScale parent this variable label min max resolution ?command?\""
    }
  }
}

proc CreateScaleCmd {args} {
  switch [llength $args] {
    11 {
      lassign $args name parent this label default min max resolution ticks orient command
      return [nome::bound_scale $parent.$this ${name}_$this $label $default $min $max $resolution $command]
    }
    8 {
      lassign $args parent this variable label min max resolution command
      return [nome::bound_scale $parent.$this $variable $label "" $min $max $resolution $command]
    }
    default {
      error "wrong # args: should be \"CreateScaleCmd name parent this label default min max resolution ticks orient command\""
    }
  }
}

proc CreateScaleL {name parent this label default min max resolution ticks orient length} {
  return [nome::bound_scale $parent.$this ${name}_$this $label $default $min $max $resolution ""]
}

# Two sliders for a range: A stays below B (each slider's end follows the other's value in SLIDE; here both
# keep the whole range).
proc CreateDoubleScale {name parent this thisA thisB labelA labelB min defaultA defaultB max resolution ticks orient} {
  frame $parent.$this
  nome::bound_scale $parent.$this.$thisA ${name}_$thisA $labelA $defaultA $min $max $resolution ""
  nome::bound_scale $parent.$this.$thisB ${name}_$thisB $labelB $defaultB $min $max $resolution ""
  return $parent.$this
}

proc CreateSLIDEEnumList {fields} {
  set choices {}
  foreach field $fields { lappend choices [list $field [set ::$field]] }
  return $choices
}

proc CreateRadioButtonFrame {name parent this label default choices} {
  set path $parent.$this
  frame $path
  upvar #0 ${name}_$this value
  set value $default
  foreach choice $choices {
    lassign $choice field number
    radiobutton $path.slf$field -text $field -variable ${name}_$this -value $number
  }
  return $path
}

proc CreateLODFrame {name parent} {
  CreateRadioButtonFrame $name $parent lod LOD $::SLF_FULL [CreateSLIDEEnumList {SLF_OFF SLF_BOUND SLF_EDGES SLF_FULL}]
}
proc CreateShadingFrame {name parent} {
  CreateRadioButtonFrame $name $parent shading Shading $::SLF_INHERIT \
      [CreateSLIDEEnumList {SLF_INHERIT SLF_WIRE SLF_FLAT SLF_GOURAUD SLF_PHONG}]
}
proc CreateSolidFrame {name parent} {
  CreateRadioButtonFrame $name $parent solid Solid $::SLF_SOLID [CreateSLIDEEnumList {SLF_SOLID SLF_HOLLOW}]
}
proc CreateProjectionFrame {name parent} {
  CreateRadioButtonFrame $name $parent projection Projection $::SLF_PERSPECTIVE \
      [CreateSLIDEEnumList {SLF_PERSPECTIVE SLF_PARALLEL}]
}
proc CreateLightTypeFrame {name parent} {
  CreateRadioButtonFrame $name $parent type Type $::SLF_AMBIENT \
      [CreateSLIDEEnumList {SLF_AMBIENT SLF_DIRECTIONAL SLF_POINT SLF_SPOT}]
}

# The window of an element's controls: .slf_NAME under the parent.
proc nome::element_window {parent name} {
  if {$parent eq "" || $parent eq "."} { set path .slf_$name } else { set path $parent.slf_$name }
  toplevel $path
  return $path
}

proc CreateObjectUI {parent name} {
  set path [nome::element_window $parent $name]
  CreateLODFrame $name $path
  CreateShadingFrame $name $path
  CreateSolidFrame $name $path
  return $path
}
proc CreateGroupUI {parent name} {
  set path [nome::element_window $parent $name]
  CreateLODFrame $name $path
  CreateShadingFrame $name $path
  return $path
}
proc CreateInstanceUI {parent name} { CreateGroupUI $parent $name }

# The settings of a subdivision node and of an offset node, in a global array the nodes' braced values read
# (`subdivisions {expr $oSubdivision(subdivisions)}`), and their controls: the level, the height and the
# width are sliders; the rest are SLIDE's display choices.
proc CreateSLIDESubdivisionObject {name} {
  upvar #0 $name node
  array set node [list lod $::SLF_FULL shading $::SLF_INHERIT type $::SLF_SUBDIVISION_CATMULL_CLARK \
      subdivisions 1 errormetric 0 drawcontrols 0 drawcurrent 1 drawvertices 0 \
      weightededges 0 weight 0 a 0 b 0 tolerance 0 facetsmax 0]
  return $name
}
proc CreateSLIDESubdivisionUI {parent name} {
  set path $parent.f$name
  frame $path
  nome::bound_scale $path.subdivisions ${name}(subdivisions) "subdivisions" "" 0 6 1 ""
  return $path
}
proc CreateSLIDEOffsetObject {name} {
  upvar #0 $name node
  array set node [list lod $::SLF_FULL shading $::SLF_INHERIT type $::SLF_OFFSET_ANGULAR \
      height 0.05 width 0.05 drawcontrols 0]
  return $name
}
proc CreateSLIDEOffsetUI {parent name} {
  set path $parent.f$name
  frame $path
  nome::bound_scale $path.height ${name}(height) "height" "" 0 0.5 0.005 ""
  nome::bound_scale $path.width ${name}(width) "width" "" 0 0.5 0.005 ""
  return $path
}

# The display settings of an object or a group (the slideui package's), which Nome leaves to its own view.
proc CreateSLIDEObjectObject {name} {
  upvar #0 $name node
  array set node [list lod $::SLF_FULL shading $::SLF_INHERIT solid $::SLF_SOLID]
  return $name
}
proc nome::choices {path variable fields} {
  foreach field $fields { radiobutton $path.slf$field -text $field -variable $variable -value [set ::$field] }
}
proc CreateSLIDEGroupUI {parent name} {
  set path $parent.f$name
  frame $path
  nome::choices $path ${name}(lod) {SLF_OFF SLF_BOUND SLF_EDGES SLF_FULL}
  nome::choices $path ${name}(shading) {SLF_INHERIT SLF_WIRE SLF_FLAT SLF_GOURAUD SLF_PHONG}
  return $path
}
proc CreateSLIDEObjectUI {parent name} {
  set path [CreateSLIDEGroupUI $parent $name]
  nome::choices $path ${name}(solid) {SLF_SOLID SLF_HOLLOW}
  return $path
}

proc CreateRGBColorUI {name parent this} {
  frame $parent.$this
  foreach channel {r g b} {
    nome::bound_scale $parent.$this.$channel ${name}_${this}_$channel $channel "" 0 1 0.01 ""
  }
  return $parent.$this
}
)tcl";
}

}  // namespace nome::slide
