#include "dashdot_arguments.h"

#include <set>

#include "lbm/input_error.h"
#include "plugin_common/number_text.h"

namespace lbm_pore {

void parse_dashdot_coefficients(const std::vector<std::string>& words,
                                contact::PairContactParams& params, const std::string& command) {
  constexpr double kBig = 1e300;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < words.size(); i += 2) {
    const std::string& key = words[i];
    if (i + 1 >= words.size())
      throw lbm::InputError(command + ": keyword '" + key + "' needs a value");
    const std::string& value = words[i + 1];
    if (key == "kn") {
      params.normal.k_n = number_in_range(command, "kn", value, 0.0, false, kBig);
    } else if (key == "kc") {
      params.cohesion.k_c = number_in_range(command, "kc", value, 0.0, true, kBig);
    } else if (key == "damping") {
      params.normal.damping_ratio = number_in_range(command, "damping", value, 0.0, true, 1.0);
    } else {
      throw lbm::InputError(command + ": unknown keyword '" + key +
                            "' (expected kn, kc or damping)");
    }
    if (!seen.insert(key).second) throw lbm::InputError(duplicate_keyword_message(command, key));
  }
}

}  // namespace lbm_pore
