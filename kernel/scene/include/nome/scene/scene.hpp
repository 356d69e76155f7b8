#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>

#include "nome/id_vector.hpp"
#include "nome/mesh/named_sharp_edge.hpp"
#include "nome/ops/boundary_mode.hpp"
#include "nome/ops/pipeline_settings.hpp"
#include "nome/scene/ast.hpp"
#include "nome/scene/ids.hpp"
#include "nome/scene/piece.hpp"
#include "nome/scene/scene_edits.hpp"
#include "nome/scene/vertex_origin.hpp"

namespace nome::scene {

// A slider: `set NAME value min max step` in `bank BANK`; expressions read it as $BANK_NAME.
struct Parameter {
  std::string bank;
  std::string name;       // within its bank
  std::string full_name;  // BANK_NAME
  double value = 0, min = 0, max = 0, step = 0;
  double file_value = 0;  // what the file's `set` gives it: `value` differs where the slider was moved
  std::string label;      // the panel's text for it (a SLIDE scale's -label); empty: its name
};

// A slider panel.
struct Bank {
  std::string name;
  std::vector<ParameterId> parameters;
  std::vector<ParameterId> shown;  // the successor's `list (ids)`, in its order; all parameters without one
};

// The built-in parameters $time and $frame (0 unless set: `nome render --time T`, the viewer's clock).
inline constexpr const char* time_parameter = "time";
inline constexpr const char* frame_parameter = "frame";

// What the file's stage blocks ask of the pipeline (`subdivision ... sd_level N`, `offset ... height H`),
// evaluated with the current slider values; the command line's own options win over them.
struct StageSettings {
  std::optional<int> subdivision_levels;
  std::optional<double> offset_distance;
  std::optional<BoundaryMode>
      boundary;  // `sd_boundary MODE` in a subdivision block, or `boundary MODE endboundary`
  // The successor's dialect: coincident vertices are welded before subdividing, as JIPCAD's merger does on
  // every subdivision (the 2016 dialect merges only when asked).
  bool welds_before_subdividing = false;
};

// Turns the merge on where the scene welds before subdividing and the settings subdivide; true when the
// scene's rule applied (the CLI and the viewer then say so with welding_note).
bool weld_before_subdividing(const StageSettings& stages, PipelineSettings& settings);
inline constexpr const char* welding_note =
    "subdividing the merged mesh: the successor's dialect welds coincident vertices first, as JIPCAD does";

// A light that a `light` statement defines and an instance statement places, as JIPCAD lights its scene:
// an ambient light adds its colour to every face; a directional one (NOME_DIRECTIONAL, and NOME_POINT and
// NOME_SPOT, which Nome draws as directional) shines along `direction`: the light's own `direction` field
// or, without one, +y, turned by the instance's transforms.
struct SceneLight {
  enum class Kind { ambient, directional };
  Kind kind = Kind::ambient;
  Color color{1.0f};
  Vec3 direction{0.0, 1.0, 0.0};  // world space, unit: where the light travels
};

// The file's render statements as picture defaults, evaluated with the current slider values; `nome
// render` and the viewer use them unless their own options say otherwise.
struct RenderDefaults {
  std::optional<Color> background;               // `backgroundcolor`, or a window's `background`
  std::optional<Color> front_color;              // `frontcolor`
  std::optional<Color> back_color;               // `backcolor`, or the `backface` colour an instance names
  std::optional<std::string> camera_projection;  // the first camera's, as written (NOME_PERSPECTIVE, ...)
  std::vector<double> camera_frustum;
  std::size_t light_count = 0;
  std::vector<SceneLight> lights;  // the placed lights; none: the viewer's own lights
};

// One top-level instance, evaluated: world-space geometry whose vertices and faces carry hierarchical
// names (`kb_t3_hc2`). The versions tell a viewer what to rebuild: geometry_version changes with any
// change, topology_version only when the faces or the vertex count change (else only positions moved).
struct SceneInstance {
  std::string name;
  Piece geometry;
  std::uint64_t geometry_version = 0;
  std::uint64_t topology_version = 0;
};

// What evaluating a scene may cost. The instance tree is counted before it is expanded: a scene over
// the budget is refused with the count (BudgetError, located at the top-level instance that crosses it)
// unless forced; even forced, a tree beyond 32-bit placement ids is an error. The faces of the pieces are
// counted as they are made (a generator makes at most 100,000 segments), and evaluation stops with a
// BudgetError and an estimate of the whole as soon as they pass the face budget (about 150 bytes a face:
// 3 GB), unless forced; a slider move over it changes nothing.
struct SceneOptions {
  std::uint64_t instance_budget = 1000000;
  std::uint64_t face_budget = 20000000;
  bool force = false;
  std::optional<Dialect> dialect =
      std::nullopt;  // `--dialect`: read the text in this spelling whatever it says
  // False for an editor that keeps the file's edits itself (SceneDocument): the scene resolves them (an
  // unknown or ambiguous name is an error) but its geometry does not show them, and take_edits() hands
  // them over without evaluating anything again.
  bool shows_edits = true;
};

// How many times a scene has been evaluated whole (read, or made again for an .anom file), in this
// process: tests check that saving evaluates nothing and loading evaluates once.
std::uint64_t scene_evaluation_count();

// An evaluated scene (report sections 3 and 6): the parsed text, the slider values, and the geometry of
// every top-level instance, kept up to date incrementally. Every instance statement of the expanded
// hierarchy is a placement; a placement of geometry (not of a group) records the parameters its
// expressions read (its own and its ancestors' transforms and colours, its definition's numbers, and
// those of the placements whose vertices it references), so that moving a slider re-evaluates only
// the placements that read it.
class Scene {
 public:
  // Parses and evaluates a .nome text. Throws SceneError listing every error found.
  static Scene from_text(std::string_view text, const std::string& file, const SceneOptions& options = {});
  // Evaluates a parsed scene (the .slf reader builds one). `warnings` are kept with the scene.
  static Scene from_ast(SceneAst ast, std::vector<Diagnostic> warnings = {},
                        const SceneOptions& options = {});

