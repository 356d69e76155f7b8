#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace nome::cli {

// A usage mistake: exit status 2 with the command's help hint.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct OptionSpec {
  std::string name;        // "--subdiv"
  std::string short_name;  // "-o" or empty
  std::string value_name;  // "N"; empty for a flag
  std::string help;
  bool repeatable = false;
};

// Options of one command, parsed from argv. Every option has a help line; the help text is built
// from the same table the parser reads, so the two never disagree.
class Arguments {
 public:
  Arguments(std::string command, std::string synopsis, std::vector<OptionSpec> specs);

  void parse(const std::vector<std::string>& args);
  std::string help() const;

  bool has(const std::string& name) const { return values_.count(name) > 0; }
  std::optional<std::string> value(const std::string& name) const;
  std::vector<std::string> values(const std::string& name) const;
  const std::vector<std::string>& positionals() const { return positionals_; }

  int int_value(const std::string& name, int fallback, int min, int max) const;
  double double_value(const std::string& name, double fallback) const;

 private:
  const OptionSpec* find(const std::string& name) const;

  std::string command_;
  std::string synopsis_;
  std::vector<OptionSpec> specs_;
  std::map<std::string, std::vector<std::string>> values_;
  std::vector<std::string> positionals_;
};

}  // namespace nome::cli
