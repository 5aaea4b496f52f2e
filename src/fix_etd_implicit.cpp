// ETD-DPD: fix etd ... scheme implicit.
//
// Inertial (default), per step of length h = dt (BAOAB in its half-step, leapfrog form):
//   v += h F/m;  x += h/2 v;  solve (M + h/2 G) v' = (M - h/2 G) v + sqrt(h) B xi;
//   x += h/2 v';  [LAMMPS: neighbors, forces F(x)]
// The trajectory is BAOAB's (B(h/2) A O A B(h/2), the closing half kick merged into the next
// step's opening one); what differs is where the velocities are read. atom->v holds v', the
// friction step's output, at the end of every step: in the harmonic limit its kinetic
// temperature is exact at any step, while BAOAB's end-of-step velocity runs cool by about
// h^2 <F^2> / (4 m kBT), which thermo, dumps and the kinetic stress would all see
// (doc/fix_etd.rst, "Which velocities a step leaves").
// F holds every non-dissipative force (the package's pair styles leave out their friction and
// noise while this scheme runs). Overdamped (m -> 0):
//   solve G v = F + B xi / sqrt(h);  x += h v
// G, B and xi are built at the positions where the solve happens, from the fix's own half
// neighbor list (newton off: see partner_exchange.h) and the pair styles' coefficients; atoms
// outside the group keep their velocities (walls, a fixed sphere) and enter G with them. With
// dpd/fpm pairs the unknowns are (v, Omega) per atom, M holds masses and moments of inertia,
// and G couples translation and rotation through the pairs' shear friction
// (friction_operator.h).
#include "fix_etd_implicit.h"

#include "close_neighbors.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "dpd_kernel.h"
#include "dpd_style_lookup.h"
#include "error.h"
#include "force.h"
#include "fpm_kernel.h"
#include "lammps_compat.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

FixETDImplicit::FixETDImplicit(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), overdamped(false), midpoint(true), warm_start(false), tolerance(1e-6),
    max_iterations(200), dt(0.0), list(nullptr), list_newton_off(true), dofs(3),
    any_fixed_partner(false), partners_built(-1), partner_slots(0), comm_nslots(0),
    comm_positions(false), split_requested(false), split_rows(0), split(nullptr),
    last_iterations(0), last_residual(0.0), iterations_sum(0.0), solves(0), predictor_steps(0),
    end_velocity(nullptr)
{
  time_integrate = 1;
  force_reneighbor = 1;    // post_integrate() may ask for an early rebuild
  next_reneighbor = -1;
  vector_flag = 1;
  size_vector = 5;
  extvector = 0;
  global_freq = 1;
  // per atom: the velocity at the end of the step in BAOAB's sense, v + h/2 F/m (v holds the
  // friction step's output): its mean is the streaming velocity, without v's offset of
  // h/2 <F>/m under a steady force (doc/fix_etd.rst, "Which velocities a step leaves")
  peratom_flag = 1;
  size_peratom_cols = 3;
  peratom_freq = 1;
  comm_forward = 9;    // positions and 3 values per atom (v), 6 with rotation (v, Omega)
  // the dissipative and random forces are this fix's, so is their virial (pressure, stress)
  virial_global_flag = virial_peratom_flag = 1;
  thermo_virial = 1;
  peratom_virial = false;

  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (iarg + 2 > narg)
      error->all(FLERR, "Illegal fix etd command: keyword {} needs a value", key);
    const std::string value = arg[iarg + 1];
    if (key == "scheme") {
      if (value != "implicit")
        error->all(FLERR, "Illegal fix etd command: scheme must be diagonal or implicit, got {}",
                   value);
    } else if (key == "overdamped") {
      if (value == "yes")
        overdamped = true;
      else if (value == "no")
        overdamped = false;
      else
        error->all(FLERR, "Illegal fix etd command: overdamped must be yes or no, got {}", value);
    } else if (key == "tol") {
      tolerance = utils::numeric(FLERR, value.c_str(), false, lmp);
      if (!(tolerance > 0.0 && tolerance < 1.0))
        error->all(FLERR, "Illegal fix etd command: tol must be between 0 and 1, got {}", value);
    } else if (key == "midpoint") {
      if (value == "yes")
        midpoint = true;
      else if (value == "no")
        midpoint = false;
      else
        error->all(FLERR, "Illegal fix etd command: midpoint must be yes or no, got {}", value);
    } else if (key == "start") {
      if (value == "velocity")
        warm_start = true;
      else if (value == "jacobi")
        warm_start = false;
      else
        error->all(FLERR, "Illegal fix etd command: start must be velocity or jacobi, got {}",
                   value);
    } else if (key == "maxiter") {
      max_iterations = utils::inumeric(FLERR, value.c_str(), false, lmp);
      if (max_iterations < 1)
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
    iarg += 2;
  }

  if (overdamped && warm_start)
    error->all(FLERR,
               "Illegal fix etd command: start velocity needs overdamped no (the zero-mass "
               "solve starts from the block-Jacobi solution)");

  partners.reset(new etd::PartnerExchange(world));

  // per-atom split for compute dpd/split, kept with the atoms when they migrate or are sorted
  maxexchange = 15;    // the split, the per-atom virial (vatom) and the end-of-step velocity,
                       // which must travel too: the atoms migrate and are sorted after the
                       // step that set them
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
}

FixETDImplicit::~FixETDImplicit()
{
  atom->delete_callback(id, Atom::GROW);
  memory->destroy(split);
  memory->destroy(end_velocity);
}

int FixETDImplicit::setmask()
{
  return INITIAL_INTEGRATE | POST_INTEGRATE | FINAL_INTEGRATE | POST_NEIGHBOR | POST_RUN;
}

