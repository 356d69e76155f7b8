#include "cli/print_setup_arguments.hpp"

#include <charconv>
#include <cmath>

#include "nome/number_text.hpp"

namespace nome::cli {

std::vector<OptionSpec> print_setup_options() {
  return {{"--fit-height", "", "L", "scale the solid to height L (60mm, 6cm, 2.5in; a number is mm)"},
          {"--fit-size", "", "L", "scale the solid so that its largest dimension is L"},
          {"--rest-on", "", "flattest|FACE",
           "rotate the solid onto its flattest large face or face FACE, lowest point at z = 0"}};
}

double millimeters_per(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::millimeter:
      return 1.0;
    case LengthUnit::centimeter:
      return 10.0;
    case LengthUnit::inch:
      return 25.4;
    case LengthUnit::meter:
      return 1000.0;
  }
  return 1.0;
}

double length_in_mm(const std::string& text, const std::string& option) {
  double value = 0.0;
  const auto [end, error] = number_from_chars(text.data(), text.data() + text.size(), value);
  const std::string unit_text(end, text.data() + text.size());
  const std::optional<LengthUnit> unit =
      unit_text.empty() ? std::optional(LengthUnit::millimeter) : parse_length_unit(unit_text);
  if (error != std::errc() || !unit || !(value > 0.0) || !std::isfinite(value))
    throw UsageError(option + " expects a positive length such as 60mm, 6cm or 2.5in, found '" + text + "'");
  return value * millimeters_per(*unit);
}

PrintPlacementOptions print_setup_argument(const Arguments& parsed, std::optional<PrintPlacementOptions> kept,
                                           LengthUnit unit) {
  PrintPlacementOptions setup = kept.value_or(PrintPlacementOptions{});
  setup.fit_size /= millimeters_per(unit);  // the scene keeps millimetres
  if (parsed.has("--fit-height") && parsed.has("--fit-size"))
    throw UsageError("--fit-height and --fit-size exclude each other");
  for (const char* option : {"--fit-height", "--fit-size"})
    if (const auto text = parsed.value(option)) {
      setup.fit = std::string(option) == "--fit-height" ? FitTarget::height : FitTarget::largest;
      setup.fit_size = length_in_mm(*text, option) / millimeters_per(unit);
    }
  if (const auto rest = parsed.value("--rest-on")) {
    Index face = 0;
    const auto [end, error] = std::from_chars(rest->data(), rest->data() + rest->size(), face);
    if (*rest == "flattest") {
      setup.rest = RestOn::flattest;
    } else if (error == std::errc() && end == rest->data() + rest->size()) {
      setup.rest = RestOn::face;
      setup.rest_face = face;
    } else {
      throw UsageError("--rest-on expects flattest or a face number, found '" + *rest + "'");
    }
  }
  return setup;
}

}  // namespace nome::cli
