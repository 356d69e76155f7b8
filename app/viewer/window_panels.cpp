#include <algorithm>
#include <cmath>

#define GLFW_INCLUDE_NONE  // GL comes from glad (render/gl.hpp)
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "nome/mesh/topology_report.hpp"
#include "viewer/window.hpp"

// The ImGui side of the window: menu, panels, status bar, help overlay and prompts.
namespace nome::viewer {
namespace {

const ImVec4 error_color(0.85f, 0.15f, 0.15f, 1.0f);
const ImVec4 warning_color(0.80f, 0.55f, 0.05f, 1.0f);

float status_bar_height() {
  return ImGui::GetFrameHeight() + 4.0f;
}

}  // namespace

void Window::draw_panels() {
  draw_menu();
  draw_control_panel();
  draw_slider_panels();
  draw_topology_panel();
  if (show_log_) draw_log_panel();
  draw_status_bar();
  if (show_help_) draw_help_overlay();
  draw_unsaved_prompt();
  draw_progress();
  if (const auto chosen = browser_.draw()) {
    if (browser_purpose_ == BrowserPurpose::open) {
      request_open(*chosen);
    } else if (browser_purpose_ == BrowserPurpose::save) {
      save(*chosen);
    } else {
      try {
        export_mesh(*chosen);
      } catch (const std::exception& e) {
        log_.error(e.what());
      }
    }
  }
}

void Window::draw_menu() {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Open...", "Ctrl+O")) keys_.press("Ctrl+O");
    if (ImGui::BeginMenu("Open Recent", !recent_.files().empty())) {
      for (std::size_t i = 0; i < recent_.files().size(); ++i) {
        const std::string shortcut = i < 4 ? "Ctrl+" + std::to_string(i + 1) : "";
        if (ImGui::MenuItem(recent_.files()[i].string().c_str(), shortcut.c_str())) {
          request_open(recent_.files()[i]);
          break;
        }
      }
      ImGui::EndMenu();
    }
    const bool is_scene = session_ && session_->scene();
    if (ImGui::MenuItem("Save", "Ctrl+S", false, is_scene)) save(std::nullopt);
    if (ImGui::MenuItem("Save As...", "Ctrl+Shift+S", false, is_scene)) keys_.press("Ctrl+Shift+S");
    if (ImGui::MenuItem("Export STL / OBJ...", "Ctrl+E", false, session_.has_value())) keys_.press("Ctrl+E");
    if (ImGui::MenuItem("Screenshot", "P")) keys_.press("P");
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) request_quit();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    const bool has_document = session_.has_value();
    if (ImGui::MenuItem("Undo", "Ctrl+Z", false, has_document && session_->document().can_undo()))
      run_action("undo");
    if (ImGui::MenuItem("Redo", "Ctrl+Y", false, has_document && session_->document().can_redo()))
      run_action("redo");
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    bool is_wire = display_.show_wireframe;
    if (ImGui::MenuItem("Faces", "W", &display_.show_faces) && !display_.show_faces)
      display_.show_wireframe = true;
    if (ImGui::MenuItem("Wireframe overlay", nullptr, &is_wire)) display_.show_wireframe = is_wire;
    bool is_flat = display_.shading == render::Shading::flat;
    if (ImGui::MenuItem("Flat shading", "S", &is_flat))
      display_.shading = is_flat ? render::Shading::flat : render::Shading::smooth;
    bool is_culled = display_.back_faces == render::BackFacePolicy::cull;
    if (ImGui::MenuItem("Back-face culling", "X", &is_culled))
      display_.back_faces = is_culled ? render::BackFacePolicy::cull : render::BackFacePolicy::different;
    bool is_back_colored = display_.back_faces == render::BackFacePolicy::different;
    if (ImGui::MenuItem("Back faces in their own colour", nullptr, &is_back_colored))
      display_.back_faces =
          is_back_colored ? render::BackFacePolicy::different : render::BackFacePolicy::same;
    ImGui::MenuItem("Möbius edges", nullptr, &display_.show_mobius_edges);
    ImGui::MenuItem("Borders", nullptr, &display_.show_borders);
    ImGui::MenuItem("Instance colours", nullptr, &display_.use_face_colors);
    ImGui::Separator();
    if (ImGui::MenuItem("Frame all", "F")) frame_all();
    if (ImGui::MenuItem("Reset view", "Ctrl+H")) reset_view();
    if (ImGui::MenuItem("Front", "Keypad1")) set_view(0.0, 0.0);
    if (ImGui::MenuItem("Right", "Keypad3")) set_view(90.0, 0.0);
    if (ImGui::MenuItem("Top", "Keypad7")) set_view(0.0, 90.0);
    ImGui::Separator();
    ImGui::MenuItem("Log panel", "L", &show_log_);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Keys and mouse", "F1")) show_help_ = !show_help_;
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void Window::draw_control_panel() {
  ImGui::SetNextWindowPos(ImVec2(8, 30), ImGuiCond_FirstUseEver);
  // Fits its content as sections open and close (every widget has a fixed width: no feedback loop).
  if (!ImGui::Begin("Controls", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  if (ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) {
    int mode = int(selection_.mode());
    const char* labels[] = {"vertex", "face", "border (whole)", "border (partial)"};
    for (int i = 0; i < 4; ++i) {
      if (ImGui::RadioButton(labels[i], &mode, i)) selection_.set_mode(SelectionMode(i));
      if (i % 2 == 0) ImGui::SameLine(130);
    }
    ImGui::Text("%zu vertices, %zu faces, %zu borders", selection_.vertices().size(),
                selection_.faces().size(), selection_.borders().size());
    if (ImGui::Button("Clear selection")) {
      selection_.clear();
      refresh_selection();
    }
  }
  if (ImGui::CollapsingHeader("Stage", ImGuiTreeNodeFlags_DefaultOpen)) {
    int stage = int(settings_.stage);
    const char* stages[] = {to_string(Stage::scene), to_string(Stage::merged), to_string(Stage::subdivided),
                            to_string(Stage::offset), to_string(Stage::subdivided_offset)};
    ImGui::SetNextItemWidth(200);
    if (ImGui::Combo("show", &stage, stages, IM_ARRAYSIZE(stages))) settings_.stage = Stage(stage);
    if (ImGui::Button("Merge")) settings_.stage = Stage::merged;
    ImGui::SameLine();
    float tolerance = float(settings_.merge_tolerance);
    ImGui::SetNextItemWidth(120);
    if (ImGui::InputFloat("tolerance", &tolerance, 0.0f, 0.0f, "%.5f", ImGuiInputTextFlags_EnterReturnsTrue))
      settings_.merge_tolerance = std::max(0.0f, tolerance);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("0: a thousandth of the scene's size");
    ImGui::Checkbox("subdivide the merged mesh", &settings_.merge);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("off: the scene's pieces are subdivided each on its own");
    ImGui::SetNextItemWidth(120);
    ImGui::SliderInt("subdivision", &settings_.subdivision_levels, 0, 6);
    ImGui::SameLine();
    int rule = int(settings_.rule);
    const char* rules[] = {"classic", "report"};
    ImGui::SetNextItemWidth(80);
    if (ImGui::Combo("##rule", &rule, rules, IM_ARRAYSIZE(rules))) settings_.rule = SubdivisionRule(rule);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("smooth-vertex rule: Catmull-Clark's or the 2016 report's");
    float distance = float(settings_.offset_distance);
    ImGui::SetNextItemWidth(120);
    if (ImGui::SliderFloat("offset", &distance, 0.001f, 1.0f, "%.4f", ImGuiSliderFlags_Logarithmic))
      settings_.offset_distance = std::max(distance, 1e-6f);
    ImGui::SetNextItemWidth(120);
    ImGui::SliderInt("subdivision after offset", &settings_.subdivision_after, 0, 4);
  }
  if (ImGui::CollapsingHeader("Edit", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (!is_editable(settings_.stage))
      ImGui::TextDisabled("%s is computed: edit on scene or merged", to_string(settings_.stage));
    ImGui::BeginDisabled(!can_edit());
    if (ImGui::Button("Add polygon")) run_action("add-polygon");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("through the selected vertices, in click order (Enter)");
    ImGui::SameLine();
    if (ImGui::Button("Delete faces")) run_action("delete");
    if (ImGui::Button("Zip borders")) run_action("zip");
    ImGui::SameLine();
    float penalty = float(zipper_options_.triangle_penalty);
    ImGui::SetNextItemWidth(110);
    if (ImGui::SliderFloat("triangle penalty", &penalty, 1.0f, 3.0f, "%.2f"))
      zipper_options_.triangle_penalty = penalty;
    ImGui::EndDisabled();
    ImGui::BeginDisabled(!session_ || session_->document().temporary_faces().empty());
    if (ImGui::Button("Accept")) run_action("accept");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("move the temporary faces into the consolidated mesh");
    ImGui::SameLine();
    if (ImGui::Button("Clear temporary")) run_action("clear");
    ImGui::EndDisabled();
    if (session_)
      ImGui::Text(
          "%zu temporary, %zu consolidated, %zu deleted", session_->document().temporary_faces().size(),
          session_->document().consolidated_faces().size(), session_->document().deleted_faces().size());
  }
  if (ImGui::CollapsingHeader("Colours")) {
    ImGui::ColorEdit3("default", &display_.front_color.x, ImGuiColorEditFlags_NoInputs);
    ImGui::ColorEdit3("back faces", &display_.back_color.x, ImGuiColorEditFlags_NoInputs);
    if (ImGui::ColorEdit3("selected", &display_.selection_color.x, ImGuiColorEditFlags_NoInputs))
      refresh_selection();
    ImGui::ColorEdit3("background", &display_.background.x, ImGuiColorEditFlags_NoInputs);
    ImGui::ColorEdit3("rim lines", &rim_color_.x, ImGuiColorEditFlags_NoInputs);
    bool is_recoloured = ImGui::ColorEdit3("temporary", &temporary_color_.x, ImGuiColorEditFlags_NoInputs);
    is_recoloured |= ImGui::ColorEdit3("consolidated", &consolidated_color_.x, ImGuiColorEditFlags_NoInputs);
    if (is_recoloured) apply_face_colors();
  }
  ImGui::End();
}

void Window::draw_slider_panels() {
  const scene::Scene* scene = session_ ? session_->scene() : nullptr;
  if (!scene) return;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  float y = 206.0f;  // below the topology panel
  for (const scene::Bank& bank : scene->banks()) {
    ImGui::SetNextWindowPos(ImVec2(size.x - 338, y), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
    y += 40.0f + 26.0f * float(bank.parameters.size());
    if (!ImGui::Begin(("bank " + bank.name).c_str())) {
      ImGui::End();
      continue;
    }
    for (Index id : bank.parameters) {
      const scene::Parameter& p = scene->parameters()[id];
      float value = float(p.value);
      ImGui::SetNextItemWidth(-70);
      // Ctrl+click on a slider types an exact value (ImGui's own behaviour).
      if (ImGui::SliderFloat(p.name.c_str(), &value, float(p.min), float(p.max), "%.4g")) {
        double snapped = value;
        if (p.step > 0.0) snapped = p.min + std::round((value - p.min) / p.step) * p.step;
        snapped = std::clamp(snapped, p.min, p.max);
        if (snapped != p.value) set_slider(id, snapped);
      }
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("$%s: %g .. %g, step %g", p.full_name.c_str(), p.min, p.max, p.step);
    }
    ImGui::End();
  }
}

void Window::draw_topology_panel() {
  if (!shown_mesh()) return;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x - 338, 30), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(330, 170), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Topology")) {
    ImGui::End();
    return;
  }
  const TopologyReport& report = shown_->topology;
  ImGui::Text("V %u  E %u  F %u  chi %lld", report.vertices, report.edges, report.faces, report.chi);
  ImGui::Text("%s, %u borders, %u Möbius edges", report.orientable ? "orientable" : "non-orientable",
              report.borders, report.mobius_edges);
  if (ImGui::BeginTable("components", 8, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
    for (const char* title : {"#", "V", "E", "F", "chi", "or.", "b", "g"}) ImGui::TableSetupColumn(title);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < report.components.size() && i < 64; ++i) {
      const ComponentTopology& c = report.components[i];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("%zu", i);
      ImGui::TableNextColumn();
      ImGui::Text("%u", c.vertices);
      ImGui::TableNextColumn();
      ImGui::Text("%u", c.edges);
      ImGui::TableNextColumn();
      ImGui::Text("%u", c.faces);
      ImGui::TableNextColumn();
      ImGui::Text("%lld", c.chi);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(c.orientable ? "yes" : "no");
      ImGui::TableNextColumn();
      ImGui::Text("%u", c.borders);
      ImGui::TableNextColumn();
      ImGui::Text("%lld", c.genus);
    }
    ImGui::EndTable();
  }
  if (report.components.size() > 64) ImGui::Text("... %zu components in all", report.components.size());
  ImGui::End();
}

void Window::draw_log_panel() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  const float height = 130.0f;
  ImGui::SetNextWindowPos(ImVec2(8, size.y - status_bar_height() - height - 6), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(std::min(size.x - 16, 760.0f), height), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Log", &show_log_)) {
    ImGui::End();
    return;
  }
  for (const Message& m : log_.messages()) {
    const bool is_colored = m.level != MessageLevel::info;
    if (is_colored)
      ImGui::PushStyleColor(ImGuiCol_Text, m.level == MessageLevel::error ? error_color : warning_color);
    const char* prefix = m.level == MessageLevel::error     ? "error: "
                         : m.level == MessageLevel::warning ? "warning: "
                                                            : "";
    if (m.count > 1)
      ImGui::TextWrapped("%s%s (x%zu)", prefix, m.text.c_str(), m.count);
    else
      ImGui::TextWrapped("%s%s", prefix, m.text.c_str());
    if (is_colored) ImGui::PopStyleColor();
  }
  if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
  ImGui::End();
}

void Window::draw_status_bar() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0, size.y - status_bar_height()));
  ImGui::SetNextWindowSize(ImVec2(size.x, status_bar_height()));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  ImGui::Begin("##status", nullptr, flags);
  if (session_ && shown_mesh()) {
    const Mesh& mesh = *shown_mesh();
    ImGui::Text("%s%s | %s stage: %u V, %u F | %s mode", session_->path().filename().string().c_str(),
                session_->is_modified() ? " *" : "", to_string(shown_->stage), mesh.num_vertices(),
                mesh.num_faces(), to_string(selection_.mode()));
  } else {
    ImGui::TextUnformatted("no file: File > Open (Ctrl+O) or drop a file on the window");
  }
  if (const Message* latest = log_.latest()) {
    ImGui::SameLine();
    ImGui::TextUnformatted("|");
    ImGui::SameLine();
    if (latest->level == MessageLevel::error)
      ImGui::TextColored(error_color, "%s", latest->text.c_str());
    else if (latest->level == MessageLevel::warning)
      ImGui::TextColored(warning_color, "%s", latest->text.c_str());
    else
      ImGui::TextUnformatted(latest->text.c_str());
  }
  ImGui::End();
}

