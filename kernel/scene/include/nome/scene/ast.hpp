#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nome/ops/print_placement.hpp"
#include "nome/scene/expression.hpp"

namespace nome::scene {

// A name as written, with where it stands. Dotted NOME 2.x paths are normalised to `_` (cf.tun5.lc5 ->
// cf_tun5_lc5) so that both spellings name the same thing.
struct Name {
  std::string text;
  SourceLocation location;
};

// The two spellings of the language: the 2016 report's and JIPCAD's (NOME's successor). They differ in
// a few words (`isloop`/`closed`, a bank's `list`) and in funnel and tunnel's argument order.
enum class Dialect { report2016, jipcad };

// Which dialect a text is read in, and what decided it (`'list' in a bank at 3:3`, `--dialect`).
struct DialectChoice {
  Dialect dialect = Dialect::report2016;
  std::string cue;  // empty: nothing in the text decided, the 2016 spelling is the default
};

// `set NAME value min max step` inside `bank BANK`: a slider, referenced as $BANK_NAME.
struct SliderDecl {
  Name name;
  Value value, min, max, step;
  std::string label = {};  // a SLIDE scale's -label
};

// `bank NAME set ... [list (ids)] endbank`: the successor's `list` names the sliders the panel shows.
struct BankDecl {
  Name name;
  std::vector<SliderDecl> sliders;
  std::optional<std::vector<Name>> shown;
};

// `surface NAME color (r g b) endsurface`
struct SurfaceDecl {
  Name name;
  Value rgb[3];
};

// `point NAME (x y z) endpoint`
struct PointDecl {
  Name name;
  Value xyz[3];
};

// `face NAME (v1 v2 ...) [surface S] endface`, at top level or inside a mesh.
struct FaceDecl {
  Name name;
  std::vector<Name> vertices;
  std::optional<Name> surface;
};

// `polyline NAME (v1 v2 ...) [isloop] endpolyline`: a rim line.
struct PolylineDecl {
  Name name;
  std::vector<Name> vertices;
  bool is_loop = false;
};

// `object NAME (f1 f2 ...) endobject`: a mesh made of top-level faces.
struct ObjectDecl {
  Name name;
  std::vector<Name> faces;
};

// `func [...]`, `funcX [...]`: a function of the generator's variables written in brackets (JIPCAD's
// function surfaces); `text` is what stands between the brackets.
struct FunctionText {
  Name keyword;
  std::string text;
  SourceLocation location;  // of the '['
};

// `KEYWORD NAME [functions] (arguments [options]) endKEYWORD`: a generator (funnel, tunnel, circle,
// sphere, ...), whose keyword, argument count and evaluator are its row of statement_kinds().
struct GeneratorDecl {
  Index kind = 0;  // row of statement_kinds()
  Name name;
  std::vector<Value> args;
  std::vector<Name> options;  // words among the arguments: a cylinder's `botcap`, `topcap`
  std::vector<FunctionText> functions;
};

// `sharp [weight] (v1 v2 ...) ... endsharp` inside a mesh or at the top level (naming instances' vertices by
// path): the chain of edges v1-v2, v2-v3, ... is sharp; a single vertex is a sharp corner. The weight is
// OpenSubdiv's crease sharpness (none: infinite). `sharp [weight] border (v ...) endsharp` (top level):
// the whole border of each named vertex's own instance through it (a funnel's rim).
struct SharpDecl {
  std::vector<Name> vertices;
  SourceLocation location;
  std::optional<Value> weight = std::nullopt;
  bool is_border = false;
};

// `controlpoint NAME point P [scale (sx sy sz)] [rotate (rx ry rz)] [crosssection C] [reverse]
// endcontrolpoint`: point P, where a sweep shapes its cross-section (scale, tilt and turn in degrees, its
// own cross-section, reversed order from here on). Faces and curves name it like a point.
struct ControlPointDecl {
  Name name;
  Name point;
  Value scale[3] = {{1, no_index, {}}, {1, no_index, {}}, {1, no_index, {}}};
  Value rotate[3] = {};
  bool has_scale = false, has_rotate = false;
  std::optional<Name> cross_section;
  bool is_reversing = false;
};

// `beziercurve NAME (p1 p2 ...) [segs N] endbeziercurve`, `bspline NAME [order K] (p1 p2 ...) [segs N]
// [closed] endbspline`: a curve sampled into N segments over named points (or control points).
struct CurveDecl {
  Index kind = 0;  // row of statement_kinds()
  Name name;
  std::vector<Name> points;
  std::optional<Value> order, segs;
  bool is_closed = false;
};

// `sweep NAME crosssection C [reverse] [begincap] [endcap] endcrosssection path P [mintorsion]
// [azimuth A] [twist T] [cutbegin] [cutend] endpath [brep TRIANGLES|QUADRILATERALS] endsweep`; a
// `sweepmorph` has no crosssection block (its path's control points give them) but takes the flags.
struct SweepDecl {
  Index kind = 0;  // row of statement_kinds(): sweep or sweepmorph
  Name name;
  std::optional<Name> cross_section;
  Name path;
  bool is_reversed = false, has_begin_cap = false, has_end_cap = false;
  bool is_minimal_torsion = false, is_cut_begin = false, is_cut_end = false, is_triangles = false;
  std::optional<Value> azimuth, twist;
};

// `morphvisualizer NAME sweep S index (I) endmorphvisualizer`: the cross-section a sweep uses at its
// I-th path sample, as a closed rim line in the plane z = 0.
struct MorphVisualizerDecl {
  Name name;
  Name sweep;
  Value index;
};

// `mesh NAME face ... endface ... [sharp ...] endmesh`
struct MeshDecl {
  Name name;
  std::vector<FaceDecl> faces;
  std::vector<SharpDecl> sharps;
};

enum class TransformKind { translate, rotate, scale, mirror };

// translate (x y z) | rotate (ax ay az) (degrees) | scale (sx sy sz) | mirror (a b c d)
struct TransformDecl {
  TransformKind kind = TransformKind::translate;
  Value args[4];
  SourceLocation location;
};

// `instance NAME TARGET [transforms] [surface S] endinstance`
// SLIDE's `lookat eye (x y z) target (x y z) up (x y z) endlookat` in an instance of a camera or a light.
struct LookAtDecl {
  Value eye[3], target[3], up[3];
  SourceLocation location;
};

struct InstanceDecl {
  Name name;
  Name target;
  std::vector<TransformDecl> transforms;
  std::optional<Name> surface;
  SourceLocation location;
  std::optional<Name> backface =
      std::nullopt;        // the successor's `backface B` (or `surface B` naming a backface)
  Index stage = no_index;  // top level: the stage block (SceneAst::stages) it is written in, if any
  std::optional<LookAtDecl> look_at = std::nullopt;  // .slf: how a camera or a light looks
};

// `subdivision NAME [sd_type T] sd_level N instance ... endsubdivision` and `offset NAME [offset_type T]
// height width instance ... endoffset` (the successor's stage blocks): their instances are roots of the
// scene, and the block sets the pipeline's subdivision levels or offset distance.
enum class StageKind { subdivision, offset };
struct StageDecl {
  StageKind kind = StageKind::subdivision;
  Name name;
  std::optional<Name> type;  // NOME_SD_CC_sharp, NOME_OFFSET_DEFAULT, ...
  Value amount;              // sd_level, or the offset's height (half thickness)
  std::optional<Value> width;
  std::optional<Name> boundary;  // a subdivision block's `sd_boundary MODE`
  SourceLocation location;
};

// One field of a render statement: `type NOME_AMBIENT`, `color (r g b)`, `frustum (...)`, `cameraID c`.
struct RenderField {
  Name key;
  std::optional<Name> word;
  std::vector<Value> values;
};

// `camera`, `light`, `window`, `viewport` (named blocks of fields), `frontcolor`, `backcolor`,
// `background` (a colour) and `backface NAME color (...)`: the picture's defaults, not geometry.
struct RenderDecl {
  std::string keyword;
  std::optional<Name> name;
  std::vector<RenderField> fields;
  SourceLocation location;
};

// `group NAME instance ... endgroup`
struct GroupDecl {
  Name name;
  std::vector<InstanceDecl> instances;
};

// A face given by the hierarchical names of its vertices: the consolidated mesh of the editing workflow
// (`consolidate ... consolidateface vertex N endvertex ... endconsolidateface ... endconsolidate`).
struct NamedFace {
  std::vector<Name> vertices;
  SourceLocation location;
};

// `sharpedges [weight] (a b) ... endsharpedges`: an edge marked sharp in the viewer, with its weight.
struct SharpEdgeDecl {
  NamedFace edge;  // two vertices
  float weight = infinite_sharpness;
};

// One parsed .nome text. Definitions are resolved by name, so their order does not matter.
// Program text inside a scene (SLIDE's Tcl in .slf files), with where it stands.
struct ScriptText {
  std::string text;
  SourceLocation location;
};

struct SceneAst {
  std::string file;
  ExpressionPool expressions;
  std::vector<ScriptText> script_blocks;  // `tclinit { ... }`, in file order: run before any evaluation
  std::vector<ScriptText> script_values;  // braced values: ExprOp::script nodes name them by index
  std::vector<BankDecl> banks;
  std::vector<SurfaceDecl> surfaces;
  std::vector<PointDecl> points;
  std::vector<FaceDecl> faces;  // top-level faces (used by objects, or instantiated directly)
  std::vector<PolylineDecl> polylines;
  std::vector<ObjectDecl> objects;
  std::vector<GeneratorDecl> generators;
  std::vector<ControlPointDecl> control_points;
  std::vector<CurveDecl> curves;
  std::vector<SweepDecl> sweeps;
  std::vector<MorphVisualizerDecl> morph_visualizers;
  std::vector<MeshDecl> meshes;
  std::vector<GroupDecl> groups;
  std::vector<InstanceDecl> instances;  // top-level: the scene's roots
  std::vector<Name> deleted_faces;      // `delete face NAME endface ... enddelete`
  std::vector<NamedFace> consolidated_faces;
  std::vector<SharpEdgeDecl> sharp_edges;  // `sharpedges [weight] (a b) ... endsharpedges`
  std::vector<SharpDecl> sharps;           // top-level `sharp ... endsharp`: instances' vertices by path
  std::vector<StageDecl> stages;
  std::vector<Name> boundary_modes;                  // `boundary MODE endboundary`: subdivision at the border
  std::optional<PrintPlacementOptions> print_setup;  // `printsetup ... endprintsetup`: print preparation
  std::vector<RenderDecl> render;
  std::vector<InstanceDecl> render_instances;  // top-level instances of a camera, light, window or viewport
  std::vector<std::string> included_files;     // every file read by `include`, in reading order
  DialectChoice dialect;
};

// The name every consolidated mesh is instantiated by (`instance tp1 consolidatemesh ... endinstance`).
inline constexpr const char* consolidated_mesh_name = "consolidatemesh";

}  // namespace nome::scene
