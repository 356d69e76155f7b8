// The one table of the .nome language's statements. Each row is made by its statement's own file (its
// keywords, the dialects it belongs to, argument shape, parser, writer and evaluator); this file only lists
// them. To add a generator: write generators/NAME.cpp (its geometry, its evaluator and NAME_statement()
// returning its row), declare NAME_statement() below and add it to the table; then its section in
// docs/language.md and its tests.
#include "nome/scene/statement_kinds.hpp"

#include <algorithm>

namespace nome::scene {

StatementKind bank_statement();
StatementKind surface_statement();
StatementKind point_statement();
StatementKind polyline_statement();
StatementKind face_statement();
StatementKind object_statement();
StatementKind funnel_statement();
StatementKind tunnel_statement();
StatementKind circle_statement();
StatementKind mobius_strip_statement();
StatementKind sphere_statement();
StatementKind ellipsoid_statement();
StatementKind cylinder_statement();
StatementKind cone_statement();
StatementKind disk_statement();
StatementKind torus_statement();
StatementKind torus_knot_statement();
StatementKind helix_statement();
StatementKind spiral_statement();
StatementKind hyperboloid_statement();
StatementKind dupin_statement();
StatementKind cartesian_statement();
StatementKind parametric_statement();
StatementKind implicit_statement();
StatementKind mesh_statement();
StatementKind group_statement();
StatementKind instance_statement();
StatementKind delete_statement();
StatementKind consolidate_statement();
StatementKind sharp_statement();
StatementKind sharp_edges_statement();
StatementKind include_statement();
StatementKind subdivision_statement();
StatementKind offset_statement();
StatementKind boundary_statement();
StatementKind print_setup_statement();
StatementKind camera_statement();
StatementKind light_statement();
StatementKind window_statement();
StatementKind viewport_statement();
StatementKind frontcolor_statement();
StatementKind backcolor_statement();
StatementKind backgroundcolor_statement();
StatementKind backface_statement();
StatementKind control_point_statement();
StatementKind bezier_curve_statement();
StatementKind bspline_statement();
StatementKind sweep_statement();
StatementKind sweep_morph_statement();
StatementKind morph_visualizer_statement();
StatementKind ribbon_statement();
StatementKind script_block_statement();
StatementKind render_statement();
StatementKind slide_mirror_statement();

namespace {

// The built-in rows, then any added ones (AddedStatementKind).
std::vector<StatementKind>& table() {
  // In the order error messages list the keywords and the writer writes the statements (any order
  // reads back: names are resolved after parsing).
  static std::vector<StatementKind> rows = {
      bank_statement(),          // sliders
      surface_statement(),       // a colour
      point_statement(),         // a named position
      polyline_statement(),      // a rim line over named vertices
      face_statement(),          // one face over named vertices
      object_statement(),        // a mesh of top-level faces
      funnel_statement(),        // generator (report 6.3)
      tunnel_statement(),        // generator: two funnels
      circle_statement(),        // generator: a closed rim line
      mobius_strip_statement(),  // generator: mobiusstrip
      sphere_statement(),        // generator (JIPCAD): a globe, poles shared
      ellipsoid_statement(),     // generator (JIPCAD): a globe with its own polar radius
      cylinder_statement(),      // generator (JIPCAD): a mantle with optional caps
      cone_statement(),          // generator (JIPCAD): a possibly truncated cone
      disk_statement(),          // generator (JIPCAD): a disk or wedge
      torus_statement(),         // generator (JIPCAD): a torus, partial angles
      torus_knot_statement(),    // generator (JIPCAD): a tube along a torus knot
      helix_statement(),         // generator (JIPCAD): a helical rim line
      spiral_statement(),        // generator (JIPCAD): a spiral rim line
      hyperboloid_statement(),   // generator (JIPCAD): one sheet, paraboloid, two sheets
      dupin_statement(),         // generator (JIPCAD): a Dupin cyclide
      cartesian_statement(),     // generator (JIPCAD): z = f(x, y)
      parametric_statement(),    // generator (JIPCAD): (x, y, z)(u, v)
      implicit_statement(),      // generator (JIPCAD): f(x, y, z) = 0
      mesh_statement(),          // faces and sharp edges over named vertices
      group_statement(),         // instances
      instance_statement(),      // a top-level instance: a root of the scene
      delete_statement(),        // faces deleted by name
      consolidate_statement(),   // the consolidated mesh
      sharp_statement(),         // creases and corners over instances' vertices, by path
      sharp_edges_statement(),   // edges marked sharp in the viewer
      include_statement(),       // successor: another file's statements
      subdivision_statement(),   // successor: root instances and the subdivision levels
      offset_statement(),        // successor: root instances and the offset distance
      boundary_statement(),      // subdivision at the border (both dialects)
      print_setup_statement(),   // print preparation kept with the scene: size and rest face
      camera_statement(),        // successor: render defaults
      light_statement(), window_statement(), viewport_statement(), frontcolor_statement(),
      backcolor_statement(), backgroundcolor_statement(), backface_statement(),

      // Curves and sweeps
      control_point_statement(),     // a point that shapes a sweep's cross-section
      bezier_curve_statement(),      // curve: a rim line, a sweep's path or cross-section
      bspline_statement(),           // curve: uniform B-spline
      sweep_statement(),             // a cross-section swept along a path (kernel sweep())
      sweep_morph_statement(),       // a sweep whose cross-sections blend between control points
      morph_visualizer_statement(),  // one of a sweep's cross-sections
      ribbon_statement(),            // a band along a rim line (report 6.3's rim ribbon)

      script_block_statement(),  // SLIDE: `tclinit { Tcl }`
      render_statement(),        // SLIDE: what is drawn, through which camera
      slide_mirror_statement(),  // SLIDE: a group whose mirrored faces are turned back
  };
  return rows;
}

}  // namespace

std::span<const StatementKind> statement_kinds() {
  return table();
}

AddedStatementKind::AddedStatementKind(StatementKind kind) {
  table().push_back(kind);
}

AddedStatementKind::~AddedStatementKind() {
  table().pop_back();
}

std::optional<Index> find_statement_kind(std::string_view keyword) {
  const std::span<const StatementKind> kinds = statement_kinds();
  const auto it =
      std::find_if(kinds.begin(), kinds.end(), [&](const StatementKind& k) { return k.keyword == keyword; });
  if (it == kinds.end()) return std::nullopt;
  return Index(it - kinds.begin());
}

bool is_slide_statement(StatementDialect dialect) {
  return dialect == StatementDialect::slide || dialect == StatementDialect::slide_only ||
         dialect == StatementDialect::successor_and_slide;
}

bool is_nome_statement(StatementDialect dialect) {
  return dialect != StatementDialect::slide_only;
}

std::string statement_keyword_list(bool is_slf) {
  std::string list;
  for (const StatementKind& k : statement_kinds())
    if (is_slf ? is_slide_statement(k.dialect) : is_nome_statement(k.dialect))
      list += (list.empty() ? "" : ", ") + std::string(k.keyword);
  return list;
}

}  // namespace nome::scene