void FixETDImplicit::init()
{
  dt = update->dt;
  dpd_styles = etd::fix_etd_pair_styles(lmp, "friction");
  if (atom->tag_enable == 0)
    error->all(FLERR, "Fix etd scheme implicit requires atom IDs (its noise is keyed on them)");
  // Atoms outside the group enter the solve with their velocities held: walls, obstacles and
  // atoms moved by fix move. Another integrator moving them (fix nve, fix rigid/small) would
  // see no DPD friction or noise on them: the pair styles leave both to this fix, whose solve
  // does not give the reaction back to atoms it does not integrate, nor treat pairs of them.
  for (int f = 0; f < modify->nfix; f++) {
    Fix *other = modify->fix[f];
    if (other == this || !other->time_integrate || utils::strmatch(other->style, "^move")) continue;
    error->all(FLERR,
               "Fix etd scheme implicit cannot be combined with fix {} ({}): the DPD friction "
               "and noise of the atoms it integrates would be lost (the pair style leaves them to "
               "the implicit scheme, which holds atoms outside its group at their velocities). "
               "Integrate every DPD atom with fix etd scheme implicit, or use fix etd scheme "
               "diagonal, whose pair forces stay complete",
               other->id, other->style);
  }
  // Under a steady force the friction step's output, which v holds, lags the streaming
  // velocity by h/2 <F>/m (doc/fix_etd.rst): say where mean velocities should be read.
  if (!overdamped && comm->me == 0 && !warned_force_fixes)
    for (int f = 0; f < modify->nfix; f++)
      if (modify->fix[f] != this && (modify->fmask[f] & POST_FORCE)) {
        warned_force_fixes = true;
        error->warning(FLERR,
                       "Fix etd scheme implicit: fix {} ({}) adds forces; under a steady force "
                       "the velocities in v lag the streaming velocity by dt/2 <F>/m: read mean "
                       "velocities (flow profiles, drift) from the fix's per-atom output "
                       "f_{}[1], f_{}[2], f_{}[3]",
                       modify->fix[f]->id, modify->fix[f]->style, id, id, id);
      }
  // fix wall/reflect/stochastic moves an atom that crossed its wall back along the atom's
  // velocity at post_integrate (it assumes the atom travelled with it). Here the atom travelled
  // with the mean of the velocities before and after the friction step, so an atom whose normal
  // velocity the step reversed is put back beyond the wall and is lost later (measured: the
  // sphere-in-Couette example, one atom by step 650). The overdamped drift uses the velocity
  // it leaves in v, so it is not affected.
  if (Fix *walls = overdamped ? nullptr : etd::find_fix_style(lmp, "^wall/reflect/stochastic"))
    error->all(FLERR,
               "Fix etd scheme implicit cannot be combined with fix wall/reflect/stochastic ({}): "
               "that fix puts an atom that crossed its wall back along the atom's velocity after "
               "the step, which under the implicit friction step is not the velocity the atom "
               "travelled with, and atoms are left beyond the wall. Use fix wall/reflect with fix "
               "wall/thermal/layer for thermal walls, or fix etd scheme diagonal",
               walls->id);

  const int ntypes = atom->ntypes;
  pair_table.assign((ntypes + 1) * (ntypes + 1), nullptr);
  fpm_table.assign((ntypes + 1) * (ntypes + 1), nullptr);
  bool rotation = false;
  for (auto *p : dpd_styles) {
    bool supplies = false;
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++) {
        if (const etd::PairCoefficients *c = p->dpd_coefficients(i, j)) {
          pair_table[i * (ntypes + 1) + j] = c;
          supplies = true;
        }
        if (const etd::FpmCoefficients *c = p->fpm_coefficients(i, j)) {
          fpm_table[i * (ntypes + 1) + j] = c;
          supplies = rotation = true;
        }
      }
    // a style that cannot hand over its friction must not be silently reduced to its
    // conservative part
    if (!supplies)
      error->all(FLERR, "Fix etd scheme implicit: a pair style supplies no DPD coefficients");
    p->request_conservative_only();
  }
  friction_cutsq_max = 0.0;
  for (const etd::PairCoefficients *c : pair_table)
    if (c && c->gamma != 0.0) friction_cutsq_max = std::max(friction_cutsq_max, c->rcsq_d);
  for (const etd::FpmCoefficients *c : fpm_table)
    if (c) friction_cutsq_max = std::max(friction_cutsq_max, c->rcsq);
  dofs = rotation ? 6 : 3;
  if (rotation) {
    if (!atom->omega_flag || !atom->torque_flag || !atom->radius_flag || !atom->rmass_flag)
      error->all(FLERR,
                 "Fix etd scheme implicit with pair style dpd/fpm needs angular velocities, "
                 "torques, radii and per-atom masses (atom_style sphere)");
    if (overdamped)
      error->all(FLERR,
                 "Fix etd scheme implicit: overdamped yes is not available with pair style "
                 "dpd/fpm (its rotation needs inertia); use overdamped no with a small mass");
    tagint local_bad = 0, bad = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & groupbit) && atom->rmass[i] * atom->radius[i] * atom->radius[i] <= 0.0)
        local_bad = MAX(local_bad, atom->tag[i]);
    MPI_Allreduce(&local_bad, &bad, 1, MPI_LMP_TAGINT, MPI_MAX, world);
    if (bad > 0)
      error->all(FLERR,
                 "Fix etd scheme implicit: atom {} has zero moment of inertia; give it a "
                 "diameter (set ... diameter) and a mass",
                 bad);
  }
  noise = etd::PairNoise(dpd_styles.front()->noise_seed(), etd::NoiseStream::Integrator);
  // On several ranks the list is newton off, so that a pair crossing ranks is held by both
  // (partner_exchange.h); on one rank there is no such pair, and the default list is a free
  // copy of the pair style's where the newton settings agree.
  const bool several_ranks = comm->nprocs > 1;
  // With newton on, this newton-off list would be a second list, built at every reneighboring
  // beside the pair style's newton-on one (measured: it doubled the neighbor time of a 2-rank
  // step). A lone style (not in hybrid) makes its own list newton off instead, and LAMMPS then
  // hands this fix a copy of it.
  if (several_ranks && force->newton_pair && dpd_styles.size() == 1 &&
      dynamic_cast<etd::DpdPairInterface *>(force->pair) == dpd_styles.front())
    dpd_styles.front()->request_newton_off_list();
  etd::compat::request_fix_half_list(neighbor, this, instance_me, several_ranks);
  list_newton_off = several_ranks || !force->newton_pair;
  partners_built = -1;
  neighbor_safety.check_settings(lmp, this, !overdamped);
  peratom_virial = false;
  for (int c = 0; c < modify->ncompute; c++)
    if (modify->compute[c]->pressatomflag) peratom_virial = true;
}

void FixETDImplicit::init_list(int, NeighList *ptr)
{
  list = ptr;
}

void FixETDImplicit::setup(int)
{
  neighbor_safety.start_run(lmp);
  // no friction step yet: a pressure evaluated at the set-up step has no friction virial
  for (int k = 0; k < 6; k++) virial[k] = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < 6; k++) vatom[i][k] = 0.0;
  record_end_velocity();
}
void FixETDImplicit::setup_post_neighbor()
{
  neighbor_safety.record_build_positions(lmp);
}
void FixETDImplicit::post_neighbor()
{
  neighbor_safety.record_build_positions(lmp);
}
void FixETDImplicit::post_run()
{
  neighbor_safety.end_run(lmp, id);
}

void FixETDImplicit::reset_dt()
{
  dt = update->dt;
}

