#pragma once
// Numbers as our styles' keywords accept them, and the words they are given in: plain decimal
// only ("1", "-2.5", ".5", "3e-4"), never hexadecimal ("0x10", which std::strtod reads as 16),
// "inf", "nan", leading blanks or trailing characters. No LIGGGHTS dependency, so the
// parsers of every style (and their fuzz targets, tests/fuzz) share it.
#include <optional>
#include <string>

namespace lbm_pore {

// The value of a plain decimal number, or nothing when `text` is not one or is out of the
// range of a double (overflow or underflow). The value is std::strtod's, so every number the
// parsers accepted before reads the same.
std::optional<double> read_decimal(const std::string& text);

// An optionally signed string of decimal digits in the range of int, or nothing.
std::optional<int> read_decimal_integer(const std::string& text);

// A closed or half-open range as the error messages print it: "(0, inf]", "[1, 100000]".
std::string interval_text(double min, bool min_inclusive, double max);

// min < value <= max (min <= value <= max when min_inclusive), else lbm::InputError
// "<command>: <keyword> must be a number > 0 (got '<text>')" (or "... in [a, b] ...").
double number_in_range(const std::string& command, const std::string& keyword,
                       const std::string& text, double min, bool min_inclusive, double max);

// min <= value <= max, else lbm::InputError "<command>: <keyword> must be an integer in [a, b] (got
// ..)".
int integer_in_range(const std::string& command, const std::string& keyword,
                     const std::string& text, int min, int max);

// "<command>: keyword '<keyword>' is given twice; give it once" (the parsers used to let the
// last one win silently).
std::string duplicate_keyword_message(const std::string& command, const std::string& keyword);

}  // namespace lbm_pore
