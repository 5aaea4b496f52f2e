// ETD-DPD: fix etd scheme implicit, the step: the friction and noise step of the inertial
// scheme and the overdamped step, with their solves (the scheme: fix_etd_implicit.cpp).
#include "fix_etd_implicit.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

etd::SolverResult FixETDImplicit::solve_system(const std::vector<double> &rhs_in,
                                               std::vector<double> &solution, double mass_weight,
                                               double friction_weight, bool deflate,
                                               const std::vector<double> *start,
                                               const std::vector<double> *start_friction)
{
  const int *mask = atom->mask;
  assembly.accumulate_blocks(diagonal, 2 * dofs, atom->nlocal);    // the preconditioner's

  etd::FrictionSystem system;
  system.n = dofs * atom->nlocal;
  system.inertia = work.inertia.data();    // this step's (initial_integrate)
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
    assembly.accumulate_friction(operand.data(), out, atom->nlocal, weight);
  };
  return etd::solve_friction_system(system, mobile, apply_friction, sum_over_ranks(),
                                    rhs_in.data(), solution, options.tolerance,
                                    options.max_iterations, work.solve,
                                    start ? start->data() : nullptr,
                                    (start && start_friction) ? start_friction->data() : nullptr);
}

// sums count values over all ranks, in place (the solvers sum at most 9 at once)
std::function<void(double *, int)> FixETDImplicit::sum_over_ranks() const
{
  return [this](double *values, int count) {
    double sums[16];
    MPI_Allreduce(values, sums, count, MPI_DOUBLE, MPI_SUM, world);
    for (int k = 0; k < count; k++) values[k] = sums[k];
  };
}

// (mass_weight M + friction_weight G) x = rhs over the group's atoms on this rank, atoms
// outside the group held at zero (their velocities are already in rhs). With 'deflate' the
// uniform translation (null space of G) is projected out of rhs and of the solution.
bool FixETDImplicit::solve(const std::vector<double> &rhs_in, std::vector<double> &solution,
                           double mass_weight, double friction_weight, bool deflate,
                           bool singular_ok, const std::vector<double> *start,
                           const std::vector<double> *start_friction)
{
  const etd::SolverResult result = solve_system(rhs_in, solution, mass_weight, friction_weight,
                                                deflate, start, start_friction);
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
                   result.iterations, result.relative_residual, options.tolerance);
  return result.converged;
}

// b = M q - h/2 G (q + q_fixed) + sqrt(h) B xi into work.step_rhs (q = v, or v and Omega), at
// the half-drifted positions, whose pairs it builds; work.u keeps q over the partners (2 q
// outside the group), work.gu_rhs G of it, work.impulse sqrt(h) B xi.
void FixETDImplicit::friction_step_rhs()
{
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  // the fixed atoms' velocities appear twice, once from the old and once from the new side of
  // the Pade update
  std::vector<double> &u = work.u, &rhs = work.step_rhs;
  // One forward exchange brings the ghosts to the half-drifted positions and carries their
  // velocities (every exchange is a point where the ranks wait for each other)
  const int nall = nlocal + atom->nghost;
  std::vector<double> &ghost_u = work.ghost_u;
  ghost_u.resize(dofs * nall);
  rhs.resize(dofs * nlocal);
  threads.for_ranges(nlocal, [&](int begin, int end, int) {
    for (int i = begin; i < end; i++)
      for (int k = 0; k < dofs; k++) ghost_u[dofs * i + k] = *dof_pointer(i, k);
  });
  ghosts.run(lmp, this, {{&ghost_u, dofs}}, true);
  build_pairs();
  // u over the partners: owned atoms, then each remote slot from one of its ghost images
  u.resize(dofs * partners.count(nlocal));
  std::copy(ghost_u.begin(), ghost_u.begin() + dofs * nlocal, u.begin());
  for (int s = 0; s < partners.slots(); s++)
    for (int k = 0; k < dofs; k++)
      u[dofs * (nlocal + s) + k] = ghost_u[dofs * partners.ghost_of_slot(s) + k];
  for (int p = 0; p < partners.count(nlocal); p++) {
    if (mask[p < nlocal ? p : partners.ghost_of_slot(p - nlocal)] & groupbit) continue;
    for (int k = 0; k < dofs; k++) u[dofs * p + k] *= 2.0;
  }
  friction_rhs();
}

// work.step_rhs from work.u, with G u in work.gu_rhs and sqrt(h) B xi in work.impulse
void FixETDImplicit::friction_rhs()
{
  const int nlocal = atom->nlocal;
  const double h = dt;
  const std::vector<double> &u = work.u, &inertia = work.inertia;
  std::vector<double> &gu = work.gu_rhs, &rhs = work.step_rhs, &impulse = work.impulse;
  gu.assign(dofs * nlocal, 0.0);
  assembly.accumulate_friction(u.data(), gu.data(), nlocal);
  assembly.random_impulse(std::sqrt(h), impulse, nlocal);
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < dofs; k++) {
      const int d = dofs * i + k;
      rhs[d] = inertia[d] * *dof_pointer(i, k) - 0.5 * h * gu[d] + impulse[d];
    }
  // moving images: M (v' - v) = -h/2 G (v + v') - h G_offset + sqrt(h) B xi
  const std::vector<double> &image_friction = assembly.image_friction();
  if (!image_friction.empty())
    for (int d = 0; d < dofs * nlocal; d++) rhs[d] -= h * image_friction[d];
}