  // Applies an .anom text (saved slider values and working mesh) on top of this scene.
  void apply_anom(std::string_view text, const std::string& file);

  const std::string& file() const { return ast_.file; }
  const SceneAst& ast() const { return ast_; }
  // The file's warnings, then what evaluating its placements now warns of (a value read in another order,
  // a sweep's inexact join), each once.
  std::vector<Diagnostic> warnings() const;

  // Which spelling the text was read in, and what decided it.
  const DialectChoice& dialect() const { return ast_.dialect; }
  StageSettings stage_settings() const;
  RenderDefaults render_defaults() const;
  // The print preparation kept with the scene (`printsetup ... endprintsetup`), if any: exports apply it
  // unless told otherwise. Setting it changes no geometry; saving writes it.
  const std::optional<PrintPlacementOptions>& print_setup() const { return ast_.print_setup; }
  void set_print_setup(std::optional<PrintPlacementOptions> setup) { ast_.print_setup = setup; }

  const std::vector<Bank>& banks() const { return banks_; }
  const IdVector<ParameterId, Parameter>& parameters() const { return parameters_; }
  // By `bank_name` or `bank.name`.
  std::optional<ParameterId> find_parameter(const std::string& name) const;
  // Moves a slider and re-evaluates what reads it; returns the top-level instances whose geometry
  // changed. Throws InvalidInputError for a value outside the slider's range, SceneError when the scene
  // cannot be evaluated with the new value (the scene then keeps the previous value).
  std::vector<InstanceId> set_parameter(ParameterId parameter, double value);
  // Sets $time or $frame (any finite value) and re-evaluates what reads it, as set_parameter does.
  std::vector<InstanceId> set_clock(const std::string& name, double value);

  const std::vector<SceneInstance>& instances() const { return instances_; }
  // Every top-level instance as parts of one soup (a disjoint union; merging is a later stage).
  PolygonSoup combined_soup() const;
  // combined_soup()'s face attributes alone (its colours), without its polygons.
  Attributes combined_face_attributes() const;
  // The positions of combined_soup() alone (for Pipeline::move_input_vertices when no instance's
  // topology_version changed).
  Buffer<Vec3> combined_positions() const;