/* ---------------------------------------------------------------------- */

void FixETDImplicit::kick(double fraction)
{
  double **v = atom->v;
  double **f = atom->f;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) {
      const double scale = fraction * dt / atom_mass(i);
      for (int k = 0; k < 3; k++) v[i][k] += scale * f[i][k];
    }
  if (dofs == 6) {    // torques from anything but the DPD friction and noise (none from dpd/fpm)
    double **omega = atom->omega;
    double **torque = atom->torque;
    const double *radius = atom->radius;
    for (int i = 0; i < atom->nlocal; i++)
      if (mask[i] & groupbit) {
        const double scale = fraction * dt / (0.4 * atom->rmass[i] * radius[i] * radius[i]);
        for (int k = 0; k < 3; k++) omega[i][k] += scale * torque[i][k];
      }
  }
}

// each unknown's inertia: mass for velocities, 0.4 m r^2 for angular velocities
void FixETDImplicit::dof_inertia(std::vector<double> &inertia) const
{
  const int nlocal = atom->nlocal;
  inertia.resize(dofs * nlocal);
  for (int i = 0; i < nlocal; i++) {
    const double m = atom_mass(i);
    for (int k = 0; k < 3; k++) inertia[dofs * i + k] = m;
    if (dofs == 6)
      for (int k = 3; k < 6; k++)
        inertia[dofs * i + k] = 0.4 * m * atom->radius[i] * atom->radius[i];
  }
}

// the unknowns of atom i as stored in LAMMPS: v, then Omega with rotation
double *FixETDImplicit::dof_pointer(int i, int k) const
{
  return (k < 3) ? &atom->v[i][k] : &atom->omega[i][k - 3];
}

void FixETDImplicit::drift(double fraction)
{
  double **x = atom->x;
  double **v = atom->v;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit)
      for (int k = 0; k < 3; k++) x[i][k] += fraction * dt * v[i][k];
}

void FixETDImplicit::initial_integrate(int)
{
  virial_this_step = virial_wanted();
  if (overdamped) {
    overdamped_step();
    return;
  }
  kick(1.0);
  drift(0.5);
  // (friction_noise_step() brings the ghosts to the half-drifted positions)
  friction_noise_step();
  drift(0.5);
}

// The per-atom output: BAOAB's end-of-step velocity v + h/2 F/m of the group's atoms (their
// own velocity for the others, and when overdamped, where v is the velocity the atoms moved
// with). F is the force of the step's end: LAMMPS has just computed it.
void FixETDImplicit::final_integrate()
{
  record_end_velocity();
}

void FixETDImplicit::record_end_velocity()
{
  for (int i = 0; i < atom->nlocal; i++) {
    const bool kicked = !overdamped && (atom->mask[i] & groupbit);
    const double scale = kicked ? 0.5 * dt / atom_mass(i) : 0.0;
    for (int k = 0; k < 3; k++) end_velocity[i][k] = atom->v[i][k] + scale * atom->f[i][k];
  }
}

double FixETDImplicit::atom_mass(int i) const
{
  return atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]];
}

// The next friction step happens at x + h/2 (v + h F/m) (the next step's first kick and half
// drift; the last force evaluation stands in for the coming one), or overdamped near x + h/2 v;
// LAMMPS's check after this looks only at x. Where two atoms could be within the cutoff
// unlisted there, the list is rebuilt now.
void FixETDImplicit::post_integrate()
{
  const int nlocal = atom->nlocal;
  double **v = atom->v;
  double **f = atom->f;
  std::vector<double> &lead = work.lead;
  lead.resize(3 * nlocal);
  for (int i = 0; i < nlocal; i++) {
    const double kick = overdamped ? 0.0 : dt / atom_mass(i);
    for (int k = 0; k < 3; k++) lead[3 * i + k] = 0.5 * dt * (v[i][k] + kick * f[i][k]);
  }
  if (neighbor_safety.could_outrun(lmp, groupbit, lead)) next_reneighbor = update->ntimestep;
}

/* ---- the pair geometry of this step ---------------------------------------------------- */

// Which atom of the partner numbering (fix_etd_implicit.h) each ghost the list uses stands for:
// an image of an owned atom is that atom, an atom of another rank gets a slot. Found once per
// neighbor list build (ghosts are renumbered only then); collective.
void FixETDImplicit::find_partners()
{
  const int nlocal = atom->nlocal;
  const int nghost = atom->nghost;
  // every ghost learns its owner (rank, local index), exact in doubles
  std::vector<double> &owner = work.ghost_owner;
  owner.resize(2 * (nlocal + nghost));
  for (int i = 0; i < nlocal; i++) {
    owner[2 * i] = comm->me;
    owner[2 * i + 1] = i;
  }
  // and how many box vectors it lies from its owner (the velocity offset of a moving image)
  std::vector<double> &image = work.ghost_image;
  image.assign(6 * (nlocal + nghost), 0.0);
  forward_exchange({{&owner, 2}, {&image, 6, true}});

  struct Remote {
    int rank, index, ghost;
  };
  std::vector<Remote> remote;
  constexpr int unused = -1, remote_mark = -2;
  ghost_partner.assign(nghost, unused);
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (j < nlocal || ghost_partner[j - nlocal] != unused) continue;
      const int rank = static_cast<int>(owner[2 * j]);
      const int index = static_cast<int>(owner[2 * j + 1]);
      if (rank == comm->me) {
        ghost_partner[j - nlocal] = index;
      } else {
        ghost_partner[j - nlocal] = remote_mark;
        remote.push_back({rank, index, j});
      }
    }
  }
  // slots grouped by owner; several images of one remote atom share its slot
  std::sort(remote.begin(), remote.end(), [](const Remote &a, const Remote &b) {
    return a.rank != b.rank ? a.rank < b.rank : a.index < b.index;
  });
  std::vector<int> slot_rank, slot_index;
  slot_ghost.clear();
  for (const Remote &r : remote) {
    if (slot_rank.empty() || r.rank != slot_rank.back() || r.index != slot_index.back()) {
      slot_rank.push_back(r.rank);
      slot_index.push_back(r.index);
      slot_ghost.push_back(r.ghost);
    }
    ghost_partner[r.ghost - nlocal] = nlocal + static_cast<int>(slot_rank.size()) - 1;
  }
  partner_slots = static_cast<int>(slot_rank.size());
  partners->set_requests(slot_rank, slot_index);
  partners_built = neighbor->ncalls;
}

int FixETDImplicit::npartners() const
{
  return atom->nlocal + partner_slots;
}

