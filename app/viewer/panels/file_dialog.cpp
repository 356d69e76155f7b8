#include "viewer/panels/file_dialog.hpp"

#include <algorithm>
#include <cstring>

#include <imgui.h>

#include "nome/io/file_extension.hpp"

namespace nome::viewer {

void FileBrowser::open(std::string title, std::filesystem::path folder, std::vector<std::string> extensions,
                       std::string accept_label, std::string name) {
  title_ = std::move(title);
  accept_label_ = std::move(accept_label);
  extensions_ = std::move(extensions);
  std::snprintf(name_, sizeof name_, "%s", name.c_str());
  list(folder.empty() ? std::filesystem::current_path() : folder);
  is_open_ = true;
  is_new_ = true;
}

bool FileBrowser::matches(const std::filesystem::path& file) const {
  return std::find(extensions_.begin(), extensions_.end(), lower_extension(file)) != extensions_.end();
}

void FileBrowser::list(const std::filesystem::path& folder) {
  std::error_code ec;
  folder_ = std::filesystem::weakly_canonical(folder, ec);
  if (ec) folder_ = folder;
  folders_.clear();
  files_.clear();
  error_.clear();
  for (std::filesystem::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec)) {
    const auto& path = it->path();
    if (path.filename().string().starts_with(".")) continue;
    if (it->is_directory(ec))
      folders_.push_back(path);
    else if (matches(path))
      files_.push_back(path);
  }
  if (ec) error_ = "cannot list " + folder_.string() + ": " + ec.message();
  std::sort(folders_.begin(), folders_.end());
  std::sort(files_.begin(), files_.end());
}

std::optional<std::filesystem::path> FileBrowser::draw() {
  if (!is_open_) return std::nullopt;
  if (is_new_) {
    ImGui::OpenPopup(title_.c_str());
    is_new_ = false;
  }
  std::optional<std::filesystem::path> chosen;
  ImGui::SetNextWindowSize(ImVec2(560, 420), ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal(title_.c_str(), &is_open_)) return std::nullopt;
  ImGui::TextUnformatted(folder_.string().c_str());
  ImGui::BeginChild("entries", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 2), true);
  if (ImGui::Selectable("../")) list(folder_.parent_path());
  for (const auto& folder : folders_)
    if (ImGui::Selectable((folder.filename().string() + "/").c_str())) {
      list(folder);
      break;
    }
  for (const auto& file : files_) {
    const std::string name = file.filename().string();
    if (ImGui::Selectable(name.c_str(), name == name_, ImGuiSelectableFlags_AllowDoubleClick)) {
      std::snprintf(name_, sizeof name_, "%s", name.c_str());
      if (ImGui::IsMouseDoubleClicked(0)) chosen = file;
    }
  }
  ImGui::EndChild();
  if (!error_.empty()) ImGui::TextColored(ImVec4(0.9f, 0.2f, 0.2f, 1), "%s", error_.c_str());
  ImGui::SetNextItemWidth(-160);
  const bool entered = ImGui::InputText("##name", name_, sizeof name_, ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button(accept_label_.c_str()) || entered) && name_[0] != '\0') {
    const std::filesystem::path typed(name_);
    chosen = typed.is_absolute() ? typed : folder_ / typed;
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) is_open_ = false;
  if (chosen) is_open_ = false;
  if (!is_open_) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  return chosen;
}

}  // namespace nome::viewer