void FixETDImplicit::friction_noise_step()
{
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double h = dt;
  friction_step_rhs();
  std::vector<double> &u = work.u, &gu = work.gu_rhs, &rhs = work.step_rhs;
  std::vector<double> &solution = work.solution;
  // u holds the group's old velocities (the rows solve() keeps; the doubled velocities of atoms
  // outside the group are in rows it holds at zero)
  // Starting from the old velocities, G of the start is G u where no pair couples the group to
  // an atom outside it (u is 2 v only outside the group)
  solve(rhs, solution, 1.0, 0.5 * h, false, false, options.warm_start ? &u : nullptr,
        (options.warm_start && !any_fixed_partner) ? &gu : nullptr);

  conserve_momentum_and_measure();

  if (split_requested || virial_this_step) {
    // the Crank-Nicolson mean velocity (v + v')/2; u holds v in the group and 2 v outside it
    std::vector<double> &mean = work.mean;
    mean.resize(dofs * nlocal);
    for (int i = 0; i < nlocal; i++) {
      const bool mobile = mask[i] & groupbit;
      for (int k = 0; k < dofs; k++)
        mean[dofs * i + k] = 0.5 * (u[dofs * i + k] + (mobile ? *dof_pointer(i, k) : 0.0));
    }
    record_friction_forces(mean, work.impulse, 1.0 / h);    // impulse = sqrt(h) B xi
  }
}

// The group's momentum restored exactly and the new velocities written to the atoms, with the
// kinetic temperature right after the friction step (output 5).
void FixETDImplicit::conserve_momentum_and_measure()
{
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const std::vector<double> &inertia = work.inertia, &solution = work.solution;
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
  std::vector<double> parts(NSUMS * threads.ranges(nlocal), 0.0);
  threads.for_ranges(nlocal, [&](int begin, int end, int range) {
    double *local = &parts[NSUMS * range];
    for (int i = begin; i < end; i++)
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
  });
  double local[NSUMS], sums[NSUMS];
  for (int n = 0; n < NSUMS; n++) local[n] = parts[n];
  for (std::size_t at = NSUMS; at < parts.size(); at++) local[at % NSUMS] += parts[at];
  MPI_Allreduce(local, sums, NSUMS, MPI_DOUBLE, MPI_SUM, world);
  double shift[3] = {0.0, 0.0, 0.0};
  if (!any_fixed_partner && sums[MASS] > 0.0)
    for (int k = 0; k < 3; k++) shift[k] = sums[DEFICIT + k] / sums[MASS];
  threads.for_ranges(nlocal, [&](int begin, int end, int) {
    for (int i = begin; i < end; i++)
      if (mask[i] & groupbit)
        for (int k = 0; k < dofs; k++)
          *dof_pointer(i, k) = solution[dofs * i + k] + (k < 3 ? shift[k] : 0.0);
  });

  // The end-of-step velocities that thermo sees carry the splitting's deficit
  // dt^2 <F^2> / (4 m kBT); these, fresh out of the friction step, do not (output 5).
  double twice_kinetic = sums[TWICE_KINETIC];
  for (int k = 0; k < 3; k++)
    twice_kinetic += 2.0 * shift[k] * sums[MOMENTUM + k] + shift[k] * shift[k] * sums[MASS];
  // degrees of freedom as compute temp counts them (the centre-of-mass motion removed)
  const double dof = sums[COMPONENTS] - 3.0;
  friction_step_temperature = dof > 0.0 ? twice_kinetic / (force->boltz * dof) * force->mvv2e : 0.0;
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
  const std::vector<double> &image_friction = fixed_friction(u, gu);
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
  overdamped_impulse(impulse);    // kept for the corrector
  overdamped_solve(impulse, predicted, false);
  if (!options.midpoint) {    // the single-solve (Euler-Maruyama) update, for comparison
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

// B xi / sqrt(h) of this step's pairs, over the owned atoms
void FixETDImplicit::overdamped_impulse(std::vector<double> &impulse)
{
  assembly.random_impulse(1.0 / std::sqrt(dt), impulse, atom->nlocal);
  impulse.resize(3 * atom->nlocal);
}

// gu = G u over the owned atoms (u: owned atoms, at rest in the group); returns the images'
// friction G_offset under fix deform ... remap v (else empty)
const std::vector<double> &FixETDImplicit::fixed_friction(const std::vector<double> &u,
                                                          std::vector<double> &gu)
{
  apply_friction(u.data(), gu, false);
  return assembly.image_friction();
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
