// ETD-DPD: fix etd's keywords (both schemes) and the checks the two schemes share.
#ifndef ETD_FIX_ETD_OPTIONS_H
#define ETD_FIX_ETD_OPTIONS_H

#include "lammps.h"

#include <functional>
#include <initializer_list>
#include <string>

namespace etd {

// Calls handle(key, value) for each keyword/value pair of a fix etd command from arg[3] on;
// ERROR for a keyword without its value.
void for_each_fix_etd_keyword(
    LAMMPS_NS::LAMMPS *lmp, int narg, char **arg,
    const std::function<void(const std::string &, const std::string &)> &handle);

// The position of value among choices; ERROR "<key> must be a or b, got <value>" otherwise.
int fix_etd_choice(LAMMPS_NS::LAMMPS *lmp, const std::string &key, const std::string &value,
                   std::initializer_list<const char *> choices);

// Whether a fix etd command asks for scheme implicit (else diagonal, the default); ERROR for
// another scheme. The two schemes are different classes; this picks one.
bool fix_etd_scheme_is_implicit(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);

// The keywords of scheme implicit (doc/fix_etd.rst), with their defaults.
struct ImplicitOptions {
  bool overdamped = false;
  bool midpoint = true;       // overdamped: predictor-corrector, or a single solve
  bool warm_start = false;    // CG starts from the old velocities (else block-Jacobi)
  double tolerance = 1e-6;
  int max_iterations = 200;
  // where each step's pairs come from: the scheme's own search where the set-up allows it
  // (automatic), required (own), or LAMMPS's neighbor lists (lammps)
  enum class PairSearch { automatic, own, lammps };
  PairSearch pair_search = PairSearch::automatic;
};
ImplicitOptions parse_implicit_options(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);

// ERROR naming the first atom of the group (largest ID) whose sphere has no moment of
// inertia, 0.4 m r^2 = 0; collective. who: the style named in the message.
void check_moments_of_inertia(LAMMPS_NS::LAMMPS *lmp, int groupbit, const char *who);

}    // namespace etd

#endif
