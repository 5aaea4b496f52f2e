// ETD-DPD: fix etd scheme diagonal. Positions: x += v dt. Velocities, per component, after the forces of the
// new positions (and old velocities) are known:
//   v' = e^z v + dt [phi1 A_n]                                  (order 1, Mai-Duy et al. 2013, eq 31)
//   v' = e^z v + dt [(phi1 + phi2) A_n - phi2 A_(n-1)]          (order 2, Mai-Duy et al. 2013, eq 7)
// with z = -Gamma dt / m and A = (F + Gamma v)/m, Gamma the diagonal friction from the pair style.
#include "fix_etd_diagonal.h"

#include "atom.h"
#include "dpd_style_lookup.h"
#include "error.h"
#include "etd_coefficients.h"
#include "fix_etd_options.h"
#include "force.h"
#include "memory.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr int STATE = 4;    // A_(n-1) x, y, z and a validity flag
}

FixETDDiagonal::FixETDDiagonal(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), order(1), noise(Noise::Piecewise), conserve_momentum(false), dt(0.0),
    previous_forcing(nullptr)
{
  time_integrate = 1;
  restart_peratom = 1;
  create_attribute = 1;    // set_arrays(): new atoms start without order-2 history
  maxexchange = STATE;     // per-atom values this fix adds to each migrating atom
  vector_flag = 1;
  size_vector = 3;
  extvector = 0;
  global_freq = 1;
  momentum_correction[0] = momentum_correction[1] = momentum_correction[2] = 0.0;

  etd::for_each_fix_etd_keyword(
      lmp, narg, arg, [&](const std::string &key, const std::string &value) {
        if (key == "order")
          order = 1 + etd::fix_etd_choice(lmp, key, value, {"1", "2"});
        else if (key == "noise")
          noise = etd::fix_etd_choice(lmp, key, value, {"piecewise", "exact"}) == 0
              ? Noise::Piecewise
              : Noise::Exact;
        else if (key == "momentum")
          conserve_momentum = etd::fix_etd_choice(lmp, key, value, {"none", "conserve"}) == 1;
        else if (key != "scheme")    // 'scheme implicit' is another class (fix_etd_implicit.cpp)
          error->all(FLERR, "Illegal fix etd command: unknown keyword {}", key);
      });

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < STATE; k++) previous_forcing[i][k] = 0.0;
}

FixETDDiagonal::~FixETDDiagonal()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(previous_forcing);
}

int FixETDDiagonal::setmask()
{
  return INITIAL_INTEGRATE | FINAL_INTEGRATE | POST_RUN;
}

void FixETDDiagonal::init()
{
  dt = update->dt;
  dpd_styles = etd::fix_etd_pair_styles(lmp, "diagonal friction");
  rotation_checked = false;
  for (auto *p : dpd_styles) {
    p->request_diagonal_friction();
    if (needs_random_part()) p->request_force_split();
  }
  neighbor_safety.check_settings(lmp, this, true);
}

// The order-2 history A_(n-1) belongs to the velocities it was computed with: where they changed
// between runs (velocity set / scale / create), the first step of the new run extrapolates
// from a forcing of other velocities, so the history is dropped (that step is order 1). Sum of
// v^2 over the group at the end of a run and at the start of the next one, to a relative 1e-10
// (the summation order may differ, the values may not).
double FixETDDiagonal::velocity_fingerprint() const
{
  double local = 0.0, total = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit)
      for (int k = 0; k < 3; k++) local += atom->v[i][k] * atom->v[i][k];
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  return total;
}

void FixETDDiagonal::setup(int)
{
  neighbor_safety.start_run(lmp);
  if (order != 2 || fingerprint_at_end < 0.0) return;
  const double now = velocity_fingerprint();
  if (std::fabs(now - fingerprint_at_end) > 1e-10 * std::max(now, fingerprint_at_end))
    for (int i = 0; i < atom->nlocal; i++) previous_forcing[i][3] = 0.0;
}