void Window::draw_help_overlay() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.92f);
  if (!ImGui::Begin("Keys and mouse (? or F1 closes)", &show_help_,
                    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return;
  }
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    const char* mouse[][2] = {{"left drag", "turn (arcball)"},
                              {"right / middle drag", "pan"},
                              {"wheel", "zoom"},
                              {"left click", "select in the current mode (again: deselect)"},
                              {"right click", "clear the selection"},
                              {"double click", "orbit around the point clicked"}};
    for (const auto& row : mouse) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row[0]);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row[1]);
    }
    for (const KeyBinding& b : keys_.bindings()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(b.label.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(b.description.c_str());
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

void Window::draw_progress() {
  if (!job_.is_busy() || job_.seconds_running() < 0.03) return;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, 40.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("##progress", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  const char* spinner = "|/-\\";
  ImGui::Text("%c computing the %s ... %.1f s", spinner[int(job_.seconds_running() * 8.0) % 4], "stage",
              job_.seconds_running());
  ImGui::End();
}

void Window::draw_unsaved_prompt() {
  // One popup for both questions (its id after ###); the title says which.
  const char* id = "###unsaved";
  if (unsaved_prompt_ && !ImGui::IsPopupOpen(id)) ImGui::OpenPopup(id);
  const std::string title = std::string(unsaved_prompt_ && unsaved_prompt_->open ? "Open without saving?"
                                                                                 : "Quit without saving?") +
                            id;
  if (!ImGui::BeginPopupModal(title.c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  if (!unsaved_prompt_) {  // answered by a script
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return;
  }
  const bool is_open = unsaved_prompt_->open.has_value();
  ImGui::TextUnformatted("The scene has unsaved changes.");
  if (is_open) ImGui::Text("Open %s instead?", unsaved_prompt_->open->filename().string().c_str());
  if (session_ && session_->scene() && ImGui::Button(is_open ? "Save, then open" : "Save and quit"))
    answer_unsaved_prompt(UnsavedAnswer::save);
  ImGui::SameLine();
  if (ImGui::Button(is_open ? "Open without saving" : "Quit without saving"))
    answer_unsaved_prompt(UnsavedAnswer::discard);
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) answer_unsaved_prompt(UnsavedAnswer::cancel);
  if (!unsaved_prompt_) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace nome::viewer
