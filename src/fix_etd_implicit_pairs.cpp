// ETD-DPD: fix etd scheme implicit, the pairs of each step: from LAMMPS's neighbor list, or from
// the scheme's own search (solver/cell_pair_search.h), and the check that none is missing.
//
// Why a search of its own: at the steps this scheme takes the fastest atoms move more than
// half of LAMMPS's skin in one step, so LAMMPS rebuilds its lists at every step; its build was
// about 45 % of a step of the standard fluid on one rank (bench/accuracy/README.md, "Cost of a
// step"). The own search runs once per step at the end positions, where the pair style's
// conservative forces are computed (pre_force), out to the largest cutoff plus a margin; the
// next friction step, half a drift later, uses the same pairs while the atoms stayed within
// that margin, and searches again otherwise. LAMMPS still moves atoms between ranks and makes
// the ghosts; it builds no pairwise list.
#include "fix_etd_implicit.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

// Why the own search cannot stand in for LAMMPS's list here, or nullptr where it can: its
// pairs are every pair within the cutoff, which the pair style must also be able to read.
const char *FixETDImplicit::own_pairs_unsupported() const
{
  if (dpd_styles.size() != 1 ||
      dynamic_cast<etd::DpdPairInterface *>(force->pair) != dpd_styles.front())
    return "pair style hybrid or hybrid/overlay (the other styles need LAMMPS's lists)";
  if (atom->molecular) return "a molecular system (special bonds weight or exclude pairs)";
  // (the counts: Neighbor::init() sets its exclude flag from them after this fix's init)
  if (neighbor->nex_type || neighbor->nex_group || neighbor->nex_mol) return "neigh_modify exclude";
  if (neighbor->includegroup) return "neigh_modify include";
  if (utils::strmatch(update->integrate_style, "^respa")) return "run_style respa";
  return nullptr;
}

// The search's cells are as large as the cutoff plus the margin (up to the skin). Where such a
// cell holds more than about a dozen atoms, LAMMPS's finer bins and its less frequent rebuilds
// win (measured on 1 rank: the eta = 30 fluid with rc = 1.5 at n = 4, 1.1-1.2 times LAMMPS's
// lists' time; at n = 5.29 4.7 times), where on the rc = 1 fluids at n = 3 and 4 the search saves
// 10 % (1 rank) to 35 % (2 ranks). The same on every rank: global counts only.
bool FixETDImplicit::own_pairs_pay() const
{
  const double reach = force->pair->cutforce + neighbor->skin;
  const double volume = domain->xprd * domain->yprd * (domain->dimension == 3 ? domain->zprd : 1.0);
  const double atoms_per_cell = static_cast<double>(atom->natoms) / volume * reach * reach * reach;
  return atoms_per_cell <= 12.0;
}

etd::PairListView FixETDImplicit::step_pairs() const
{
  return own.active ? own.view : etd::view_of(*list);
}

void FixETDImplicit::setup_pre_force(int vflag)
{
  if (!own.active) return;
  // the first friction step of a run moves atoms by h/2 (v + h F/m): the margin is learnt from
  // it (refresh_own_pairs), starting from none
  own.cutoff = std::max(force->pair->cutforce, assembly.friction_cutoff_max());
  own.margin = 0.0;
  pre_force(vflag);
}

void FixETDImplicit::pre_force(int)
{
  if (!own.active) return;
  search_own_pairs(own.margin);
  own.step = update->ntimestep;
}

// every pair within cutoff + margin at the current positions (ghosts' included)
void FixETDImplicit::search_own_pairs(double margin)
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const double *x = nall > 0 ? atom->x[0] : nullptr;
  own.search.build(x, nlocal, nall, own.cutoff + margin, list_newton_off, threads.chunks,
                   threads.runner);
  own.view = own.search.view();
  own.positions.assign(x, x + 3 * nlocal);
  partners.invalidate();    // the ghosts these pairs use
}

// At the friction step: the two largest displacements since the search (all ranks) must stay
// within the margin, or a pair now within the cutoff could be absent; then search again here.
// The margin follows the largest recent displacements, with room to grow.
void FixETDImplicit::refresh_own_pairs()
{
  double **x = atom->x;
  const int nlocal = atom->nlocal;
  // (the two largest of all ranges are the two largest of their parts)
  std::vector<double> tops(2 * threads.ranges(nlocal), 0.0);
  threads.for_ranges(nlocal, [&](int begin, int end, int range) {
    double *top = &tops[2 * range];
    for (int i = begin; i < end; i++) {
      double dsq = 0.0;
      for (int k = 0; k < 3; k++) dsq += std::pow(x[i][k] - own.positions[3 * i + k], 2);
      etd::keep_two_largest(top, std::sqrt(dsq));
    }
  });
  double top[2] = {tops[0], tops[1]};
  for (int range = 1; range < threads.ranges(nlocal); range++)
    for (int k = 0; k < 2; k++) etd::keep_two_largest(top, tops[2 * range + k]);
  const double local[3] = {0.0, top[0], top[1]};
  double global[3];
  etd::NeighborSafety::reduce_with_flag(local, global, world);
  const double moved = global[1] + global[2];
  if (moved > own.margin) search_own_pairs(0.0);
  // (the overdamped step also asks at its start, where nothing has moved yet)
  // (and never beyond the skin: atoms that far apart need the second search anyway)
  if (moved > 0.0) own.margin = std::min(std::max(1.25 * moved, 0.9 * own.margin), neighbor->skin);
}

void FixETDImplicit::build_pairs()
{
  if (own.active) refresh_own_pairs();
  const etd::PairListView pairs = step_pairs();
  if (!partners.current(neighbor->ncalls)) partners.find(lmp, this, pairs, ghosts);
  const etd::FrictionPairAssembly::Context context{pairs, &partners, groupbit, list_newton_off,
                                                   update->ntimestep};
  check_missing_pairs(assemble_pairs(context));
}

bool FixETDImplicit::assemble_pairs(const etd::FrictionPairAssembly::Context &context)
{
  return assembly.build(lmp, context);
}

// One reduction: whether a pair has an atom outside the group, and how far atoms are from where
// the list was built (this friction step's positions were not checked by LAMMPS); where two
// displacements add up to more than the skin, whether a pair is in fact missing (with the own
// search, whether an atom now within the cutoff of another is not among the ghosts).
void FixETDImplicit::check_missing_pairs(bool local_fixed_partner)
{
  double local[3] = {local_fixed_partner ? 1.0 : 0.0}, global[3];
  neighbor_safety.largest_displacements(lmp, groupbit, local + 1);
  etd::NeighborSafety::reduce_with_flag(local, global, world);
  any_fixed_partner = global[0] > 0.0;
  if (global[1] + global[2] <= neighbor->skin) return;
  auto friction_cutoff = [this](int itype, int jtype) {
    return assembly.friction_cutoff(itype, jtype);
  };
  const long missed = neighbor_safety.missed_pairs(lmp, groupbit, global + 1, friction_cutoff);
  if (missed > 0)
    error->all(FLERR,
               "Fix {}: {} pair(s) within the friction cutoff missing from the neighbor list "
               "at step {}: atoms moved up to {:.3g} since it was built, and two of them {:.3g} "
               "together, more than the skin {}; use a larger skin (neighbor command; at least "
               "{:.2g} here) or a smaller timestep",
               id, missed, update->ntimestep, global[1], global[1] + global[2], neighbor->skin,
               1.2 * (global[1] + global[2]));
  if (missed < 0) neighbor_safety.count_if_outrun(lmp, global + 1);
}
