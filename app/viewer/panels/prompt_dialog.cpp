#include "viewer/panels/prompt_dialog.hpp"

#include <string>

#include <imgui.h>

namespace nome::viewer {

UnsavedQuestion Prompts::take_unsaved() {
  UnsavedQuestion question = *unsaved_;
  unsaved_.reset();
  return question;
}

std::optional<UnsavedAnswer> Prompts::draw_unsaved(bool can_save) {
  // One popup for both questions (its id after ###); the title says which.
  const char* id = "###unsaved";
  if (unsaved_ && !ImGui::IsPopupOpen(id)) ImGui::OpenPopup(id);
  const bool is_open = unsaved_ && unsaved_->open;
  const std::string title = std::string(is_open ? "Open without saving?" : "Quit without saving?") + id;
  if (!ImGui::BeginPopupModal(title.c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return std::nullopt;
  if (!unsaved_) {  // answered by a script
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return std::nullopt;
  }
  std::optional<UnsavedAnswer> answer;
  ImGui::TextUnformatted("The scene has unsaved changes.");
  if (is_open) ImGui::Text("Open %s instead?", unsaved_->open->filename().string().c_str());
  if (can_save && ImGui::Button(is_open ? "Save, then open" : "Save and quit")) answer = UnsavedAnswer::save;
  ImGui::SameLine();
  if (ImGui::Button(is_open ? "Open without saving" : "Quit without saving")) answer = UnsavedAnswer::discard;
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) answer = UnsavedAnswer::cancel;
  if (answer) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  return answer;
}

std::optional<bool> Prompts::draw_recovery(bool is_offered, const std::filesystem::path& document) {
  const char* title = "Restore unsaved changes?";
  if (is_offered && !ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return std::nullopt;
  if (!is_offered) {  // answered by a script
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return std::nullopt;
  }
  std::optional<bool> restore;
  ImGui::Text("Nome did not end cleanly while %s had unsaved changes.", document.filename().string().c_str());
  ImGui::TextUnformatted("Restore them from the recovery file, or discard them?");
  if (ImGui::Button("Restore")) restore = true;
  ImGui::SameLine();
  if (ImGui::Button("Discard")) restore = false;
  if (restore) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  return restore;
}

}  // namespace nome::viewer