// The velocity a periodic image has on top of its owner's under fix deform ... remap v, as
// LAMMPS's own ghost communication adds it (AtomVec::pack_comm_vel); false where it has none.
bool FixETDImplicit::image_velocity(int ghost, double offset[3]) const
{
  if (!(atom->mask[ghost] & domain->deform_groupbit)) return false;
  const double *n = &work.ghost_image[6 * ghost];
  const double *rate = domain->h_rate;
  offset[0] = n[0] * rate[0] + n[5] * rate[5] + n[4] * rate[4];
  offset[1] = n[1] * rate[1] + n[3] * rate[3];
  offset[2] = n[2] * rate[2];
  return offset[0] != 0.0 || offset[1] != 0.0 || offset[2] != 0.0;
}

void FixETDImplicit::build_pairs()
{
  if (partners_built != neighbor->ncalls) find_partners();
  double **x = atom->x;
  const int *type = atom->type;
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;
  const double *special_lj = force->special_lj;
  const int ntypes1 = atom->ntypes + 1;
  const int nlocal = atom->nlocal;
  const std::int64_t step = update->ntimestep;

  pairs.clear();
  pair_noise.clear();
  pair_tags.clear();
  fpm_pairs.clear();
  fpm_noise.clear();
  pair_distance.clear();
  pair_offset.clear();
  fpm_offset.clear();
  const bool moving_images = domain->deform_vremap;
  image_friction.assign(moving_images ? dofs * nlocal : 0, 0.0);
  auto keep_j = [=](int j) {
    return j < nlocal;
  };
  // j's velocity on top of its owner's (a moving image); zero for owned atoms and resting images
  double offset[3];
  auto moving_image = [&](int j) {
    if (j >= nlocal && image_velocity(j, offset)) return true;
    offset[0] = offset[1] = offset[2] = 0.0;
    return false;
  };
  int fixed_partner = 0;
  const double *xflat = nlocal + atom->nghost > 0 ? x[0] : nullptr;    // rows at 3 j
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    const bool i_mobile = mask[i] & groupbit;
    const double xi0 = xflat[3 * i], xi1 = xflat[3 * i + 1], xi2 = xflat[3 * i + 2];
    // about half of the list lies in its skin: rejected by distance alone, before any of the
    // per-pair lookups below (close_neighbors.h)
    const int nclose = etd::gather_close_neighbors(
        jlist, jnum, NEIGHMASK, xflat, xi0, xi1, xi2,
        [&](int, double rsq) {
          return rsq < friction_cutsq_max;
        },
        work.close);
    const int *close = work.close.data();
    for (int jj = 0; jj < nclose; jj++) {
      const int j_bits = close[jj];
      const int j = j_bits & NEIGHMASK;
      const double *xj = xflat + 3 * j;
      const double d[3] = {xi0 - xj[0], xi1 - xj[1], xi2 - xj[2]};
      const double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const double factor = special_lj[(j_bits >> SBBITS) & 3];
      if (factor == 0.0) continue;
      int partner = j;
      if (j >= nlocal) {
        partner = ghost_partner[j - nlocal];
        // an image of an owned atom: a newton-off list holds the pair from both ends, one is
        // kept (an atom and its own image have no relative velocity and opposite noise)
        if (partner < nlocal && list_newton_off && tag[i] >= tag[partner]) continue;
      }
      const bool j_mobile = mask[j] & groupbit;
      if (!i_mobile && !j_mobile) continue;
      const etd::PairCoefficients *c = pair_table[type[i] * ntypes1 + type[j]];
      if (!c) {
        const etd::FpmCoefficients *fc = fpm_table[type[i] * ntypes1 + type[j]];
        if (fc && add_fpm_pair(*fc, i, partner, d, rsq, factor, tag[i], tag[j], step)) {
          if (!i_mobile || !j_mobile) fixed_partner = 1;
          if (moving_images) {
            if (moving_image(j))
              etd::accumulate_fpm_image_offset(fpm_pairs.back(), offset, image_friction.data(),
                                               keep_j);
            fpm_offset.insert(fpm_offset.end(), offset, offset + 3);
          }
        }
        continue;
      }
      if (c->gamma == 0.0) continue;
      if (rsq >= c->rcsq_d || rsq == 0.0) continue;
      const double r = std::sqrt(rsq);
      const double inv_r = 1.0 / r;
      const etd::PairDissipation dissipation = etd::pair_dissipation(*c, r, factor);
      // written in place (a pair assembled on the stack and copied stalled on the copy)
      pairs.emplace_back();
      etd::FrictionPair &p = pairs.back();
      p.i = i;
      p.j = partner;
      for (int k = 0; k < 3; k++) p.e[k] = static_cast<float>(d[k] * inv_r);
      p.friction = static_cast<float>(dissipation.friction);
      // the amplitude now, the Gaussian in a second pass: without the generator in it this
      // loop is short enough for the processor to overlap the square roots of successive pairs
      pair_noise.push_back(dissipation.noise);
      pair_tags.push_back({tag[i], tag[j]});
      if (!i_mobile || !j_mobile) fixed_partner = 1;
      pair_distance.push_back(r);
      if (moving_images) {
        if (moving_image(j))
          etd::accumulate_image_offset(p, offset, image_friction.data(), keep_j, dofs);
        pair_offset.insert(pair_offset.end(), offset, offset + 3);
      }
    }
  }
  for (size_t n = 0; n < pairs.size(); n++)
    pair_noise[n] *= noise.gaussian(pair_tags[n].first, pair_tags[n].second, step);
  etd::find_runs(pairs, pair_runs);
  // one reduction: a pair with an atom outside the group, and how far atoms are from where the
  // list was built (this friction step's positions were not checked by LAMMPS)
  double local[3] = {static_cast<double>(fixed_partner)}, global[3];
  neighbor_safety.largest_displacements(lmp, groupbit, local + 1);
  etd::NeighborSafety::reduce_with_flag(local, global, world);
  any_fixed_partner = global[0] > 0.0;
  // where two displacements add up to more than the skin, whether a pair is in fact missing
  if (global[1] + global[2] > neighbor->skin) {
    // a type pair's friction cutoff, 0 where the friction step has no pairs of those types
    auto friction_cutoff = [this, ntypes1](int itype, int jtype) {
      const etd::PairCoefficients *c = pair_table[itype * ntypes1 + jtype];
      if (c) return c->gamma != 0.0 ? c->rc_d : 0.0;
      const etd::FpmCoefficients *fc = fpm_table[itype * ntypes1 + jtype];
      return fc ? fc->rc : 0.0;
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
}

// One dpd/fpm pair (friction_operator.h): its geometry and its random force on i (without the
// time factor), sqrt(w) [sigma_C theta_C e + sigma_S theta_A x e]; false outside the cutoff.
bool FixETDImplicit::add_fpm_pair(const etd::FpmCoefficients &c, int i, int j, const double d[3],
                                  double rsq, double factor, tagint tag_i, tagint tag_j,
                                  std::int64_t step)
{
  if (rsq >= c.rcsq || rsq == 0.0 || (c.gamma_c == 0.0 && c.gamma_s == 0.0)) return false;
  const double r = std::sqrt(rsq);
  const etd::FpmDissipation dissipation = etd::fpm_dissipation(c, r, factor);
  const double e[3] = {d[0] / r, d[1] / r, d[2] / r};
  etd::FpmFrictionPair p;
  p.i = i;
  p.j = j;
  for (int k = 0; k < 3; k++) p.e[k] = static_cast<float>(e[k]);
  p.half_r = static_cast<float>(0.5 * r);
  p.central = static_cast<float>(dissipation.central);
  p.shear = static_cast<float>(dissipation.shear);
  fpm_pairs.push_back(p);
  double theta[4];
  noise.gaussians4(tag_i, tag_j, step, 0, theta);
  etd::FpmNoise pair_noise;
  pair_noise.central = theta[0];
  for (int k = 0; k < 3; k++) pair_noise.shear[k] = theta[k + 1];
  const etd::FpmRandomForce random = etd::fpm_random_force(c, e, dissipation.noise, pair_noise);
  for (int k = 0; k < 3; k++) fpm_noise.push_back(random.central * e[k] + random.shear[k]);
  return true;
}

// gu = G u over owned atoms (u given on owned atoms; the remote partners are filled here). With
// group_only, atoms outside the group count as at rest (the solver's unknowns are the group's
// velocities).
void FixETDImplicit::apply_friction(const double *u, std::vector<double> &gu, bool group_only)
{
  gather_operand(u, group_only);
  gu.assign(dofs * atom->nlocal, 0.0);
  accumulate_friction(operand.data(), gu.data());
}

// operand = u on all partners (u given on owned atoms; the remote slots filled by their owners)
void FixETDImplicit::gather_operand(const double *u, bool group_only)
{
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  operand.resize(dofs * npartners());
  if (group_only) {
    for (int i = 0; i < nlocal; i++) {
      const double keep = (mask[i] & groupbit) ? 1.0 : 0.0;
      for (int k = 0; k < dofs; k++) operand[dofs * i + k] = keep * u[dofs * i + k];
    }
  } else {
    std::copy(u, u + dofs * nlocal, operand.begin());
  }
  partners->exchange(operand.data(), nlocal, dofs);
}

// gu += scale G u over owned atoms from u given on all partners (a remote partner's share is
// its owner's to compute)
void FixETDImplicit::accumulate_friction(const double *u, double *gu, double scale) const
{
  const int nlocal = atom->nlocal;
  auto keep_j = [=](int j) {
    return j < nlocal;
  };
  if (dofs == 3)
    etd::accumulate_friction_by_runs<3>(pairs, pair_runs, u, gu, keep_j, scale);
  else
    etd::accumulate_friction_by_runs<6>(pairs, pair_runs, u, gu, keep_j, scale);
  if (dofs == 6) etd::accumulate_fpm_friction(fpm_pairs, u, gu, keep_j, scale);
}

// the random impulse sum_pairs B xi, times scale, on owned atoms (a pair that crosses ranks
// draws the same theta on both: the noise is keyed on the atom IDs)
void FixETDImplicit::random_impulse(double scale, std::vector<double> &impulse)
{
  const int nlocal = atom->nlocal;
  impulse.assign(dofs * nlocal, 0.0);
  auto keep_j = [=](int j) {
    return j < nlocal;
  };
  etd::accumulate_noise(pairs, pair_noise, scale, impulse.data(), keep_j, dofs);
  if (dofs == 6) etd::accumulate_fpm_noise(fpm_pairs, fpm_noise, scale, impulse.data(), keep_j);
}

// each owned atom's 3x3 block(s) of G (6 values each, v-v and with rotation Omega-Omega)
void FixETDImplicit::accumulate_blocks(int block_values)
{
  const int nlocal = atom->nlocal;
  diagonal.assign(block_values * nlocal, 0.0);
  auto keep_j = [=](int j) {
    return j < nlocal;
  };
  etd::accumulate_blocks(pairs, diagonal.data(), keep_j, block_values);
  if (dofs == 6) etd::accumulate_fpm_blocks(fpm_pairs, diagonal.data(), keep_j);
}

/* ---- the solves ------------------------------------------------------------------------ */

// (mass_weight M + friction_weight G) x = rhs over the group's atoms on this rank, atoms
// outside the group held at zero (their velocities are already in rhs). With 'deflate' the
// uniform translation (null space of G) is projected out of rhs and of the solution.
bool FixETDImplicit::solve(const std::vector<double> &rhs_in, std::vector<double> &solution,
                           double mass_weight, double friction_weight, bool deflate,
                           bool singular_ok, const std::vector<double> *start,
                           const std::vector<double> *start_friction)
{
  const int *mask = atom->mask;
  dof_inertia(work.masses);
  accumulate_blocks(2 * dofs);    // G's diagonal 3x3 blocks, the preconditioner's

  etd::FrictionSystem system;
  system.n = dofs * atom->nlocal;
  system.inertia = work.masses.data();
  system.blocks = diagonal.data();
  system.mass_weight = mass_weight;
  system.friction_weight = friction_weight;
  system.deflate = deflate;
  // atoms outside the group are held at rest (their velocities are already in rhs)
  auto mobile = [&](int block) {
    return (mask[block * 3 / dofs] & groupbit) != 0;
  };
  auto apply_friction = [this](const double *u, double *out, double weight) {
    gather_operand(u, true);
    accumulate_friction(operand.data(), out, weight);
  };
  auto global_sum = [this](double *values, int count) {
    double sums[16];    // the solver sums at most 9 values at once
    MPI_Allreduce(values, sums, count, MPI_DOUBLE, MPI_SUM, world);
    for (int k = 0; k < count; k++) values[k] = sums[k];
  };
  const etd::SolverResult result = etd::solve_friction_system(
      system, mobile, apply_friction, global_sum, rhs_in.data(), solution, tolerance,
      max_iterations, work.solve, start ? start->data() : nullptr,
      (start && start_friction) ? start_friction->data() : nullptr);

  last_iterations = result.iterations;
  last_residual = result.relative_residual;
  iterations_sum += result.iterations;
  solves++;
  // without inertia a failed solve means a (nearly) singular G: an atom has lost its DPD
  // partners in some direction, so its mobility there is unbounded; moving it would throw it
  // out of the box. The overdamped step decides what to do (singular_ok).
  if (!result.converged && mass_weight == 0.0) {
    if (singular_ok) return false;
    error->all(FLERR,
               "Fix etd overdamped yes: conjugate gradients did not converge ({} iterations, "
               "relative residual {:.3g}): the friction system is nearly singular (an atom without "
               "DPD partners in some direction). Start from an equilibrated configuration, use a "
               "smaller timestep, or the inertial implicit scheme with a small mass",
               result.iterations, result.relative_residual);
  }
  if (!result.converged && comm->me == 0)
    error->warning(FLERR,
                   "Fix etd scheme implicit: conjugate gradients stopped after {} "
                   "iterations at relative residual {:.3g} (tol {:.3g}); raise maxiter or the step",
                   result.iterations, result.relative_residual, tolerance);
  return result.converged;
}

void FixETDImplicit::friction_noise_step()
{
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double h = dt;

  // b = M q - h/2 G (q + q_fixed) + sqrt(h) B xi: the fixed atoms' velocities appear twice,
  // once from the old and once from the new side of the Pade update (q = v, or v and Omega)
  std::vector<double> &u = work.u, &gu = work.gu_rhs, &rhs = work.step_rhs, &impulse = work.impulse;
  std::vector<double> &inertia = work.inertia;
  dof_inertia(inertia);
  // One forward exchange brings the ghosts to the half-drifted positions and carries their
  // velocities (every exchange is a point where the ranks wait for each other)
  const int nall = nlocal + atom->nghost;
  std::vector<double> &ghost_u = work.ghost_u;
  ghost_u.resize(dofs * nall);
  rhs.resize(dofs * nlocal);
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < dofs; k++) ghost_u[dofs * i + k] = *dof_pointer(i, k);
  forward_exchange({{&ghost_u, dofs}}, true);
  build_pairs();
  // u over the partners: owned atoms, then each remote slot from one of its ghost images
  u.resize(dofs * npartners());
  std::copy(ghost_u.begin(), ghost_u.begin() + dofs * nlocal, u.begin());
  for (int s = 0; s < partner_slots; s++)
    for (int k = 0; k < dofs; k++) u[dofs * (nlocal + s) + k] = ghost_u[dofs * slot_ghost[s] + k];
  for (int p = 0; p < npartners(); p++) {
    if (mask[p < nlocal ? p : slot_ghost[p - nlocal]] & groupbit) continue;
    for (int k = 0; k < dofs; k++) u[dofs * p + k] *= 2.0;
  }
  gu.assign(dofs * nlocal, 0.0);
  accumulate_friction(u.data(), gu.data());
  random_impulse(std::sqrt(h), impulse);
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < dofs; k++) {
      const int d = dofs * i + k;
      rhs[d] = inertia[d] * *dof_pointer(i, k) - 0.5 * h * gu[d] + impulse[d];
    }
  // moving images: M (v' - v) = -h/2 G (v + v') - h G_offset + sqrt(h) B xi
  if (!image_friction.empty())
    for (int d = 0; d < dofs * nlocal; d++) rhs[d] -= h * image_friction[d];
  std::vector<double> &solution = work.solution;
  // u holds the group's old velocities (the rows solve() keeps; the doubled velocities of atoms
  // outside the group are in rows it holds at zero)
  // Starting from the old velocities, G of the start is G u where no pair couples the group to
  // an atom outside it (u is 2 v only outside the group)
  solve(rhs, solution, 1.0, 0.5 * h, false, false, warm_start ? &u : nullptr,
        (warm_start && !any_fixed_partner) ? &gu : nullptr);

  // The exact solution conserves the group's momentum when no pair couples it to atoms outside
  // it (the rows of G sum to zero and the random impulses cancel in pairs, so sum M v' = sum
  // M v); an iterate leaves an error of the order of the tolerance, which would random-walk
  // over a long run. Remove it exactly, against the old momentum itself rather than sum rhs: a
  // pair that crosses ranks is built on each rank from its own image of the other atom, so its
  // two halves cancel only to rounding of single-precision e_ij, which the sums of G u and B xi
  // would carry into the momentum.
  // One reduction for both this and the kinetic energy of the shifted velocities below:
  // sum m (v + c)^2 = sum m v^2 + 2 c . sum m v + c^2 sum m.
  enum { DEFICIT = 0, MASS = 3, MOMENTUM = 4, TWICE_KINETIC = 7, COMPONENTS = 8, NSUMS = 9 };
  double local[NSUMS] = {}, sums[NSUMS];
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) {
      const double m = inertia[dofs * i];
      const double *s = &solution[dofs * i];
      for (int k = 0; k < 3; k++) {
        local[DEFICIT + k] += m * (*dof_pointer(i, k) - s[k]);
        local[MOMENTUM + k] += m * s[k];
      }
      local[MASS] += m;
      local[TWICE_KINETIC] += m * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
      local[COMPONENTS] += 3.0;
    }
  MPI_Allreduce(local, sums, NSUMS, MPI_DOUBLE, MPI_SUM, world);
  double shift[3] = {0.0, 0.0, 0.0};
  if (!any_fixed_partner && sums[MASS] > 0.0)
    for (int k = 0; k < 3; k++) shift[k] = sums[DEFICIT + k] / sums[MASS];
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      for (int k = 0; k < dofs; k++)
        *dof_pointer(i, k) = solution[dofs * i + k] + (k < 3 ? shift[k] : 0.0);

  // The end-of-step velocities that thermo sees carry the splitting's deficit
  // dt^2 <F^2> / (4 m kBT); these, fresh out of the friction step, do not (output 5).
  double twice_kinetic = sums[TWICE_KINETIC];
  for (int k = 0; k < 3; k++)
    twice_kinetic += 2.0 * shift[k] * sums[MOMENTUM + k] + shift[k] * shift[k] * sums[MASS];
  // degrees of freedom as compute temp counts them (the centre-of-mass motion removed)
  const double dof = sums[COMPONENTS] - 3.0;
  friction_step_temperature = dof > 0.0 ? twice_kinetic / (force->boltz * dof) * force->mvv2e : 0.0;

  if (split_requested || virial_this_step) {
    // the Crank-Nicolson mean velocity (v + v')/2; u holds v in the group and 2 v outside it
    std::vector<double> &mean = work.mean;
    mean.resize(dofs * nlocal);
    for (int i = 0; i < nlocal; i++) {
      const bool mobile = mask[i] & groupbit;
      for (int k = 0; k < dofs; k++)
        mean[dofs * i + k] = 0.5 * (u[dofs * i + k] + (mobile ? *dof_pointer(i, k) : 0.0));
    }
    record_friction_forces(mean, impulse, 1.0 / h);    // impulse = sqrt(h) B xi
  }
}