  // The file's editing data (SceneEdits): the consolidated faces by their vertices' names as written
  // (full names when SceneOptions::shows_edits is false), the deleted faces and the sharp edits by full
  // names. combined_soup() shows them, the consolidated faces as the instance `consolidatemesh`, unless
  // shows_edits is false.
  const SceneEdits& edits() const { return edits_; }
  // Hands the edits over to an editor, their vertex names in full: the scene then holds and shows none,
  // and its text has no editing statements. A scene read with shows_edits false is not evaluated again;
  // one that showed consolidated faces is (SceneError if their names no longer resolve).
  SceneEdits take_edits();

  // The full hierarchical name of the vertex a (possibly shortened) name refers to. Throws SceneError
  // naming the candidates when the name is unknown or ambiguous.
  std::string resolve_vertex_name(const std::string& name) const;

  // The sliders a vertex's position reads (its placement's and its ancestors' transforms, its
  // definition's numbers), sorted, by a unique suffix of its hierarchical name; none for an unknown or
  // ambiguous name. The viewer lists the banks a selection depends on first.
  std::vector<ParameterId> parameters_of_vertex(const std::string& name) const;

  // How the vertex of that full name is placed (vertex_origins.cpp); throws InvalidInputError for a name
  // no placement made.
  VertexOrigin vertex_origin(const std::string& full_name) const;
  // The vertex of that full name (referencing placements included), or none.
  std::optional<PlacedVertex> find_placed_vertex(const std::string& full_name) const;
  // Where it is now: valid while the faces stay (Scene::last_change_moved_vertices_only).
  Vec3 position(PlacedVertex v) const { return placements_[v.placement].world.soup.positions[v.vertex]; }
  // Where these vertices would be with the sliders at `values` (the others as they are), for an editor that
  // searches slider values: only the placements that make them are evaluated, and nothing of the scene
  // changes. Sliders that change the faces give no meaningful answer; a vertex that cannot be evaluated
  // is NaN.
  std::vector<Vec3> positions_with(std::span<const PlacedVertex> vertices,
                                   std::span<const std::pair<ParameterId, double>> values);
  // How the instance of that placement path is placed; throws InvalidInputError for an unknown path.
  InstanceOrigin instance_origin(const std::string& path) const;
  const InstanceDecl& instance_statement(const InstanceOrigin& origin) const;
  // The statement's transforms [first, end) as one matrix, at the current slider values.
  glm::dmat4 transforms_matrix(const InstanceDecl& decl, std::size_t first, std::size_t end) const;

  // Instance colours (report 8.4: colours given to selected instances). An instance is named by its
  // placement's path (`sh_tun1`); the path of the instance that placed a face (the longest placement path
  // its name starts with), none for a face no placement made.
  std::optional<std::string> instance_of_face(const std::string& face_name) const;
  // The surface the instance statement of that placement names, if any.
  std::optional<std::string> instance_surface(const std::string& path) const;
  // Names a surface in the instance statement (none: takes it out) and re-evaluates. A statement inside a
  // group is every placement of that group. Throws InvalidInputError for an unknown path or surface.
  void set_instance_surface(const std::string& path, const std::optional<std::string>& surface);
  // Gives the instance a colour: a surface named for the colour (`rgb_ff8000`), added when missing.
  void set_instance_color(const std::string& path, Color color);

  // How many placements have been evaluated since the scene was built (tests and status lines).
  std::size_t placement_evaluations() const { return placement_evaluations_; }
  // How many times a slider moved a placement's vertices without evaluating it whole.
  std::size_t vertex_moves() const { return vertex_moves_; }
  // Whether the last slider or clock change only moved vertices (names, faces and colours the same), so
  // that combined_positions() tells all of it.
  bool last_change_moved_vertices_only() const { return has_only_moved_vertices_; }

 private:
  friend class DefinitionScope;
  friend class DefinitionContext;
  friend class ValueChange;

