#include "dpd_style_lookup.h"

#include "force.h"
#include "pair.h"

#include <algorithm>

std::vector<etd::DpdExtrasProvider *> etd::find_dpd_providers(LAMMPS_NS::LAMMPS *lmp)
{
  std::vector<DpdExtrasProvider *> found;
  LAMMPS_NS::Pair *pair = lmp->force->pair;
  if (!pair) return found;
  if (auto *provider = dynamic_cast<DpdExtrasProvider *>(pair)) {
    found.push_back(provider);
    return found;
  }
  // sub-styles of pair hybrid: pair_match returns the n-th instance of a style, and falls back
  // to the only instance when there is one, so stop at the first repeat
  for (const char *name : {"dpd/gen", "dpd/fpm"}) {
    for (int nsub = 1;; nsub++) {
      auto *provider = dynamic_cast<DpdExtrasProvider *>(lmp->force->pair_match(name, 1, nsub));
      if (!provider || std::find(found.begin(), found.end(), provider) != found.end()) break;
      found.push_back(provider);
    }
  }
  return found;
}
