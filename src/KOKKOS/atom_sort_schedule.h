// ETD-DPD: LAMMPS's atom sort, kept frequent while a style's kernels split the atoms among
// threads by index. LAMMPS's sort (atom_modify sort, every 1000 steps by default) keeps atoms
// that are close in space close in index; at small masses the atoms leave that order within tens
// of steps (bench/kokkos/README.md, "The atoms kept sorted"), and the threads then read and write
// each other's data in every pair loop. At a reneighboring at least `every` steps after the last
// sort, LAMMPS sorts again (its own sort and bins); a user period of `every` steps or fewer is
// kept, and atom_modify sort 0 sorts never. A fix asks from its pre_exchange(); a pair style,
// which has no hook there, keeps LAMMPS's next sort due from its compute(), only where its kernel
// runs on the host's threads (splits_by_index()); fix etd/kk scheme implicit, whose search and
// pair loop run there on any backend, asks on every backend.
#ifndef ETD_ATOM_SORT_SCHEDULE_H
#define ETD_ATOM_SORT_SCHEDULE_H

#include "atom.h"
#include "lmptype.h"

#include <Kokkos_Core.hpp>

#include <algorithm>

namespace etd::kk {

class AtomSortSchedule {
 public:
  static constexpr int every = 20;

  // whether kernels of ExecutionSpace split the atoms among threads by index: a host backend's
  // (OpenMP, Threads, Serial), not a device's, whose threads each take an atom
  template <class ExecutionSpace> static constexpr bool splits_by_index()
  {
    return Kokkos::SpaceAccessibility<ExecutionSpace, Kokkos::HostSpace>::accessible;
  }

  // the run's setup sorted the atoms (Verlet::setup, where atom_modify sort is on)
  void run_started(LAMMPS_NS::bigint step) { last_sort = step; }

  void before_exchange(LAMMPS_NS::Atom *atom, LAMMPS_NS::bigint step)
  {
    if (atom->sortfreq <= every || step - last_sort < every) return;
    atom->nextsort = step;
    last_sort = step;
  }

  // From a compute() at step: LAMMPS sorts at the first reneighboring from atom->nextsort on and
  // then moves it on by its own period, so a value other than the one set here means that LAMMPS
  // sorted at this step's reneighboring (or a run's setup did)
  void keep_due(LAMMPS_NS::Atom *atom, LAMMPS_NS::bigint step)
  {
    if (atom->sortfreq <= every) return;
    if (atom->nextsort != due) last_sort = step;
    due = std::min(atom->nextsort, last_sort + every);
    atom->nextsort = due;
  }

 private:
  LAMMPS_NS::bigint last_sort = 0;    // (LAMMPS keeps no record of it)
  LAMMPS_NS::bigint due = -1;         // the next sort keep_due() set
};

}    // namespace etd::kk

#endif
