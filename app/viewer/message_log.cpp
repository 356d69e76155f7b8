#include "viewer/message_log.hpp"

#include <algorithm>
#include <iostream>

namespace nome::viewer {

void MessageLog::add(MessageLevel level, std::string text, std::optional<scene::SourcePlace> place) {
  if (!place) place = scene::parse_source_place(text);
  if (is_echoed_) {
    const char* prefix = level == MessageLevel::error     ? "error: "
                         : level == MessageLevel::warning ? "warning: "
                                                          : "";
    std::cerr << "nome: " << prefix << text << "\n";
  }
  if (level == MessageLevel::warning) {
    const auto same = std::find_if(messages_.begin(), messages_.end(), [&](const Message& m) {
      return m.level == MessageLevel::warning && m.text == text;
    });
    if (same != messages_.end()) {
      Message batched = *same;
      ++batched.count;
      messages_.erase(same);
      messages_.push_back(std::move(batched));
      return;
    }
  }
  messages_.push_back({level, std::move(text), 1, std::move(place)});
  // A long session keeps the latest few hundred lines.
  constexpr std::size_t limit = 500;
  if (messages_.size() > limit) messages_.erase(messages_.begin(), messages_.end() - limit);
}

void MessageLog::diagnostics(const std::vector<scene::Diagnostic>& list) {
  for (const scene::Diagnostic& d : list) {
    const MessageLevel level =
        d.severity == scene::Severity::error ? MessageLevel::error : MessageLevel::warning;
    // The log shows the level itself.
    add(level, d.place() + ": " + d.message, scene::SourcePlace{d.file, d.location});
  }
}

void MessageLog::error(const std::exception& e) {
  if (const auto* located = dynamic_cast<const scene::SceneError*>(&e);
      located && !located->diagnostics().empty())
    diagnostics(located->diagnostics());
  else
    add(MessageLevel::error, e.what());
}

std::size_t MessageLog::count(MessageLevel level) const {
  std::size_t n = 0;
  for (const Message& m : messages_)
    if (m.level == level) n += m.count;
  return n;
}

}  // namespace nome::viewer
