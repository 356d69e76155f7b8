#pragma once

#include <cstddef>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "nome/scene/source_place.hpp"

namespace nome::viewer {

enum class MessageLevel { info, warning, error };

struct Message {
  MessageLevel level = MessageLevel::info;
  std::string text;  // errors about a file start with file:line:col
  std::size_t count = 1;
  // Where a message about user content points: clicking it in the log shows the place in the text pane.
  std::optional<scene::SourcePlace> place;
};

// The log panel's content (polyscope's split): info lines, warnings batched (the same warning again
// only raises its count), errors. The status bar shows the latest message.
class MessageLog {
 public:
  void info(std::string text) { add(MessageLevel::info, std::move(text)); }
  void warning(std::string text) { add(MessageLevel::warning, std::move(text)); }
  void error(std::string text) { add(MessageLevel::error, std::move(text)); }
  // A message without a place of its own gets the `file:line:col` its text starts with, if any.
  void add(MessageLevel level, std::string text, std::optional<scene::SourcePlace> place = std::nullopt);
  // One message a diagnostic, each with its place.
  void diagnostics(const std::vector<scene::Diagnostic>& list);
  // An error caught: a SceneError's diagnostics one a line, any other by its what().
  void error(const std::exception& e);
  void clear() { messages_.clear(); }
  // Scripted sessions also print every message on stderr, where tests and users read them.
  void set_echo(bool is_echoed) { is_echoed_ = is_echoed; }

  const std::vector<Message>& messages() const { return messages_; }
  // The latest message, or none.
  const Message* latest() const { return messages_.empty() ? nullptr : &messages_.back(); }
  std::size_t count(MessageLevel level) const;

 private:
  std::vector<Message> messages_;
  bool is_echoed_ = false;
};

}  // namespace nome::viewer
