#pragma once

#include <charconv>

// Numbers to text and back as <charconv> does it, also where the standard library has only the integer
// overloads (Emscripten's libc++): there the fallback below stands in.
namespace nome {

// The shortest text that reads back to `value`, as std::to_chars(first, last, value).
std::to_chars_result shortest_to_chars(char* first, char* last, double value);
std::to_chars_result shortest_to_chars(char* first, char* last, float value);

// `value` as printf's %.*g, as std::to_chars(first, last, value, std::chars_format::general, precision).
std::to_chars_result general_to_chars(char* first, char* last, double value, int precision);

// A number in [first, last) as std::from_chars(first, last, value) (std::chars_format::general).
std::from_chars_result number_from_chars(const char* first, const char* last, double& value);

// The same on snprintf and strtod in the C locale, used where the standard library lacks them; compiled
// in every build so that the tests hold it to the standard library's.
namespace fallback {
std::to_chars_result shortest_to_chars(char* first, char* last, double value);
std::to_chars_result shortest_to_chars(char* first, char* last, float value);
std::to_chars_result general_to_chars(char* first, char* last, double value, int precision);
std::from_chars_result number_from_chars(const char* first, const char* last, double& value);
}  // namespace fallback

}  // namespace nome
