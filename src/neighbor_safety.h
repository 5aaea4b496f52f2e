// ETD-DPD: fix etd and LAMMPS's neighbor-list settings.
//
// The package's integrators exist to take steps at which atoms travel a sizeable part of the
// skin per step. LAMMPS rebuilds the neighbor lists only after 'neigh_modify delay' steps and
// then every 'every' steps; in between, an atom that has moved more than half the skin can
// miss a partner, and nothing tells the user (29Sep2021 defaults to delay 10). So:
//  - init: an ERROR naming neigh_modify where the settings leave atoms unchecked for longer
//    than it takes the fastest atom, at the current step, to cover half the skin (the
//    zero-mass scheme has no speed to bound: it needs every 1 delay 0 check yes);
//  - during the run (implicit scheme): its friction step works at half-drifted positions,
//    half a step beyond where LAMMPS checked the list, so the fix asks for a rebuild one step
//    early where two atoms could reach each other unlisted there;
//  - at each friction step where two atoms' displacements add up to more than the skin
//    (implicit scheme): an ERROR if a pair within the cutoff is in fact missing from the list
//    (checked exactly among the few atoms that moved far enough to take part in one);
//  - end of run: a WARNING where the run had dangerous builds (LAMMPS's count), or friction
//    steps where too many atoms had moved far for that check.
#ifndef ETD_NEIGHBOR_SAFETY_H
#define ETD_NEIGHBOR_SAFETY_H

#include "lmptype.h"

#include <mpi.h>

#include <functional>
#include <vector>

namespace LAMMPS_NS {
class Fix;
class LAMMPS;
}    // namespace LAMMPS_NS

namespace etd {

// top[0] >= top[1]: the two largest of the values seen so far, d among them
inline void keep_two_largest(double top[2], double d)
{
  if (d > top[0]) {
    top[1] = top[0];
    top[0] = d;
  } else if (d > top[1]) {
    top[1] = d;
  }
}

// The number of steps LAMMPS may go between two looks at the atoms' displacements.
inline int unchecked_steps(int every, int delay)
{
  return every > delay ? every : delay;
}

// Whether atoms moving at most max_speed can cover half the skin within those steps.
inline bool settings_outrun_skin(int every, int delay, double dt, double max_speed, double skin)
{
  return unchecked_steps(every, delay) * dt * max_speed > 0.5 * skin;
}

class NeighborSafety {
 public:
  // init(): ERROR if the settings are unsafe for the fix's group at this step. inertial:
  // velocities bound the displacement; otherwise every step must be checked.
  void check_settings(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::Fix *fix, bool inertial) const;
  // setup(): remember LAMMPS's count of dangerous builds and forget the last run's outruns
  void start_run(LAMMPS_NS::LAMMPS *lmp);
  // post_neighbor(): the positions the new list was built from (owned atoms)
  void record_build_positions(LAMMPS_NS::LAMMPS *lmp);
  // The two largest displacements of the group's owned atoms on this rank since the list was
  // built (each moved on by lead, 3 values per owned atom, if given), into top[0] >= top[1].
  void largest_displacements(LAMMPS_NS::LAMMPS *lmp, int groupbit, double top[2],
                             const std::vector<double> *lead = nullptr) const;
  // Allreduce of {flag, top two}: the flag by max, and the two largest displacements of all
  // ranks (one reduction for the caller's flag and this check)
  static void reduce_with_flag(const double local[3], double global[3], MPI_Comm comm);
  // Whether two atoms of the group, each moved on by lead (3 values per owned atom), could
  // then be within the cutoff unlisted: their displacements since the list was built add up to
  // more than the skin (the test below, ahead of time). Collective.
  bool could_outrun(LAMMPS_NS::LAMMPS *lmp, int groupbit, const std::vector<double> &lead) const;
  // LAMMPS's own test (Neighbor::check_distance): two atoms may have come within the cutoff
  // unlisted once their two largest displacements add up to more than the skin; counted.
  void count_if_outrun(LAMMPS_NS::LAMMPS *lmp, const double top[2]);
  // Where that test fires, whether it happened: the pairs of the group's atoms now closer than
  // their types' cutoff (cutoff_of(itype, jtype), 0 for pairs the caller does not use) that
  // were farther apart than the list's reach (neighbor->cutneighmax) when it was built, so are
  // missing from it. Only atoms displaced by more than skin - top[0] can form one (the other's
  // displacement is at most top[0]); they are gathered from all ranks and every pair of them
  // is checked under the minimum-image convention. Returns that count, or -1 where it cannot
  // tell: more than max_checked atoms qualify, or the list leaves pairs out on purpose
  // (neigh_modify exclude, special bonds of a molecular system). Collective.
  long missed_pairs(LAMMPS_NS::LAMMPS *lmp, int groupbit, const double top[2],
                    const std::function<double(int, int)> &cutoff_of, int max_checked = 4096);
  // post_run(): the WARNING, once, from rank 0
  void end_run(LAMMPS_NS::LAMMPS *lmp, const char *fix_id) const;

 private:
  LAMMPS_NS::bigint danger_at_start = 0;
  long outruns = 0;
  std::vector<double> build_positions;
};

}    // namespace etd

#endif
