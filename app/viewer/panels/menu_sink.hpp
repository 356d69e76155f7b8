#pragma once

#include <string>

namespace nome::viewer {

// What the menu bar is drawn through: ImGui in the window (ImGuiMenuSink), a recorder in tests, so that
// what each menu holds, what is enabled and what choosing an item does can be checked without a screen.
class MenuSink {
 public:
  virtual ~MenuSink() = default;
  // The bar and its menus: true when open (the items follow, then end_*).
  virtual bool begin_bar() = 0;
  virtual void end_bar() = 0;
  virtual bool begin_menu(const char* label, bool is_enabled = true) = 0;
  virtual void end_menu() = 0;
  // An item; returns whether it was chosen this frame. `is_checked` shows a check mark.
  virtual bool item(const char* label, const std::string& shortcut, bool is_checked = false,
                    bool is_enabled = true) = 0;
  // An item that turns `value` on and off; returns whether it was chosen (and `value` flipped).
  bool toggle(const char* label, const std::string& shortcut, bool& value) {
    if (!item(label, shortcut, value)) return false;
    value = !value;
    return true;
  }
  virtual void separator() = 0;
  // A line of greyed text (a hint under the items).
  virtual void note(const std::string& text) = 0;
};

// Draws with ImGui's main menu bar.
class ImGuiMenuSink final : public MenuSink {
 public:
  bool begin_bar() override;
  void end_bar() override;
  bool begin_menu(const char* label, bool is_enabled) override;
  void end_menu() override;
  bool item(const char* label, const std::string& shortcut, bool is_checked, bool is_enabled) override;
  void separator() override;
  void note(const std::string& text) override;
};

}  // namespace nome::viewer
