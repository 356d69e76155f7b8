#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "viewer/tools/text_pane.hpp"
#include "viewer/tools/tool.hpp"

namespace nome::viewer {

// The scene text pane as a tool: the pane beside the left sidebar, its keys (Ctrl+T, Ctrl+Enter), the
// script's text-set and log-click, the statement of the selected face or vertex in the status bar, and
// the pane's unsaved text, which quitting asks about.
class TextPaneTool final : public Tool {
 public:
  void bind(ToolContext& context) override;
  void before_draw(ToolContext& context) override;
  std::optional<bool> run_script(ToolContext& context, const ScriptCommand& command) override;
  std::string status_text(const ToolContext& context) const override;
  std::string state_text(const ToolContext& context) const override;
  std::string pane_title() const override { return "Scene text"; }
  void draw_pane(ToolContext& context) override;
  bool show_place(ToolContext& context, const scene::SourcePlace& place) override;
  bool has_unsaved_changes() const override { return pane_.is_modified(); }
  bool save_changes(ToolContext& context) override { return save_text(context); }

  const TextPane& pane() const { return pane_; }

 private:
  bool apply_text(ToolContext& context);
  bool save_text(ToolContext& context);
  void sync(ToolContext& context);
  // The statement that made the selected face or vertex (the last clicked), on the scene or merged stage.
  std::optional<scene::SourcePlace> selection_statement(const ToolContext& context) const;

  TextPane pane_;
  std::uint64_t seen_scene_text_ = 0;  // SessionController::scene_text_version shown
};

}  // namespace nome::viewer