void FixETDImplicit::record_friction_forces(const std::vector<double> &mean_velocity,
                                            const std::vector<double> &random_force,
                                            double random_scale)
{
  gather_operand(mean_velocity.data(), false);
  if (split_requested) record_split(random_force, random_scale);
  if (virial_this_step) tally_friction_virial();
}

// Whether a pressure or stress compute is due at this step (as LAMMPS's integrator decides
// whether forces tally their virial, Integrate::ev_set, which runs only after this fix's step)
bool FixETDImplicit::virial_wanted() const
{
  if (!thermo_virial) return false;
  for (int c = 0; c < modify->ncompute; c++) {
    Compute *compute = modify->compute[c];
    if ((compute->pressflag || compute->pressatomflag) && compute->matchstep(update->ntimestep))
      return true;
  }
  return false;
}

// Virial of the step's dissipative and random pair forces, sum over pairs of r_ij F_ij (F on i,
// at the velocities in operand, the random force sigma w_R theta / sqrt(h) in both schemes).
// A pair that crosses ranks is held by both: each counts half. Per atom (compute stress/atom):
// half to each of the pair's atoms.
void FixETDImplicit::tally_friction_virial()
{
  const int nlocal = atom->nlocal;
  const double random_scale = 1.0 / std::sqrt(dt);
  for (int k = 0; k < 6; k++) virial[k] = 0.0;
  if (peratom_virial) {    // (vatom grows with the atoms: grow_arrays)
    for (int i = 0; i < nlocal; i++)
      for (int k = 0; k < 6; k++) vatom[i][k] = 0.0;
  }
  auto tally = [&](int i, int j, const double rij[3], const double f[3]) {
    const double w[6] = {rij[0] * f[0], rij[1] * f[1], rij[2] * f[2],
                         rij[0] * f[1], rij[0] * f[2], rij[1] * f[2]};
    const double share = (j < nlocal) ? 1.0 : 0.5;
    for (int k = 0; k < 6; k++) virial[k] += share * w[k];
    if (!peratom_virial) return;
    for (int k = 0; k < 6; k++) vatom[i][k] += 0.5 * w[k];
    if (j < nlocal)
      for (int k = 0; k < 6; k++) vatom[j][k] += 0.5 * w[k];
  };
  const double no_offset[3] = {0.0, 0.0, 0.0};
  for (size_t n = 0; n < pairs.size(); n++) {
    const etd::FrictionPair &p = pairs[n];
    const double *offset = pair_offset.empty() ? no_offset : &pair_offset[3 * n];
    const double *uj = &operand[dofs * p.j];
    const double moving_j[3] = {uj[0] + offset[0], uj[1] + offset[1], uj[2] + offset[2]};
    const double along =
        -etd::pair_friction(p, &operand[dofs * p.i], moving_j) + random_scale * pair_noise[n];
    const double r = pair_distance[n];
    const double rij[3] = {r * p.e[0], r * p.e[1], r * p.e[2]};
    const double f[3] = {along * p.e[0], along * p.e[1], along * p.e[2]};
    tally(p.i, p.j, rij, f);
  }
  for (size_t n = 0; n < fpm_pairs.size(); n++) {
    const etd::FpmFrictionPair &p = fpm_pairs[n];
    const double *offset = fpm_offset.empty() ? no_offset : &fpm_offset[3 * n];
    const double *qj = &operand[6 * p.j];
    const double moving_j[6] = {
        qj[0] + offset[0], qj[1] + offset[1], qj[2] + offset[2], qj[3], qj[4], qj[5]};
    double friction[3];
    etd::fpm_pair_friction(p, &operand[6 * p.i], moving_j, 1.0, friction);
    const double r = 2.0 * p.half_r;
    const double rij[3] = {r * p.e[0], r * p.e[1], r * p.e[2]};
    double f[3];
    for (int k = 0; k < 3; k++) f[k] = -friction[k] + random_scale * fpm_noise[3 * n + k];
    tally(p.i, p.j, rij, f);
  }
}

