#include "nome/number_text.hpp"

namespace nome {

#if defined(__cpp_lib_to_chars)

std::to_chars_result shortest_to_chars(char* first, char* last, double value) {
  return std::to_chars(first, last, value);
}

std::to_chars_result shortest_to_chars(char* first, char* last, float value) {
  return std::to_chars(first, last, value);
}

std::to_chars_result general_to_chars(char* first, char* last, double value, int precision) {
  return std::to_chars(first, last, value, std::chars_format::general, precision);
}

std::from_chars_result number_from_chars(const char* first, const char* last, double& value) {
  return std::from_chars(first, last, value);
}

#else

std::to_chars_result shortest_to_chars(char* first, char* last, double value) {
  return fallback::shortest_to_chars(first, last, value);
}

std::to_chars_result shortest_to_chars(char* first, char* last, float value) {
  return fallback::shortest_to_chars(first, last, value);
}

std::to_chars_result general_to_chars(char* first, char* last, double value, int precision) {
  return fallback::general_to_chars(first, last, value, precision);
}

std::from_chars_result number_from_chars(const char* first, const char* last, double& value) {
  return fallback::number_from_chars(first, last, value);
}

#endif

}  // namespace nome
