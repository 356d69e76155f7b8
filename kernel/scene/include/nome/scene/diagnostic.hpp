#pragma once

#include <string>
#include <vector>

#include "nome/error.hpp"

namespace nome::scene {

// A place in a source text: 1-based line and column (column counts bytes).
struct SourceLocation {
  int line = 0;
  int column = 0;
  bool operator==(const SourceLocation&) const = default;
};

// `line:col`, as messages that point at a second place write it.
std::string location_text(SourceLocation at);

enum class Severity { error, warning };

// One message about user content, printed as `file:line:col: message`.
struct Diagnostic {
  Severity severity = Severity::error;
  std::string file;
  SourceLocation location;
  std::string message;

  bool operator==(const Diagnostic&) const = default;
  // `file:line:col`
  std::string place() const;
  std::string to_string() const;
};

// The diagnostics of one text, in order of appearance.
class Diagnostics {
 public:
  explicit Diagnostics(std::string file = {}) : file_(std::move(file)) {}

  void error(SourceLocation at, std::string message);
  void warning(SourceLocation at, std::string message);
  // One of another text's diagnostics (an included file's), kept with its own file.
  void add(Diagnostic diagnostic);
  bool has_errors() const;
  const std::vector<Diagnostic>& all() const { return items_; }
  const std::string& file() const { return file_; }
  // Throws SceneError with every error (warnings are left for the caller) when there is one.
  void throw_if_errors() const;

 private:
  std::string file_;
  std::vector<Diagnostic> items_;
  size_t errors_ = 0;  // reported, listed or not
};

// Malformed scene content: one or several located errors. what() lists them one per line.
class SceneError : public Error {
 public:
  explicit SceneError(std::vector<Diagnostic> errors);
  const std::vector<Diagnostic>& diagnostics() const { return errors_; }

 private:
  std::vector<Diagnostic> errors_;
};

// Levenshtein distance: how many single-character edits turn `a` into `b`.
size_t edit_distance(const std::string& a, const std::string& b);

// The names among `candidates` nearest to `name` (edit distance), at most `limit`, for messages.
std::vector<std::string> nearest_names(const std::string& name, const std::vector<std::string>& candidates,
                                       size_t limit = 3);
// " (did you mean a, b?)" or "" when there is no candidate.
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace nome::scene
