#pragma once
// The keyword pairs of `pair_style lbm/dashdot` (the defaults) and `pair_coeff I J` (one type
// pair): kn v, kc v, damping v, each at most once. No LIGGGHTS dependency, so the parser is
// unit-tested and fuzzed (tests/fuzz) on its own; the pair style turns its errors into
// LIGGGHTS errors.
#include <string>
#include <vector>

#include "contact/pair_contact.h"

namespace lbm_pore {

// Sets the given keywords of `params` (the others keep their value). Throws lbm::InputError
// "<command>: ..." naming the keyword and its range (kn > 0, kc >= 0, damping in [0, 1]), an
// unknown keyword, a keyword without value or one given twice.
void parse_dashdot_coefficients(const std::vector<std::string>& words,
                                contact::PairContactParams& params, const std::string& command);

}  // namespace lbm_pore
