#include "cli/arguments.hpp"

#include <cmath>
#include <sstream>

namespace nome::cli {

Arguments::Arguments(std::string command, std::string synopsis, std::vector<OptionSpec> specs)
    : command_(std::move(command)), synopsis_(std::move(synopsis)), specs_(std::move(specs)) {
  specs_.push_back({"--help", "-h", "", "show this help"});
}

const OptionSpec* Arguments::find(const std::string& name) const {
  for (const OptionSpec& s : specs_)
    if (s.name == name || (!s.short_name.empty() && s.short_name == name)) return &s;
  return nullptr;
}

void Arguments::parse(const std::vector<std::string>& args) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.size() < 2 || arg[0] != '-' || (arg.size() > 1 && (std::isdigit(arg[1]) || arg[1] == '.'))) {
      positionals_.push_back(arg);
      continue;
    }
    std::string name = arg, value;
    bool has_inline_value = false;
    if (const size_t eq = arg.find('='); eq != std::string::npos && arg.rfind("--", 0) == 0) {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
      has_inline_value = true;
    }
    const OptionSpec* spec = find(name);
    if (!spec) throw UsageError("unknown option '" + name + "' for 'nome " + command_ + "'");
    if (spec->value_name.empty()) {
      if (has_inline_value) throw UsageError("option " + spec->name + " takes no value");
    } else if (!has_inline_value) {
      if (i + 1 >= args.size())
        throw UsageError("option " + spec->name + " needs a value " + spec->value_name);
      value = args[++i];
    }
    auto& slot = values_[spec->name];
    if (!slot.empty() && !spec->repeatable) throw UsageError("option " + spec->name + " given twice");
    slot.push_back(value);
  }
}

std::optional<std::string> Arguments::value(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second.back();
}

std::vector<std::string> Arguments::values(const std::string& name) const {
  auto it = values_.find(name);
  return it == values_.end() ? std::vector<std::string>{} : it->second;
}

int Arguments::int_value(const std::string& name, int fallback, int min, int max) const {
  const auto v = value(name);
  if (!v) return fallback;
  size_t used = 0;
  long parsed = 0;
  try {
    parsed = std::stol(*v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != v->size() || v->empty()) throw UsageError(name + " expects a whole number, found '" + *v + "'");
  if (parsed < min || parsed > max)
    throw UsageError(name + " must be between " + std::to_string(min) + " and " + std::to_string(max) +
                     ", found " + *v);
  return static_cast<int>(parsed);
}

double Arguments::double_value(const std::string& name, double fallback) const {
  const auto v = value(name);
  if (!v) return fallback;
  size_t used = 0;
  double parsed = 0;
  try {
    parsed = std::stod(*v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != v->size() || v->empty() || !std::isfinite(parsed))
    throw UsageError(name + " expects a finite number, found '" + *v + "'");
  return parsed;
}

std::string Arguments::help() const {
  std::ostringstream out;
  out << "usage: " << synopsis_ << "\n\noptions:\n";
  for (const OptionSpec& s : specs_) {
    std::string left = "  " + (s.short_name.empty() ? "" : s.short_name + ", ") + s.name;
    if (!s.value_name.empty()) left += " " + s.value_name;
    out << left;
    if (left.size() < 30)
      out << std::string(30 - left.size(), ' ');
    else
      out << "\n" << std::string(30, ' ');
    out << s.help << "\n";
  }
  return out.str();
}

}  // namespace nome::cli
