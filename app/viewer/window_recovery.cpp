#define GLFW_INCLUDE_NONE  // GL comes from glad (render/gl.hpp)
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "viewer/window.hpp"

// Crash recovery in the window: the autosave of the open scene, and the offer to restore what a viewer
// that did not end cleanly left behind.
namespace nome::viewer {

void Window::update_autosave() {
  // Until the offer is answered the session holds the file as saved, and the recovery file must stay.
  if (!session_ || recovery_offer_) return;
  try {
    autosave_.update(*session_, glfwGetTime());
  } catch (const std::exception& e) {
    log_.warning("autosave: " + std::string(e.what()));
  }
}

void Window::draw_recovery_prompt() {
  const char* title = "Restore unsaved changes?";
  if (recovery_offer_ && !ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  if (!recovery_offer_) {  // answered by a script
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return;
  }
  ImGui::Text("Nome did not end cleanly while %s had unsaved changes.",
              session_->path().filename().string().c_str());
  ImGui::TextUnformatted("Restore them from the recovery file, or discard them?");
  if (ImGui::Button("Restore")) answer_recovery(true);
  ImGui::SameLine();
  if (ImGui::Button("Discard")) answer_recovery(false);
  if (!recovery_offer_) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

void Window::answer_recovery(bool restore) {
  const std::filesystem::path recovery = *recovery_offer_;
  recovery_offer_.reset();
  const std::filesystem::path document = session_->path();
  if (!restore) {
    autosave_.discard(document);
    log_.info("discarded the recovered changes of " + document.filename().string());
    return;
  }
  try {
    Session restored = Session::restore(document, recovery);
    session_.emplace(std::move(restored));
    selection_.clear();
    has_request_ = false;
    log_.info("restored the unsaved changes of " + document.filename().string() + " (not saved yet)");
  } catch (const std::exception& e) {
    // The recovery file stays for the user to look at.
    log_.error("cannot restore " + recovery.string() + ": " + e.what());
  }
}

}  // namespace nome::viewer
