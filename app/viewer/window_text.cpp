#include <imgui.h>

#include "nome/error.hpp"
#include "nome/io/read_scene.hpp"
#include "viewer/window.hpp"

// The scene text pane in the window: its keys, its panel, the selection's statement, and the log's places.
namespace nome::viewer {

void Window::bind_text_actions() {
  actions_.bind(Action::toggle_text_pane, [this] {
    layout_settings_.is_text_shown = !layout_settings_.is_text_shown;
    return true;
  });
  actions_.bind(Action::apply_text, [this] { return apply_text(); });
  actions_.bind(Action::save_text, [this] { return save_text(); });
}

bool Window::apply_text() {
  sync_text_pane();
  const bool is_applied = sessions_.apply_text(text_pane_.text());
  sync_text_pane();
  update_stage();
  return is_applied;
}

bool Window::save_text() {
  sync_text_pane();
  if (!sessions_.save_text(text_pane_.text())) return false;
  text_pane_.saved();
  sync_text_pane();
  update_stage();
  return true;
}

void Window::sync_text_pane() {
  text_pane_.sync(sessions_.path(), sessions_.has_scene(), sessions_.disk_version());
  // The marks follow every evaluation of the file: Apply, Save, a reload after another program's change.
  text_pane_.set_errors(sessions_.text_errors());
}

std::optional<scene::SourcePlace> Window::selection_statement() const {
  const StageResult* shown = stage_.shown();
  const Session* session = sessions_.session();
  if (!shown || !session || !is_editable(shown->stage)) return std::nullopt;
  // The shown mesh has the input's faces in their order, unless it is still one made from an older input.
  const PolygonSoup& soup = session->polygons();
  const Mesh& mesh = *shown->mesh;
  if (mesh.num_faces() != soup.num_faces() || mesh.face_names() != soup.face_names) return std::nullopt;
  const bool is_face_mode = selection_.mode() == SelectionMode::face;
  if (is_face_mode && !selection_.faces().empty())
    return scene::face_statement(soup, selection_.faces().back());
  if (!is_face_mode && !selection_.vertices().empty())
    return scene::vertex_statement(mesh, soup, selection_.vertices().back());
  return std::nullopt;
}

std::string Window::statement_text(const std::optional<scene::SourcePlace>& place) const {
  if (!place) return {};
  const std::string line = "line " + std::to_string(place->location.line);
  if (text_pane_.is_in_file(place->file)) return line;
  return std::filesystem::path(place->file).filename().string() + " " + line;
}

void Window::show_place(const scene::SourcePlace& place) {
  sync_text_pane();
  if (!text_pane_.is_scene() || !text_pane_.is_in_file(place.file)) {
    log_.info(place.file + " is not the open scene's text: the text pane shows " +
              (sessions_.has_scene() ? sessions_.path().filename().string() : std::string("no scene")));
    return;
  }
  layout_settings_.is_text_shown = true;
  text_pane_.go_to(place.location);
}

void Window::set_text(const std::filesystem::path& path) {
  sync_text_pane();
  if (!text_pane_.is_scene()) throw InvalidInputError("text-set: the text pane shows scene files only");
  text_pane_.set_text(read_text_file(path));
}

bool Window::click_log(int back) {
  const auto& messages = log_.messages();
  if (back < 1 || std::size_t(back) > messages.size())
    throw InvalidInputError("log-click: the log has " + std::to_string(messages.size()) + " messages");
  const Message& m = messages[messages.size() - std::size_t(back)];
  if (!m.place) throw InvalidInputError("log-click: '" + m.text + "' names no place");
  show_place(*m.place);
  return true;
}

}  // namespace nome::viewer