// D = -G operand - the moving images' constant part, R = random_scale * random_force
void FixETDImplicit::record_split(const std::vector<double> &random_force, double random_scale)
{
  std::vector<double> &gmean = work.gmean;
  gmean.assign(dofs * atom->nlocal, 0.0);
  accumulate_friction(operand.data(), gmean.data());
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < 3; k++) {
      split[i][k] =
          -gmean[dofs * i + k] - (image_friction.empty() ? 0.0 : image_friction[dofs * i + k]);
      split[i][3 + k] = random_scale * random_force[dofs * i + k];
    }
}

// Solves G v = F + B xi / sqrt(h) - G v_fixed at the current pair geometry, with the given
// random impulse (translation only: init() refuses rotation here).
bool FixETDImplicit::overdamped_solve(const std::vector<double> &impulse,
                                      std::vector<double> &velocity, bool singular_ok)
{
  double **v = atom->v;
  double **f = atom->f;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  std::vector<double> &u = work.u, &gu = work.gu_rhs, &rhs = work.step_rhs;
  u.assign(3 * nlocal, 0.0);
  rhs.resize(3 * nlocal);
  for (int i = 0; i < nlocal; i++)
    if (!(mask[i] & groupbit))
      for (int k = 0; k < 3; k++) u[3 * i + k] = v[i][k];
  apply_friction(u.data(), gu, false);
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < 3; k++) {
      rhs[3 * i + k] = f[i][k] + impulse[3 * i + k] - gu[3 * i + k];
      if (!image_friction.empty()) rhs[3 * i + k] -= image_friction[3 * i + k];
    }
  // without a fixed partner nothing sets the mean velocity: G is singular in the translation,
  // which is removed (the group's mean velocity is zero)
  return solve(rhs, velocity, 0.0, 1.0, !any_fixed_partner, singular_ok);
}