void FixETDDiagonal::post_run()
{
  neighbor_safety.end_run(lmp, id);
  if (order == 2) fingerprint_at_end = velocity_fingerprint();
}

// an atom created between runs has no history
void FixETDDiagonal::set_arrays(int i)
{
  for (int k = 0; k < STATE; k++) previous_forcing[i][k] = 0.0;
}

void FixETDDiagonal::reset_dt()
{
  dt = update->dt;
}

void FixETDDiagonal::initial_integrate(int)
{
  double **x = atom->x;
  double **v = atom->v;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) {
      x[i][0] += dt * v[i][0];
      x[i][1] += dt * v[i][1];
      x[i][2] += dt * v[i][2];
    }
}

void FixETDDiagonal::final_integrate()
{
  double **v = atom->v;
  double **f = atom->f;
  const int *mask = atom->mask;
  const int *type = atom->type;
  const double *rmass = atom->rmass;
  const double *mass = atom->mass;
  const int nlocal = atom->nlocal;
  update_angular_velocities();

  // the random force is needed apart whenever it is not simply part of A_n: for the exact
  // (Ornstein-Uhlenbeck) noise, and for order 2, whose extrapolation of A must not extrapolate
  // noise (that multiplies the noise variance by up to 5 at large |z|)
  const bool separate_noise = needs_random_part();
  const bool exact_noise = (noise == Noise::Exact);
  // the dpd_styles' arrays, looked up once per step rather than per atom and component
  std::vector<double **> friction_arrays, split_arrays;
  for (auto *p : dpd_styles) {
    friction_arrays.push_back(p->diagonal_friction());
    if (separate_noise) split_arrays.push_back(p->force_split());
  }
  // the common case (order 1, piecewise noise, no momentum correction) in its cheap form:
  // v += dt phi1(z) F/m with the full force (etd_coefficients.h), and no per-atom history
  if (order == 1 && !separate_noise && !conserve_momentum) {
    for (int i = 0; i < nlocal; i++) {
      if (!(mask[i] & groupbit)) continue;
      const double inv_m = 1.0 / (rmass ? rmass[i] : mass[type[i]]);
      for (int k = 0; k < 3; k++) {
        double friction = 0.0;
        for (double **g : friction_arrays) friction += g[i][k];
        v[i][k] += etd::first_order_effective_step(friction * inv_m, dt) * f[i][k] * inv_m;
      }
    }
    return;
  }

  double local_sums[7] = {0.0};    // actual momentum change, expected (dt F), group mass
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double m = rmass ? rmass[i] : mass[type[i]];
    const double inv_m = 1.0 / m;
    const bool use_previous = (order == 2) && previous_forcing[i][3] != 0.0;
    for (int k = 0; k < 3; k++) {
      double friction = 0.0, random_force = 0.0;
      for (double **g : friction_arrays) friction += g[i][k];
      for (double **split : split_arrays) random_force += split[i][6 + k];
      const etd::EtdCoefficients c =
          etd::etd_coefficients(friction * inv_m, dt, use_previous ? 2 : 1, exact_noise);
      const double forcing = (f[i][k] + friction * v[i][k]) * inv_m;
      const double random_part = random_force * inv_m;
      const double deterministic = forcing - random_part;
      const double noise_weight = exact_noise ? c.noise_exact : c.noise_piecewise;
      double v_new = c.decay * v[i][k] + c.current * deterministic + noise_weight * random_part;
      if (use_previous) v_new += c.previous * previous_forcing[i][k];
      previous_forcing[i][k] = deterministic;
      local_sums[k] += m * (v_new - v[i][k]);
      local_sums[3 + k] += dt * f[i][k];
      v[i][k] = v_new;
    }
    previous_forcing[i][3] = 1.0;
    local_sums[6] += m;
  }

  if (!conserve_momentum) return;
  // remove the momentum the per-atom implicit friction creates: the group's momentum then
  // changes by dt * (sum of forces on it), as in an explicit update
  double sums[7];
  MPI_Allreduce(local_sums, sums, 7, MPI_DOUBLE, MPI_SUM, world);
  if (sums[6] <= 0.0) return;
  for (int k = 0; k < 3; k++) momentum_correction[k] = (sums[k] - sums[3 + k]) / sums[6];
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      for (int k = 0; k < 3; k++) v[i][k] -= momentum_correction[k];
}

