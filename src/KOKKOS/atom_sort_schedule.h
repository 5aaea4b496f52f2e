// ETD-DPD: LAMMPS's atom sort, kept frequent while a fix's kernels split the atoms among threads
// by index. LAMMPS's sort (atom_modify sort, every 1000 steps by default) keeps atoms that are
// close in space close in index; at small masses the atoms leave that order within tens of steps
// (bench/kokkos/README.md, "The atoms kept sorted"), and the threads then read and write each
// other's data in every pair loop. From the fix's pre_exchange(), at a reneighboring at least
// `every` steps after the last sort, LAMMPS is asked to sort again (its own sort and bins); a
// user period of `every` steps or fewer is kept, and atom_modify sort 0 sorts never.
#ifndef ETD_ATOM_SORT_SCHEDULE_H
#define ETD_ATOM_SORT_SCHEDULE_H

#include "atom.h"
#include "lmptype.h"

namespace etd::kk {

class AtomSortSchedule {
 public:
  static constexpr int every = 20;

  // the run's setup sorted the atoms (Verlet::setup, where atom_modify sort is on)
  void run_started(LAMMPS_NS::bigint step) { last_sort = step; }

  void before_exchange(LAMMPS_NS::Atom *atom, LAMMPS_NS::bigint step)
  {
    if (atom->sortfreq <= every || step - last_sort < every) return;
    atom->nextsort = step;
    last_sort = step;
  }

 private:
  LAMMPS_NS::bigint last_sort = 0;    // (LAMMPS keeps no record of it)
};

}    // namespace etd::kk

#endif
