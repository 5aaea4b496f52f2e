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

#include "implicit_friction_tally.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "dpd_style_lookup.h"
#include "error.h"
#include "force.h"
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
    Fix(lmp, narg, arg), options(etd::parse_implicit_options(lmp, narg, arg)), dt(0.0),
    list(nullptr), list_newton_off(true), dofs(3), any_fixed_partner(false), partners(world),
    split_requested(false), split_rows(0), split(nullptr), peratom_virial(false),
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
  comm_forward = etd::GhostExchange::max_width;    // positions and v (and Omega with rotation)
  // the dissipative and random forces are this fix's, so is their virial (pressure, stress)
  virial_global_flag = virial_peratom_flag = 1;
  thermo_virial = 1;

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
  return INITIAL_INTEGRATE | POST_INTEGRATE | PRE_FORCE | FINAL_INTEGRATE | POST_NEIGHBOR |
      POST_RUN;
}

void FixETDImplicit::init()
{
  dt = update->dt;
  dpd_styles = etd::fix_etd_pair_styles(lmp, "friction");
  if (atom->tag_enable == 0)
    error->all(FLERR, "Fix etd scheme implicit requires atom IDs (its noise is keyed on them)");
  check_integrators();
  warn_force_fixes();
  assembly.set_coefficients(lmp, dpd_styles);
  dofs = assembly.dofs();
  if (assembly.rotation()) check_rotation();
  assembly.set_noise(
      etd::PairNoise(dpd_styles.front()->noise_seed(), etd::NoiseStream::Integrator));
  request_neighbor_list();
  partners.invalidate();
  neighbor_safety.check_settings(lmp, this, !options.overdamped);
  peratom_virial = false;
  for (int c = 0; c < modify->ncompute; c++)
    if (modify->compute[c]->pressatomflag) peratom_virial = true;
}

void FixETDImplicit::check_integrators()
{
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
  // fix wall/reflect/stochastic moves an atom that crossed its wall back along the atom's
  // velocity at post_integrate (it assumes the atom travelled with it). Here the atom travelled
  // with the mean of the velocities before and after the friction step, so an atom whose normal
  // velocity the step reversed is put back beyond the wall and is lost later (measured: the
  // sphere-in-Couette example, one atom by step 650). The overdamped drift uses the velocity
  // it leaves in v, so it is not affected.
  if (Fix *walls = options.overdamped ? nullptr
                                      : etd::find_fix_style(lmp, "^wall/reflect/stochastic"))
    error->all(FLERR,
               "Fix etd scheme implicit cannot be combined with fix wall/reflect/stochastic ({}): "
               "that fix puts an atom that crossed its wall back along the atom's velocity after "
               "the step, which under the implicit friction step is not the velocity the atom "
               "travelled with, and atoms are left beyond the wall. Use fix wall/reflect with fix "
               "wall/thermal/layer for thermal walls, or fix etd scheme diagonal",
               walls->id);
}

void FixETDImplicit::warn_force_fixes()
{
  // Under a steady force the friction step's output, which v holds, lags the streaming
  // velocity by h/2 <F>/m (doc/fix_etd.rst): say where mean velocities should be read.
  if (!options.overdamped && comm->me == 0 && !warned_force_fixes)
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
}

void FixETDImplicit::check_rotation()
{
  if (!atom->omega_flag || !atom->torque_flag || !atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR,
               "Fix etd scheme implicit with pair style dpd/fpm needs angular velocities, "
               "torques, radii and per-atom masses (atom_style sphere)");
  if (options.overdamped)
    error->all(FLERR,
               "Fix etd scheme implicit: overdamped yes is not available with pair style "
               "dpd/fpm (its rotation needs inertia); use overdamped no with a small mass");
  etd::check_moments_of_inertia(lmp, groupbit, "Fix etd scheme implicit");
}