  // What a name instantiates: a definition of a row of statement_kinds() (a group, or a kind that makes
  // geometry), or the consolidated mesh, which no statement defines.
  static constexpr Index consolidated_kind = no_index;
  struct Definition {
    Index kind;   // row of statement_kinds(), or consolidated_kind
    Index index;  // which of that kind's declarations
  };
  struct VertexRef {
    Index placement;
    Index vertex;
  };
  struct Placement {
    std::string path;
    Index parent = no_index;
    Index top = 0;               // the top-level instance it belongs to
    Index group = no_index;      // where its instance statement is: a group, or no_index for top level
    Index statement = no_index;  // index of the statement there; no_index: the consolidated mesh itself
    Definition target{no_index, no_index};
    bool references = false;  // its vertices are copied from other placements
    // Where each of its vertices was copied from, when all were (DefinitionContext::copied_from).
    std::vector<VertexRef> copied_from;
    Piece world;
    ParameterReads reads;
    std::optional<Color> color;     // the instance colour its faces took
    bool is_mirrored = false;       // its world matrix reverses its faces
    bool colors_own_faces = false;  // its definition gives faces colours (a face's own surface)
    // What its last evaluation warned of: they depend on values, so each evaluation replaces them.
    std::vector<Diagnostic> warnings;
  };
  // A placement's piece in world space and what its evaluation found on the way.
  struct Evaluated {
    Piece piece;
    ParameterReads reads;
    std::vector<VertexRef> copied_from;
    std::vector<Diagnostic> warnings;
  };
  // What moving a placement's vertices replaced.
  struct Moved {
    Buffer<Vec3> positions;
    std::vector<Diagnostic> warnings;
  };
  Scene() = default;
  // instance_colors.cpp: the placement of an instance path (throws InvalidInputError for none).
  Index placement_of_instance(const std::string& path) const;
  // scene.cpp: the sliders and the names of definitions, then the whole evaluation.
  void register_parameters(std::vector<Diagnostic>& errors);
  ParameterId add_parameter(Parameter p);
  std::vector<InstanceId> change_value(ParameterId parameter, double value);
  // scene_settings.cpp: a value of the file's stage and render statements, now.
  double current(const Value& v) const;
  void check_settings(std::vector<Diagnostic>& errors);
  void define_names(std::vector<Diagnostic>& errors);
  void rename_repeated_instances(std::vector<InstanceDecl>& instances);
  void build(std::vector<Diagnostic>& errors);
  Diagnostic located(SourceLocation at, std::string message) const;
  // "file:line:col" of a place in the scene's text, for the origins of faces.
  std::string where(SourceLocation at) const;
  // A warning about the text itself (a name defined again), kept once however often it is found.
  void add_warning(SourceLocation at, std::string message) const;

  // instance_expansion.cpp: the placements of the instance tree, counted against the budget first.
  void expand_roots(std::vector<Diagnostic>& errors);
  std::vector<double> group_expansion_sizes() const;
  // False (with the error) when `placements` cannot be numbered; throws BudgetError when over the budget.
  bool within_instance_budget(double placements, const InstanceDecl& crossing,
                              std::vector<Diagnostic>& errors) const;
  void expand(const InstanceDecl& decl, Index group, Index statement, Index parent, Index top,
              std::vector<Index>& stack, std::vector<Diagnostic>& errors);
  void expand_group(Index group, Index placement, Index top, std::vector<Index>& stack,
                    std::vector<Diagnostic>& errors);
  void report_unknown_target(const InstanceDecl& decl, std::vector<Diagnostic>& errors) const;
  // Reports the unknown names the instance tree would meet, in the order expand() would; true if any.
  bool reports_unknown_targets(std::vector<Diagnostic>& errors) const;
  const InstanceDecl* statement(const Placement& p) const;
  bool is_group(const Definition& d) const;
  bool is_leaf(const Placement& p) const { return !is_group(p.target); }

  // placement_evaluation.cpp: one placement's piece in world space, and the passes over many.
  Evaluated evaluate_placement(Index placement, std::vector<Diagnostic>& errors);
  void evaluate_definition(const Placement& p, Evaluated& out, std::vector<Diagnostic>& errors);
  glm::dmat4 world_matrix(Index placement, ParameterReads& reads) const;
  // The instance statement's own transforms, in order, as one matrix.
  glm::dmat4 instance_matrix(const InstanceDecl& decl, ParameterReads& reads) const {
    return transforms_matrix(decl, 0, decl.transforms.size(), reads);
  }
  glm::dmat4 transforms_matrix(const InstanceDecl& decl, std::size_t first, std::size_t end,
                               ParameterReads& reads) const;
  std::optional<Color> placement_color(Index placement, ParameterReads& reads) const;
  Color surface_color(const Name& surface, ParameterReads& reads) const;
  void mark_references(const std::vector<Index>& placements);
  // Returns the BudgetError message when the pieces' faces passed the face budget (evaluation stopped).
  std::optional<std::string> evaluate_all(const std::vector<Index>& placements,
                                          std::vector<Diagnostic>& errors);
  // Moves a placement's vertices alone when its generator tells its positions and its topology is unchanged;
  // hands back the previous positions and warnings. False: the placement must be evaluated whole.
  bool move_vertices(Index placement, Moved& previous);
  // The same for a placement whose vertices are all copies of other placements' (saved faces over placed
  // vertices) and whose faces take no colour of their own: copies their positions again. Its sources
  // have moved already; none of them is remade.
  bool move_copied_vertices(Index placement, Moved& previous);

