#include "viewer/tools/text_pane_tool.hpp"

#include "nome/error.hpp"
#include "nome/io/read_scene.hpp"

namespace nome::viewer {

void TextPaneTool::bind(ToolContext& context) {
  LayoutSettings& layout = context.layout_settings;
  context.actions.bind(Action::toggle_text_pane, [&layout] {
    layout.is_pane_shown = !layout.is_pane_shown;
    return true;
  });
  context.actions.bind(Action::apply_text, [this, &context] { return apply_text(context); });
  context.actions.bind(Action::save_text, [this, &context] { return save_text(context); });
}

bool TextPaneTool::apply_text(ToolContext& context) {
  sync(context);
  const bool is_applied = context.sessions.apply_text(pane_.text());
  sync(context);
  context.update_stage();
  return is_applied;
}

bool TextPaneTool::save_text(ToolContext& context) {
  sync(context);
  if (!context.sessions.save_text(pane_.text())) return false;
  pane_.saved();
  sync(context);
  context.update_stage();
  return true;
}

void TextPaneTool::sync(ToolContext& context) {
  SessionController& sessions = context.sessions;
  pane_.sync(sessions.path(), sessions.has_scene(), sessions.disk_version());
  // A drag (or its undo) rewrote the scene's text: the pane shows it, not saved.
  if (sessions.scene_text_version() != seen_scene_text_) {
    seen_scene_text_ = sessions.scene_text_version();
    if (pane_.is_scene()) pane_.set_text(sessions.scene_text());
  }
  sessions.set_unapplied_text(pane_.is_scene() && pane_.text() != sessions.scene_text());
  pane_.set_marks(sessions.drag_marks());
  // The marks follow every evaluation of the file: Apply, Save, a reload after another program's change.
  pane_.set_errors(sessions.text_errors());
}

void TextPaneTool::before_draw(ToolContext& context) {
  sync(context);
  pane_.set_statement(selection_statement(context));
}

std::optional<scene::SourcePlace> TextPaneTool::selection_statement(const ToolContext& context) const {
  const StageResult* shown = context.stage.shown();
  const Session* session = context.sessions.session();
  if (!shown || !session) return std::nullopt;
  // Every stage's faces carry the input face they came from; a mesh still made from an older input may
  // name faces the input no longer has (face_statement then finds none) or others for a moment.
  const PolygonSoup& soup = session->polygons();
  const Mesh& mesh = *shown->mesh;
  const Selection& selection = context.selection;
  const bool is_face_mode = selection.mode() == SelectionMode::face;
  if (is_face_mode && !selection.faces().empty())
    return scene::shown_face_statement(mesh, soup, selection.faces().back());
  if (!is_face_mode && !selection.vertices().empty())
    return scene::vertex_statement(mesh, soup, selection.vertices().back());
  return std::nullopt;
}

std::string TextPaneTool::status_text(const ToolContext& context) const {
  const std::optional<scene::SourcePlace> place = selection_statement(context);
  if (!place) return {};
  // "line 7", with the file's name when it is another than the open one.
  std::string line = "line " + std::to_string(place->location.line);
  if (pane_.is_in_file(place->file)) return line;
  return std::filesystem::path(place->file).filename().string() + " " + line;
}

std::string TextPaneTool::state_text(const ToolContext& context) const {
  return pane_.state_text(context.layout_settings.is_pane_shown);
}

void TextPaneTool::draw_pane(ToolContext& context) {
  const TextPaneRequest request = pane_.draw();
  if (request.loads_from_disk) pane_.load_from_disk();
  if (request.save)
    save_text(context);
  else if (request.apply)
    apply_text(context);
}

bool TextPaneTool::show_place(ToolContext& context, const scene::SourcePlace& place) {
  sync(context);
  if (!pane_.is_scene() || !pane_.is_in_file(place.file)) {
    const SessionController& sessions = context.sessions;
    context.log.info(place.file + " is not the open scene's text: the text pane shows " +
                     (sessions.has_scene() ? sessions.path().filename().string() : std::string("no scene")));
    return true;
  }
  context.layout_settings.is_pane_shown = true;
  pane_.go_to(place.location);
  return true;
}

std::optional<bool> TextPaneTool::run_script(ToolContext& context, const ScriptCommand& command) {
  using Kind = ScriptCommand::Kind;
  if (command.kind == Kind::text_set) {
    sync(context);
    if (!pane_.is_scene()) throw InvalidInputError("text-set: the text pane shows scene files only");
    pane_.set_text(read_text_file(command.words[0]));
    return true;
  }
  if (command.kind != Kind::log_click) return std::nullopt;
  const auto& messages = context.log.messages();
  const int back = int(command.numbers[0]);
  if (back < 1 || std::size_t(back) > messages.size())
    throw InvalidInputError("log-click: the log has " + std::to_string(messages.size()) + " messages");
  const Message& m = messages[messages.size() - std::size_t(back)];
  if (!m.place) throw InvalidInputError("log-click: '" + m.text + "' names no place");
  return show_place(context, *m.place);
}

}  // namespace nome::viewer
