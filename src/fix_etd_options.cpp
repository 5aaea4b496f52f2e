// ETD-DPD: fix etd's keywords and shared checks (fix_etd_options.h).
#include "fix_etd_options.h"

#include "atom.h"
#include "error.h"
#include "utils.h"

#include <algorithm>

using namespace LAMMPS_NS;

namespace etd {

void for_each_fix_etd_keyword(
    LAMMPS *lmp, int narg, char **arg,
    const std::function<void(const std::string &, const std::string &)> &handle)
{
  for (int iarg = 3; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (iarg + 2 > narg)
      lmp->error->all(FLERR, "Illegal fix etd command: keyword {} needs a value", key);
    handle(key, arg[iarg + 1]);
  }
}

int fix_etd_choice(LAMMPS *lmp, const std::string &key, const std::string &value,
                   std::initializer_list<const char *> choices)
{
  int index = 0;
  for (const char *choice : choices) {
    if (value == choice) return index;
    index++;
  }
  const int count = static_cast<int>(choices.size());
  std::string listed;
  index = 0;
  for (const char *choice : choices) {
    if (index > 0) listed += index == count - 1 ? " or " : ", ";
    listed += choice;
    index++;
  }
  lmp->error->all(FLERR, "Illegal fix etd command: {} must be {}, got {}", key, listed, value);
  return -1;
}

ImplicitOptions parse_implicit_options(LAMMPS *lmp, int narg, char **arg)
{
  ImplicitOptions options;
  Error *error = lmp->error;
  for_each_fix_etd_keyword(lmp, narg, arg, [&](const std::string &key, const std::string &value) {
    if (key == "scheme") {
      // (fix etd's factory picks this class for 'scheme implicit')
      if (value != "implicit")
        error->all(FLERR, "Illegal fix etd command: scheme must be diagonal or implicit, got {}",
                   value);
    } else if (key == "overdamped") {
      options.overdamped = fix_etd_choice(lmp, key, value, {"yes", "no"}) == 0;
    } else if (key == "tol") {
      options.tolerance = utils::numeric(FLERR, value.c_str(), false, lmp);
      if (!(options.tolerance > 0.0 && options.tolerance < 1.0))
        error->all(FLERR, "Illegal fix etd command: tol must be between 0 and 1, got {}", value);
    } else if (key == "midpoint") {
      options.midpoint = fix_etd_choice(lmp, key, value, {"yes", "no"}) == 0;
    } else if (key == "start") {
      options.warm_start = fix_etd_choice(lmp, key, value, {"velocity", "jacobi"}) == 0;
    } else if (key == "neighbors") {
      options.pair_search = fix_etd_choice(lmp, key, value, {"own", "lammps"}) == 0
          ? ImplicitOptions::PairSearch::own
          : ImplicitOptions::PairSearch::lammps;
    } else if (key == "maxiter") {
      options.max_iterations = utils::inumeric(FLERR, value.c_str(), false, lmp);
      if (options.max_iterations < 1)
        error->all(FLERR, "Illegal fix etd command: maxiter must be a positive integer, got {}",
                   value);
    } else if (key == "order" || key == "noise" || key == "momentum") {
      error->all(FLERR,
                 "Illegal fix etd command: keyword {} belongs to scheme diagonal; the "
                 "implicit scheme is exact in temperature and conserves momentum",
                 key);
    } else {
      error->all(FLERR, "Illegal fix etd command: unknown keyword {}", key);
    }
  });
  if (options.overdamped && options.warm_start)
    error->all(FLERR,
               "Illegal fix etd command: start velocity needs overdamped no (the zero-mass "
               "solve starts from the block-Jacobi solution)");
  return options;
}

void check_moments_of_inertia(LAMMPS *lmp, int groupbit, const char *who)
{
  Atom *atom = lmp->atom;
  tagint local_bad = 0, bad = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && atom->rmass[i] * atom->radius[i] * atom->radius[i] <= 0.0)
      local_bad = std::max(local_bad, atom->tag[i]);
  MPI_Allreduce(&local_bad, &bad, 1, MPI_LMP_TAGINT, MPI_MAX, lmp->world);
  if (bad > 0)
    lmp->error->all(FLERR,
                    "{}: atom {} has zero moment of inertia; give it a diameter (set ... "
                    "diameter) and a mass",
                    who, bad);
}

bool fix_etd_scheme_is_implicit(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
  for (int iarg = 3; iarg + 1 < narg; iarg += 2)
    if (std::string(arg[iarg]) == "scheme") {
      const std::string scheme = arg[iarg + 1];
      if (scheme == "implicit") return true;
      if (scheme != "diagonal")
        lmp->error->all(
            FLERR, "Illegal fix etd command: scheme must be diagonal or implicit, got {}", scheme);
    }
  return false;
}

}    // namespace etd