double FixETDDiagonal::compute_vector(int n)
{
  return momentum_correction[n];
}

/* ----------------------------------------------------------------------
   Angular velocities, where a pair style supplies the rotational friction diagonal (dpd/fpm):
   per component, with Gamma_rot from the pair style and the moment of inertia of a solid
   sphere I = 0.4 m r^2 (as fix nve/sphere),
     Omega' = e^z Omega + dt phi1(z) (T + Gamma_rot Omega) / I,   z = -Gamma_rot dt / I.
   The first-order formula is used for every 'order' setting (there is no torque history).
------------------------------------------------------------------------- */

void FixETDDiagonal::update_angular_velocities()
{
  if (!atom->omega_flag || !atom->torque_flag) return;
  std::vector<double **> rotational;
  for (auto *p : dpd_styles)
    if (double **g = p->rotational_friction()) rotational.push_back(g);
  const double *radius = atom->radius;
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  if (!rotation_checked) {    // first step of each run (init() clears the flag), collectively
    int local = rotational.empty() ? 0 : 1;
    MPI_Allreduce(&local, &rotation_active, 1, MPI_INT, MPI_MAX, world);
    if (rotation_active && (!atom->radius_flag || !atom->rmass_flag))
      error->all(FLERR,
                 "Fix etd: rotating atoms need a radius and per-atom mass for their moment "
                 "of inertia (atom_style sphere)");
    if (rotation_active) etd::check_moments_of_inertia(lmp, groupbit, "Fix etd");
    rotation_checked = true;
  }
  if (!rotation_active || rotational.empty()) return;
  double **omega = atom->omega;
  double **torque = atom->torque;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double inertia = 0.4 * rmass[i] * radius[i] * radius[i];
    if (inertia <= 0.0) continue;    // changed after the check: leave it alone
    const double inv_inertia = 1.0 / inertia;
    // e^z Omega + dt phi1(z) (T + Gamma_rot Omega)/I = Omega + dt phi1(z) T/I (etd_coefficients.h)
    for (int k = 0; k < 3; k++) {
      double friction = 0.0;
      for (double **g : rotational) friction += g[i][k];
      omega[i][k] +=
          etd::first_order_effective_step(friction * inv_inertia, dt) * torque[i][k] * inv_inertia;
    }
  }
}

/* ---- per-atom state: A_(n-1) migrates with atoms and is written to restart files ---- */

void FixETDDiagonal::grow_arrays(int nmax)
{
  memory->grow(previous_forcing, nmax, STATE, "etd:previous_forcing");
}

void FixETDDiagonal::copy_arrays(int i, int j, int)
{
  for (int k = 0; k < STATE; k++) previous_forcing[j][k] = previous_forcing[i][k];
}

int FixETDDiagonal::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < STATE; k++) buf[k] = previous_forcing[i][k];
  return STATE;
}

int FixETDDiagonal::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < STATE; k++) previous_forcing[nlocal][k] = buf[k];
  return STATE;
}

int FixETDDiagonal::pack_restart(int i, double *buf)
{
  buf[0] = STATE + 1;
  for (int k = 0; k < STATE; k++) buf[k + 1] = previous_forcing[i][k];
  return STATE + 1;
}

void FixETDDiagonal::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k < STATE; k++) previous_forcing[nlocal][k] = extra[nlocal][m++];
}

int FixETDDiagonal::size_restart(int)
{
  return STATE + 1;
}
int FixETDDiagonal::maxsize_restart()
{
  return STATE + 1;
}

double FixETDDiagonal::memory_usage()
{
  return static_cast<double>(atom->nmax) * STATE * sizeof(double);
}