  // vertex_origins.cpp: the vertex a copied vertex was copied from; none for one its placement makes.
  std::optional<VertexRef> copy_source(VertexRef ref) const;

  // vertex_names.cpp: names by unique suffix, indexed on the first lookup after they changed (a scene
  // that looks no vertex up by name, a sweep's, never pays for indexing its hundred thousand names).
  void build_vertex_index() const;
  const VertexRef* lookup_vertex(const Name& name, std::vector<Diagnostic>& errors) const;
  // A path as JIPCAD's editor writes it, each instance followed by its definition's name
  // (`iP3P_Prism3Pyr_tpyr`), without those names (`iP3P_tpyr`), as this program names placed vertices.
  std::string without_definition_names(std::string name) const;
  std::vector<std::string> resolve_deleted(const std::vector<Name>& names, std::vector<Diagnostic>& errors);
  void resolve_sharp_edits(std::vector<Diagnostic>& errors);
  // The consolidated faces' vertices by full name (errors located where the names were given).
  void resolve_consolidated(std::vector<Diagnostic>& errors);
  // The deletions and sharp edits the geometry shows: none when an editor keeps them.
  const std::vector<std::string>& shown_deletions() const;
  const std::vector<NamedSharpEdge>& shown_sharp_edits() const;

  // scene_sharpness.cpp: the top-level `sharp` statements resolved to full vertex names (a border's vertex
  // with its placement, whose border is walked when the soup is made), and the sliders their weights read.
  void resolve_text_sharps(std::vector<Diagnostic>& errors);
  // A weight must evaluate to 0 or more (`reads` collects the sliders it reads).
  void check_weight(const SharpDecl& s, std::vector<Diagnostic>& errors, ParameterReads* reads) const;
  void check_text_sharp_weights(std::vector<Diagnostic>& errors) const;
  // Marks the text's top-level creases and corners, then the viewer's sharp edits, on the combined soup.
  void add_sharpness(PolygonSoup& soup) const;

  // assembly.cpp: the placements of one top-level instance joined into its geometry.
  void assemble(Index top);
  void assemble_all();
  // Only vertices moved in the placements of `top` and no face is deleted: their positions alone.
  void assemble_positions(Index top);

  SceneAst ast_;
  SceneOptions options_;
  mutable std::vector<Diagnostic> warnings_;
  std::vector<Bank> banks_;
  IdVector<ParameterId, Parameter> parameters_;
  std::vector<double> values_;
  std::unordered_map<std::string, ParameterId> parameter_ids_;
  std::unordered_map<std::string, Definition> definitions_;
  std::unordered_map<std::string, Index> points_;
  std::unordered_map<std::string, Index> control_points_;  // share the points' names
  std::unordered_map<std::string, Index> surfaces_;
  std::vector<Placement> placements_;
  std::vector<SceneInstance> instances_;
  mutable std::unordered_map<std::string, std::vector<VertexRef>> vertex_suffixes_;
  mutable bool is_vertex_index_current_ = false;
  SceneEdits edits_;
  std::string consolidated_file_;  // where the consolidated faces' names are located, if not in file()
  struct TextSharp {
    Index decl;                         // of ast_.sharps
    std::vector<std::string> vertices;  // full names
    Index placement = no_index;         // a border's: the placement whose border it is
  };
  std::vector<TextSharp> text_sharps_;
  ParameterReads text_sharp_reads_;  // sorted
  std::size_t placement_evaluations_ = 0;
  std::size_t vertex_moves_ = 0;
  bool has_only_moved_vertices_ = false;
};

}  // namespace nome::scene
