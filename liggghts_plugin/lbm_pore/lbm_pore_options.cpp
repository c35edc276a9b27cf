#include "lbm_pore_options.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

#include "lbm/input_error.h"
#include "plugin_common/number_text.h"

namespace lbm_pore {

namespace {

[[noreturn]] void fail(const std::string& message) {
  throw lbm::InputError("fix lbm/pore: " + message);
}

// Reads words one by one with range-checked conversions.
class Words {
 public:
  explicit Words(const std::vector<std::string>& w) : w_(w) {}
  bool done() const { return i_ >= w_.size(); }
  std::string next_keyword() { return w_[i_++]; }
  std::string text(const std::string& keyword) {
    if (done()) fail("keyword '" + keyword + "' needs a value");
    return w_[i_++];
  }
  double number(const std::string& keyword, double lo, double hi, bool lo_open = true) {
    const std::string word = text(keyword);
    const std::optional<double> v = read_decimal(word);  // plain decimal: no hex, inf, nan
    if (!v || !(lo_open ? *v > lo : *v >= lo) || *v > hi)
      fail("keyword '" + keyword + "' = '" + word + "': must be a number in " +
           interval_text(lo, !lo_open, hi));
    return *v;
  }
  int integer(const std::string& keyword, int lo, int hi) {
    const std::string word = text(keyword);
    const std::optional<int> v = read_decimal_integer(word);
    if (!v || *v < lo || *v > hi)
      fail("keyword '" + keyword + "' = '" + word + "': must be an integer in [" +
           std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return *v;
  }
  bool yes_no(const std::string& keyword) {
    const std::string word = text(keyword);
    if (word == "yes" || word == "on") return true;
    if (word == "no" || word == "off") return false;
    fail("keyword '" + keyword + "' = '" + word + "': must be yes or no");
  }
  static std::string format(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
  }
  // Each keyword once: a repeated one used to win silently over the first.
  void require_first_use(const std::string& keyword) {
    if (!seen_.insert(keyword).second)
      throw lbm::InputError(duplicate_keyword_message("fix lbm/pore", keyword));
  }

 private:
  const std::vector<std::string>& w_;
  std::size_t i_ = 0;
  std::set<std::string> seen_;
};

constexpr double kInf = HUGE_VAL;

void parse_pore_scene(Words& words, PoreOptions& o) {
  // pore inlet Li free Lf length L outlet Lo width W diameter D (any order, all required)
  const char* names[] = {"inlet", "free", "length", "outlet", "width", "diameter"};
  double* targets[] = {&o.inlet_length, &o.free_length, &o.pore_length,
                       &o.outlet_length, &o.width,       &o.pore_diameter};
  bool seen[6] = {false, false, false, false, false, false};
  for (int n = 0; n < 6; ++n) {
    const std::string key = words.text("scene pore");
    int which = -1;
    for (int k = 0; k < 6; ++k)
      if (key == names[k]) which = k;
    if (which < 0 || seen[which])
      fail("scene pore: expected 'inlet', 'free', 'length', 'outlet', 'width' and 'diameter' "
           "once each, got '" + key + "'");
    seen[which] = true;
    // The free region may be empty; every other length must be positive.
    const bool zero_allowed = which == 1;
    *targets[which] = words.number(std::string("scene pore ") + key, 0.0, kInf, !zero_allowed);
  }
  if (o.pore_diameter > o.width)
    fail("scene pore diameter = " + Words::format(o.pore_diameter) +
         ": must be <= width = " + Words::format(o.width) + " (the pore must fit in the box)");
}

// The flow runs along +x, from the inlet at x-lo (where particles are inserted) to the outlet
// at x-hi (where they are removed): a negative drive would reverse it and turn the scene's
// regions round, so it is refused. 0 is valid: a closed box without drive (e.g. a settling
// sphere); fix_lbm_pore.txt says what the outputs then are.
double non_negative_drive(Words& words, const std::string& key) {
  const double value = words.number(key, -kInf, kInf);
  if (value < 0.0)
    fail("keyword '" + key + "' = '" + Words::format(value) +
         "': must be a number in [0, inf]: the flow runs "
         "along +x, from the inlet at x-lo to the outlet at x-hi; for the opposite direction "
         "mirror the scene "
         "(0 = a closed box without drive)");
  return value;
}

}  // namespace

PoreOptions parse_pore_options(const std::vector<std::string>& args) {
  PoreOptions o;
  Words words(args);
  bool drive_given = false;
  while (!words.done()) {
    const std::string key = words.next_keyword();
    words.require_first_use(key);
    if (key == "dx") {
      o.dx = words.number(key, 0.0, kInf);
    } else if (key == "rho") {
      o.rho = words.number(key, 0.0, kInf);
    } else if (key == "nu") {
      o.nu = words.number(key, 0.0, kInf);
    } else if (key == "n_dem") {
      o.n_dem = words.integer(key, 1, 100000);
    } else if (key == "magic") {
      o.magic = words.number(key, 0.0, 10.0);
    } else if (key == "scene") {
      const std::string kind = words.text(key);
      if (kind == "pore") {
        o.scene = PoreOptions::Scene::kPore;
        parse_pore_scene(words, o);
      } else if (kind == "voxels") {
        o.scene = PoreOptions::Scene::kVoxelFile;
        o.voxel_file = words.text("scene voxels");
      } else {
        fail("keyword 'scene' = '" + kind + "': must be 'pore' or 'voxels'");
      }
    } else if (key == "origin") {
      o.origin_given = true;
      for (int a = 0; a < 3; ++a) o.origin[a] = words.number(key, -kInf, kInf);
    } else if (key == "lateral") {
      const std::string v = words.text(key);
      if (v != "periodic" && v != "wall")
        fail("keyword 'lateral' = '" + v + "': must be 'periodic' or 'wall'");
      o.lateral_periodic = v == "periodic";
    } else if (key == "velocity") {
      if (drive_given && o.drive != PoreOptions::Drive::kVelocity)
        fail("keywords 'velocity' and 'pressure_loss' exclude each other: give one drive");
      o.drive = PoreOptions::Drive::kVelocity;
      o.drive_value = non_negative_drive(words, key);
      drive_given = true;
    } else if (key == "pressure_loss") {
      if (drive_given && o.drive != PoreOptions::Drive::kPressureLoss)
        fail("keywords 'velocity' and 'pressure_loss' exclude each other: give one drive");
      o.drive = PoreOptions::Drive::kPressureLoss;
      o.drive_value = non_negative_drive(words, key);
      drive_given = true;
    } else if (key == "max_pressure_loss") {
      o.max_pressure_loss = words.number(key, 0.0, kInf);
    } else if (key == "boundary") {
      o.boundary = words.text(key);
      if (o.boundary != "bounce_back" && o.boundary != "bouzidi" && o.boundary != "mls")
        fail("keyword 'boundary' = '" + o.boundary + "': must be bounce_back, bouzidi or mls");
    } else if (key == "mass_correction") {
      const std::string v = words.text(key);
      if (v != "yes" && v != "on" && v != "sweep" && v != "kernel" && v != "no" && v != "off")
        fail("keyword 'mass_correction' = '" + v + "': must be yes, sweep, kernel or no");
      o.mass_correction = v != "no" && v != "off";
      o.mass_correction_in_kernel = v != "sweep";
    } else if (key == "moving_walls") {
      const std::string v = words.text(key);
      if (v != "kernel" && v != "sweep")
        fail("keyword 'moving_walls' = '" + v + "': must be 'kernel' or 'sweep'");
      o.moving_walls_in_kernel = v == "kernel";
    } else if (key == "reference_pressure") {
      const std::string v = words.text(key);
      if (v != "remove" && v != "keep")
        fail("keyword 'reference_pressure' = '" + v + "': must be 'remove' or 'keep'");
      o.keep_reference_pressure = v == "keep";
    } else if (key == "substep_force") {
      const std::string v = words.text(key);
      if (v != "held" && v != "fraction")
        fail("keyword 'substep_force' = '" + v + "': must be 'held' or 'fraction'");
      o.substep_fraction = v == "fraction";
    } else if (key == "rotation") {
      o.rotation = words.yes_no(key);
    } else if (key == "lubrication") {
      o.lubrication = words.yes_no(key);
    } else if (key == "lubrication_cutoff") {
      o.lubrication_cutoff = words.number(key, 0.0, 2.0);
    } else if (key == "deposit_region") {
      const std::string v = words.text(key);
      if (v != "from_inlet" && v != "pore")
        fail("keyword 'deposit_region' = '" + v + "': must be 'from_inlet' or 'pore'");
      o.deposits_in_pore_only = v == "pore";
    } else if (key == "deposit_speed") {
      o.deposit_speed = words.number(key, 0.0, kInf, false);
    } else if (key == "burst_drop") {
      o.burst_drop = words.number(key, 0.0, 1.0);
      if (o.burst_drop >= 1.0) fail("keyword 'burst_drop' = 1: must be a number in (0, 1) (a fall of the whole peak never ends)");
    } else if (key == "burst_window") {
      o.burst_window = words.number(key, 0.0, kInf);
    } else if (key == "burst_deposits") {
      o.burst_deposits = words.integer(key, 0, 1000000000);
    } else if (key == "burst_file") {
      o.burst_file = words.text(key);
    } else if (key == "deposit_speeds") {
      o.deposit_speeds_every = words.integer(key, 1, 1000000000);
      o.deposit_speeds_file = words.text("deposit_speeds (file)");
    } else if (key == "vtk") {
      o.vtk_every = words.integer(key, 0, 1000000000);
      o.vtk_directory = words.text("vtk (directory)");
    } else if (key == "checkpoint") {
      o.checkpoint_prefix = words.text(key);
    } else if (key == "checkpoint_keep") {
      o.checkpoint_keep = words.integer(key, 0, 1000000000);
    } else {
      fail("unknown keyword '" + key + "'; valid keywords: " + pore_options_usage());
    }
  }
  if (o.dx <= 0.0) fail("keyword 'dx' (lattice spacing, > 0) is required");
  if (o.scene == PoreOptions::Scene::kNone)
    fail("keyword 'scene' is required: 'scene pore inlet .. free .. length .. outlet .. width .. "
         "diameter ..' or 'scene voxels <file>'");
  if (!drive_given) fail("a drive is required: 'velocity <U>' or 'pressure_loss <P>'");
  if (o.max_pressure_loss > 0.0 && (o.drive != PoreOptions::Drive::kVelocity || o.drive_value <= 0.0))
    fail("keyword 'max_pressure_loss' caps the pressure loss of a velocity inlet: it needs 'velocity <U>' "
         "with U > 0, not 'pressure_loss' or a closed box");
  return o;
}

const char* pore_options_usage() {
  return "dx, rho, nu, n_dem, magic, scene (pore|voxels), origin, lateral, velocity, "
         "pressure_loss, max_pressure_loss, boundary, mass_correction, moving_walls, reference_pressure, substep_force, rotation, lubrication, lubrication_cutoff, deposit_region, deposit_speed, burst_drop, "
         "burst_window, burst_deposits, burst_file, deposit_speeds, vtk, "
         "checkpoint, checkpoint_keep";
}

}  // namespace lbm_pore