void FixETDImplicit::request_neighbor_list()
{
  // On several ranks the lists are newton off, so that a pair crossing ranks is held by both
  // (partner_exchange.h); on one rank there is no such pair.
  const bool several_ranks = comm->nprocs > 1;
  list_newton_off = several_ranks || !force->newton_pair;
  const bool lone_style = dpd_styles.size() == 1 &&
      dynamic_cast<etd::DpdPairInterface *>(force->pair) == dpd_styles.front();
  // With newton on, a newton-off list of this fix would be a second list, built at every
  // reneighboring beside the pair style's newton-on one (measured: it doubled the neighbor time
  // of a 2-rank step). A lone style (not in hybrid) makes its own list newton off instead, and
  // LAMMPS then hands this fix a copy of it; with the scheme's own search, the style reads that
  // search's pairs, with the same newton setting.
  if (several_ranks && force->newton_pair && lone_style)
    dpd_styles.front()->request_newton_off_list();
  own.active = false;
  own.step = -1;
  if (options.pair_search != etd::ImplicitOptions::PairSearch::lammps) {
    const char *unsupported = own_pairs_unsupported();
    if (unsupported && options.pair_search == etd::ImplicitOptions::PairSearch::own)
      error->all(FLERR,
                 "Fix etd neighbors own is not supported with {}: use neighbors lammps (or leave "
                 "the keyword out)",
                 unsupported);
    const bool wanted = options.pair_search == etd::ImplicitOptions::PairSearch::own ||
        own_pairs_pay();
    own.active = wanted && !unsupported && dpd_styles.front()->use_external_pairs(this);
    if (!own.active && options.pair_search == etd::ImplicitOptions::PairSearch::own)
      error->all(FLERR,
                 "Fix etd neighbors own is not supported with pair style {}: use neighbors lammps "
                 "(or leave the keyword out)",
                 force->pair_style);
  }
  if (own.active) {
    list = nullptr;    // no LAMMPS list for the fix: it searches the pairs itself
    return;
  }
  etd::compat::request_fix_half_list(neighbor, this, instance_me, several_ranks);
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
  own.step = -1;    // the pair style finds its own pairs outside runs (minimize, rerun)
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
  threads.for_ranges(atom->nlocal, [&](int begin, int end, int) {
    for (int i = begin; i < end; i++)
      if (mask[i] & groupbit) {
        const double scale = fraction * dt / atom_mass(i);
        for (int k = 0; k < 3; k++) v[i][k] += scale * f[i][k];
      }
  });
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
  threads.for_ranges(nlocal, [&](int begin, int end, int) {
    for (int i = begin; i < end; i++) {
      const double m = atom_mass(i);
      for (int k = 0; k < 3; k++) inertia[dofs * i + k] = m;
      if (dofs == 6)
        for (int k = 3; k < 6; k++)
          inertia[dofs * i + k] = 0.4 * m * atom->radius[i] * atom->radius[i];
    }
  });
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
  threads.for_ranges(atom->nlocal, [&](int begin, int end, int) {
    for (int i = begin; i < end; i++)
      if (mask[i] & groupbit)
        for (int k = 0; k < 3; k++) x[i][k] += fraction * dt * v[i][k];
  });
}

void FixETDImplicit::initial_integrate(int)
{
  virial_this_step = virial_wanted();
  dof_inertia(work.inertia);    // the solves and the friction step's right-hand side
  if (options.overdamped) {
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
  if (virial_this_step && !options.overdamped) add_drift_kinetic_stress();
}

// The pressure LAMMPS computes reads m v v of the velocities in v, the friction step's output;
// the atoms move with other velocities (implicit_friction_tally.h), and the momentum they carry
// differs under shear by several per cent at large steps. The difference joins this fix's
// virial, so that pressure and stress/atom read the momentum flux of the step. Peculiar
// velocities under fix deform ... remap v, as compute temp/deform takes them.
void FixETDImplicit::add_drift_kinetic_stress()
{
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const int *mask = atom->mask;
  const double *h_rate = domain->h_rate, *h_ratelo = domain->h_ratelo;
  const bool streaming = domain->deform_vremap;
  const double mvv2e = force->mvv2e;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double m = atom_mass(i);
    double c[3] = {v[i][0], v[i][1], v[i][2]}, h[3];
    if (streaming) {
      double lamda[3];
      domain->x2lamda(x[i], lamda);
      c[0] -= h_rate[0] * lamda[0] + h_rate[5] * lamda[1] + h_rate[4] * lamda[2] + h_ratelo[0];
      c[1] -= h_rate[1] * lamda[1] + h_rate[3] * lamda[2] + h_ratelo[1];
      c[2] -= h_rate[2] * lamda[2] + h_ratelo[2];
    }
    for (int k = 0; k < 3; k++) h[k] = 0.5 * dt * f[i][k] / m;
    double w[6];
    etd::drift_kinetic_stress(m * mvv2e, c, h, w);
    for (int k = 0; k < 6; k++) virial[k] += w[k];
    if (peratom_virial)
      for (int k = 0; k < 6; k++) vatom[i][k] += w[k];
  }
}