// The zero-mass step as a midpoint (Fixman) scheme: a predictor solve at x_n moves the atoms
// half a step, the corrector solves again with G at that midpoint and the same random impulse
// B(x_n) xi, and x_(n+1) = x_n + h v. Evaluating the mobility G^-1 at the midpoint supplies the
// drift kBT div(G^-1) of Brownian motion with a configuration-dependent mobility, which a
// single solve at x_n (the Euler-Maruyama update) leaves out. The force F stays the one of x_n.
// A configuration where an atom has almost no partner across some direction makes G nearly
// singular (its mobility there unbounded): at the predictor that is an error (solve()); where
// the predictor has carried an atom into a singular midpoint configuration, the step keeps the
// predictor's velocity, which is counted (the fix's output).
void FixETDImplicit::overdamped_step()
{
  double **x = atom->x;
  double **v = atom->v;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double h = dt;

  build_pairs();
  std::vector<double> &impulse = work.impulse, &predicted = work.predicted,
                      &solution = work.solution;
  random_impulse(1.0 / std::sqrt(h), impulse);
  impulse.resize(3 * nlocal);    // owned atoms' share, kept for the corrector
  overdamped_solve(impulse, predicted, false);
  if (!midpoint) {    // the single-solve (Euler-Maruyama) update, for comparison
    for (int i = 0; i < nlocal; i++)
      if (mask[i] & groupbit)
        for (int k = 0; k < 3; k++) {
          x[i][k] += h * predicted[3 * i + k];
          v[i][k] = predicted[3 * i + k];
        }
    if (split_requested || virial_this_step) overdamped_split(predicted, impulse);
    return;
  }
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      for (int k = 0; k < 3; k++) x[i][k] += 0.5 * h * predicted[3 * i + k];
  comm->forward_comm();    // ghosts at the midpoint too

  build_pairs();
  const bool corrected = overdamped_solve(impulse, solution, true);
  if (!corrected) {
    solution = predicted;
    predictor_steps++;
  }
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      for (int k = 0; k < 3; k++) {
        x[i][k] += h * solution[3 * i + k] - 0.5 * h * predicted[3 * i + k];
        v[i][k] = solution[3 * i + k];
      }
  if (split_requested || virial_this_step) overdamped_split(solution, impulse);
}

