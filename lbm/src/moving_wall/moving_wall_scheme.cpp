#include "lbm/moving_wall/moving_wall_scheme.h"

#include "lbm/input_error.h"

namespace lbm::moving_wall {

namespace {
struct Spelling {
  MovingWallScheme scheme;
  const char* name;   // fix lbm/pore's `boundary` keyword
  const char* label;  // reports
};
constexpr Spelling kSpellings[] = {
    {MovingWallScheme::kBounceBack, "bounce_back", "bounce-back"},
    {MovingWallScheme::kBouzidi, "bouzidi", "Bouzidi"},
    {MovingWallScheme::kMeiLuoShyy, "mls", "Mei-Luo-Shyy"},
};

const Spelling& spelling(MovingWallScheme scheme) {
  for (const Spelling& s : kSpellings)
    if (s.scheme == scheme) return s;
  throw std::invalid_argument("moving_wall: not a MovingWallScheme value");
}
}  // namespace

const char* name(MovingWallScheme scheme) { return spelling(scheme).name; }

const char* label(MovingWallScheme scheme) { return spelling(scheme).label; }

MovingWallScheme parse(const std::string& word) {
  for (const Spelling& s : kSpellings)
    if (word == s.name) return s.scheme;
  throw InputError("moving-wall scheme '" + word + "': must be bounce_back, bouzidi or mls");
}

}  // namespace lbm::moving_wall
