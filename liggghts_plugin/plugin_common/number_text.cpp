#include "number_text.h"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "lbm/input_error.h"

namespace lbm_pore {

namespace {
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// Advances over [+-]; returns the position after it.
std::size_t skip_sign(const std::string& t, std::size_t i) {
  return i < t.size() && (t[i] == '+' || t[i] == '-') ? i + 1 : i;
}

std::size_t skip_digits(const std::string& t, std::size_t i) {
  while (i < t.size() && is_digit(t[i])) ++i;
  return i;
}

// [+-] (digits [. digits*] | . digits) [(e|E) [+-] digits], nothing else.
bool is_plain_decimal(const std::string& t) {
  std::size_t i = skip_sign(t, 0);
  const std::size_t integer_end = skip_digits(t, i);
  bool mantissa_digits = integer_end > i;
  i = integer_end;
  if (i < t.size() && t[i] == '.') {
    const std::size_t fraction_end = skip_digits(t, i + 1);
    mantissa_digits = mantissa_digits || fraction_end > i + 1;
    i = fraction_end;
  }
  if (!mantissa_digits) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    const std::size_t exponent_start = skip_sign(t, i + 1);
    const std::size_t exponent_end = skip_digits(t, exponent_start);
    if (exponent_end == exponent_start) return false;
    i = exponent_end;
  }
  return i == t.size();
}
}  // namespace

std::optional<double> read_decimal(const std::string& text) {
  if (!is_plain_decimal(text)) return std::nullopt;
  errno = 0;
  const double value = std::strtod(text.c_str(), nullptr);
  // ERANGE: the number overflows to inf or underflows to zero or a subnormal.
  if (errno == ERANGE || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<int> read_decimal_integer(const std::string& text) {
  const std::size_t digits = skip_sign(text, 0);
  if (digits == text.size() || skip_digits(text, digits) != text.size()) return std::nullopt;
  errno = 0;
  const long value = std::strtol(text.c_str(), nullptr, 10);
  if (errno == ERANGE || value < INT_MIN || value > INT_MAX) return std::nullopt;
  return static_cast<int>(value);
}

std::string interval_text(double min, bool min_inclusive, double max) {
  auto format = [](double v) -> std::string {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
  };
  return std::string(min_inclusive ? "[" : "(") + format(min) + ", " + format(max) + "]";
}

double number_in_range(const std::string& command, const std::string& keyword,
                       const std::string& text, double min, bool min_inclusive, double max) {
  const std::optional<double> value = read_decimal(text);
  if (value && (min_inclusive ? *value >= min : *value > min) && *value <= max) return *value;
  char range[128];
  if (max >= 1e300)
    std::snprintf(range, sizeof range, "a number %s %g", min_inclusive ? ">=" : ">", min);
  else
    std::snprintf(range, sizeof range, "a number in %s%g, %g]", min_inclusive ? "[" : "(", min,
                  max);
  throw lbm::InputError(command + ": " + keyword + " must be " + range + " (got '" + text + "')");
}

int integer_in_range(const std::string& command, const std::string& keyword,
                     const std::string& text, int min, int max) {
  const std::optional<int> value = read_decimal_integer(text);
  if (value && *value >= min && *value <= max) return *value;
  throw lbm::InputError(command + ": " + keyword + " must be an integer in [" +
                        std::to_string(min) + ", " + std::to_string(max) + "] (got '" + text +
                        "')");
}

std::string duplicate_keyword_message(const std::string& command, const std::string& keyword) {
  return command + ": keyword '" + keyword + "' is given twice; give it once";
}

}  // namespace lbm_pore
