#pragma once
// Keyword values of our styles: a plain decimal number in a range (number_text.h: no hex, inf
// or nan) or one word of a list, or a LIGGGHTS error naming the command, the keyword and the
// valid range or words.
#include <initializer_list>

namespace LAMMPS_NS {
class Error;
}

namespace lbm_pore {

// Accepts min < value <= max (min <= value <= max when min_inclusive), else error->all with
// "<command>: <keyword> must be ... (got '<text>')".
double parse_number(LAMMPS_NS::Error* error, const char* command, const char* keyword,
                    const char* text, double min, bool min_inclusive, double max);

// Integer variant: min <= value <= max.
int parse_integer(LAMMPS_NS::Error* error, const char* command, const char* keyword,
                  const char* text, int min, int max);

// The position of `text` in `choices`, else error->all with
// "<command>: <keyword> must be <a>, <b> or <c> (got '<text>')".
int parse_choice(LAMMPS_NS::Error* error, const char* command, const char* keyword,
                 const char* text, std::initializer_list<const char*> choices);

}  // namespace lbm_pore
