#include "wall_voxel_arguments.h"

#include <set>

#include "lbm/input_error.h"
#include "plugin_common/number_text.h"

namespace lbm_pore {

namespace {
const std::string kCommand = "fix wall/voxel";
constexpr double kBig = 1e300;

[[noreturn]] void fail(const std::string& message) {
  throw lbm::InputError(kCommand + ": " + message);
}

// Reads `count` values after the keyword at `i`.
const std::string& value_of(const std::vector<std::string>& words, std::size_t i, std::size_t count,
                            std::size_t which = 0) {
  if (i + count >= words.size())
    fail("keyword '" + words[i] + "' needs " + std::to_string(count) + " value(s)");
  return words[i + 1 + which];
}

// One contact keyword and its value into `params`; false when `key` is none of them.
bool parse_contact_keyword(const std::string& key, const std::string& value,
                           contact::WallContactParams& params) {
  if (key == "kw") {
    params.normal.k_n = number_in_range(kCommand, "kw", value, 0.0, false, kBig);
  } else if (key == "ka") {
    params.adhesion.k_a = number_in_range(kCommand, "ka", value, 0.0, true, kBig);
  } else if (key == "damping") {
    params.normal.damping_ratio = number_in_range(kCommand, "damping", value, 0.0, true, 1.0);
  } else if (key == "mu") {
    params.friction.mu = number_in_range(kCommand, "mu", value, 0.0, true, kBig);
  } else if (key == "kt") {
    params.friction.k_t = number_in_range(kCommand, "kt", value, 0.0, false, kBig);
  } else if (key == "tangential_damping") {
    params.friction.damping_ratio =
        number_in_range(kCommand, "tangential_damping", value, 0.0, true, 1.0);
  } else {
    return false;
  }
  return true;
}
}  // namespace

WallVoxelArguments parse_wall_voxel_arguments(const std::vector<std::string>& words) {
  WallVoxelArguments a;
  std::set<std::string> seen;
  int geometries = 0;  // 'lbm', 'file', 'pore'
  std::size_t i = 0;
  while (i < words.size()) {
    const std::string key = words[i];
    if (!seen.insert(key).second) throw lbm::InputError(duplicate_keyword_message(kCommand, key));
    if (key == "lbm") {
      a.lbm_fix_id = value_of(words, i, 1);
      ++geometries;
      i += 2;
    } else if (key == "file") {
      a.source.kind = WallGeometrySource::Kind::kFile;
      a.source.path = value_of(words, i, 1);
      ++geometries;
      i += 2;
    } else if (key == "pore") {
      a.source.kind = WallGeometrySource::Kind::kPoreScene;
      ++geometries;
      i += 1;
    } else if (key == "inlet_length" || key == "free_length" || key == "pore_length" ||
               key == "outlet_length" || key == "width") {
      const int value = integer_in_range(kCommand, key, value_of(words, i, 1), 1, 1 << 20);
      if (key == "inlet_length") a.source.pore.inlet_length = value;
      if (key == "free_length") a.source.pore.free_length = value;
      if (key == "pore_length") a.source.pore.pore_length = value;
      if (key == "outlet_length") a.source.pore.outlet_length = value;
      if (key == "width") a.source.pore.width = value;
      i += 2;
    } else if (key == "model") {
      const std::string model = value_of(words, i, 1);
      if (model != "smooth" && model != "voxel_sum")
        fail("model must be smooth or voxel_sum (got '" + model + "')");
      a.voxel_sum = model == "voxel_sum";
      i += 2;
    } else if (key == "pore_diameter") {
      a.source.pore.pore_diameter =
          number_in_range(kCommand, "pore_diameter", value_of(words, i, 1), 0.0, false, kBig);
      i += 2;
    } else if (key == "spacing") {
      a.source.spacing =
          number_in_range(kCommand, "spacing", value_of(words, i, 1), 0.0, false, kBig);
      i += 2;
    } else if (key == "origin") {
      for (std::size_t c = 0; c < 3; ++c)
        a.source.origin[c] =
            number_in_range(kCommand, "origin", value_of(words, i, 3, c), -kBig, true, kBig);
      i += 4;
    } else {
      if (i + 1 >= words.size()) fail("keyword '" + key + "' needs a value");
      if (!parse_contact_keyword(key, words[i + 1], a.params))
        fail(
            "unknown keyword '" + key +
            "' (expected file, pore, inlet_length, free_length, pore_length, outlet_length, width, "
            "pore_diameter, spacing, origin, model, lbm, kw, ka, damping, mu, kt or tangential_damping)");
      i += 2;
    }
  }
  if (geometries > 1) fail("give one geometry: 'lbm <fix-ID>', 'file <path>' or 'pore'");
  if (geometries == 0)
    fail(
        "no geometry: give keyword 'lbm <fix-ID>' (the geometry of fix lbm/pore), 'file <path>' or "
        "'pore'");
  // Defaults tied to the wall stiffness and damping unless given.
  if (!seen.count("kt"))
    a.params.friction.k_t = contact::default_tangential_stiffness(a.params.normal.k_n);
  if (!seen.count("tangential_damping"))
    a.params.friction.damping_ratio = a.params.normal.damping_ratio;
  return a;
}

}  // namespace lbm_pore