// D = -G v with G of the last solve (atoms outside the group at their own velocity), R = the
// random force of the step
void FixETDImplicit::overdamped_split(const std::vector<double> &velocity,
                                      const std::vector<double> &impulse)
{
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  std::vector<double> &mean = work.mean;
  mean.resize(3 * nlocal);
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < 3; k++)
      mean[3 * i + k] = (mask[i] & groupbit) ? velocity[3 * i + k] : atom->v[i][k];
  record_friction_forces(mean, impulse, 1.0);    // impulse = B xi / sqrt(h)
}

/* ---- output and communication ---------------------------------------------------------- */

double FixETDImplicit::compute_vector(int n)
{
  if (n == 0) return last_iterations;
  if (n == 1) return last_residual;
  if (n == 2) return solves ? iterations_sum / solves : 0.0;
  if (n == 3) return predictor_steps;
  return friction_step_temperature;
}

void FixETDImplicit::forward_exchange(std::initializer_list<CommSlot> slots, bool positions)
{
  comm_nslots = 0;
  for (const CommSlot &slot : slots) {
    slot.vector->resize(slot.width * (atom->nlocal + atom->nghost));
    comm_slots[comm_nslots++] = slot;
  }
  comm_positions = positions;
  etd::compat::forward_comm(comm, this);
  comm_positions = false;
}

int FixETDImplicit::pack_forward_comm(int n, int *list_, double *buf, int pbc_flag, int *pbc)
{
  int m = 0;
  // the positions as LAMMPS's own exchange sends them (AtomVec::pack_comm): shifted across a
  // periodic boundary
  double shift[3] = {0.0, 0.0, 0.0};
  if (comm_positions && pbc_flag) {
    if (domain->triclinic == 0) {
      shift[0] = pbc[0] * domain->xprd;
      shift[1] = pbc[1] * domain->yprd;
    } else {
      shift[0] = pbc[0] * domain->xprd + pbc[5] * domain->xy + pbc[4] * domain->xz;
      shift[1] = pbc[1] * domain->yprd + pbc[3] * domain->yz;
    }
    shift[2] = pbc[2] * domain->zprd;
  }
  double **x = atom->x;
  for (int i = 0; i < n; i++) {
    const int j = list_[i];
    if (comm_positions)
      for (int k = 0; k < 3; k++) buf[m++] = x[j][k] + shift[k];
    for (int s = 0; s < comm_nslots; s++) {
      const int width = comm_slots[s].width;
      const double *values = comm_slots[s].vector->data() + width * j;
      const bool shifted = comm_slots[s].image_counts && pbc_flag;
      for (int k = 0; k < width; k++) buf[m++] = values[k] + (shifted ? pbc[k] : 0);
    }
  }
  return m;
}

void FixETDImplicit::unpack_forward_comm(int n, int first, double *buf)
{
  double **x = atom->x;
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (comm_positions)
      for (int k = 0; k < 3; k++) x[i][k] = buf[m++];
    for (int s = 0; s < comm_nslots; s++) {
      const int width = comm_slots[s].width;
      double *values = comm_slots[s].vector->data() + width * i;
      for (int k = 0; k < width; k++) values[k] = buf[m++];
    }
  }
}

void FixETDImplicit::grow_arrays(int nmax)
{
  memory->grow(split, nmax, 6, "etd:split");
  memory->grow(vatom, nmax, 6, "etd:vatom");
  memory->grow(end_velocity, nmax, 3, "etd:end_velocity");
  for (int i = split_rows; i < nmax; i++) {
    for (int k = 0; k < 6; k++) split[i][k] = vatom[i][k] = 0.0;
    for (int k = 0; k < 3; k++) end_velocity[i][k] = 0.0;
  }
  split_rows = std::max(split_rows, nmax);
  maxvatom = split_rows;
  array_atom = end_velocity;
}

void FixETDImplicit::copy_arrays(int i, int j, int)
{
  for (int k = 0; k < 6; k++) {
    split[j][k] = split[i][k];
    vatom[j][k] = vatom[i][k];
  }
  for (int k = 0; k < 3; k++) end_velocity[j][k] = end_velocity[i][k];
}

int FixETDImplicit::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < 6; k++) {
    buf[k] = split[i][k];
    buf[6 + k] = vatom[i][k];
  }
  for (int k = 0; k < 3; k++) buf[12 + k] = end_velocity[i][k];
  return 15;
}

int FixETDImplicit::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < 6; k++) {
    split[nlocal][k] = buf[k];
    vatom[nlocal][k] = buf[6 + k];
  }
  for (int k = 0; k < 3; k++) end_velocity[nlocal][k] = buf[12 + k];
  return 15;
}

double FixETDImplicit::memory_usage()
{
  return sizeof(double) * 15 * split_rows + sizeof(etd::FrictionPair) * pairs.capacity() +
      sizeof(double) * pair_noise.capacity() + sizeof(etd::FpmFrictionPair) * fpm_pairs.capacity() +
      sizeof(double) * fpm_noise.capacity() +
      sizeof(double) * (operand.capacity() + diagonal.capacity()) +
      sizeof(int) * (ghost_partner.capacity() + slot_ghost.capacity());
}