void FixETDImplicit::record_end_velocity()
{
  threads.for_ranges(atom->nlocal, [&](int begin, int end, int) {
    for (int i = begin; i < end; i++) {
      const bool kicked = !options.overdamped && (atom->mask[i] & groupbit);
      const double scale = kicked ? 0.5 * dt / atom_mass(i) : 0.0;
      for (int k = 0; k < 3; k++) end_velocity[i][k] = atom->v[i][k] + scale * atom->f[i][k];
    }
  });
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
  threads.for_ranges(nlocal, [&](int begin, int end, int) {
    for (int i = begin; i < end; i++) {
      const double kick = options.overdamped ? 0.0 : dt / atom_mass(i);
      for (int k = 0; k < 3; k++) lead[3 * i + k] = 0.5 * dt * (v[i][k] + kick * f[i][k]);
    }
  });
  if (neighbor_safety.could_outrun(lmp, groupbit, lead)) next_reneighbor = update->ntimestep;
}

// gu = G u over owned atoms (u given on owned atoms; the remote partners are filled here). With
// group_only, atoms outside the group count as at rest (the solver's unknowns are the group's
// velocities).
void FixETDImplicit::apply_friction(const double *u, std::vector<double> &gu, bool group_only)
{
  gather_operand(u, group_only);
  gu.assign(dofs * atom->nlocal, 0.0);
  assembly.accumulate_friction(operand.data(), gu.data(), atom->nlocal);
}

// operand = u on all partners (u given on owned atoms; the remote slots filled by their owners)
void FixETDImplicit::gather_operand(const double *u, bool group_only)
{
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  operand.resize(dofs * partners.count(nlocal));
  if (group_only) {
    for (int i = 0; i < nlocal; i++) {
      const double keep = (mask[i] & groupbit) ? 1.0 : 0.0;
      for (int k = 0; k < dofs; k++) operand[dofs * i + k] = keep * u[dofs * i + k];
    }
  } else {
    std::copy(u, u + dofs * nlocal, operand.begin());
  }
  partners.exchange(operand.data(), nlocal, dofs);
}

void FixETDImplicit::record_friction_forces(const std::vector<double> &mean_velocity,
                                            const std::vector<double> &random_force,
                                            double random_scale)
{
  gather_operand(mean_velocity.data(), false);
  const int nlocal = atom->nlocal;
  if (split_requested)
    etd::record_friction_split(assembly, operand.data(), nlocal, random_force, random_scale,
                               work.gmean, split);
  if (virial_this_step)
    etd::tally_friction_virial(assembly, operand.data(), nlocal, dt, virial,
                               peratom_virial ? vatom : nullptr);
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

/* ---- output and communication ---------------------------------------------------------- */

double FixETDImplicit::compute_vector(int n)
{
  if (n == 0) return last_iterations;
  if (n == 1) return last_residual;
  if (n == 2) return solves ? iterations_sum / solves : 0.0;
  if (n == 3) return predictor_steps;
  return friction_step_temperature;
}

int FixETDImplicit::pack_forward_comm(int n, int *list_, double *buf, int pbc_flag, int *pbc)
{
  return ghosts.pack(lmp, n, list_, buf, pbc_flag, pbc);
}

void FixETDImplicit::unpack_forward_comm(int n, int first, double *buf)
{
  ghosts.unpack(lmp, n, first, buf);
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
  return sizeof(double) * 15 * split_rows + assembly.memory_usage() +
      sizeof(double) * (operand.capacity() + diagonal.capacity()) + partners.memory_usage();
}
