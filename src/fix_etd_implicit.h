// ETD-DPD: fix etd ... scheme implicit: the exponential update with the full pairwise friction
// operator, solved by conjugate gradients, and its zero-mass limit (see doc/fix_etd.rst).
#ifndef ETD_FIX_ETD_IMPLICIT_H
#define ETD_FIX_ETD_IMPLICIT_H

#include "fix.h"

#include "cell_pair_search.h"

#include "dpd_pair_interface.h"
#include "fix_etd_options.h"
#include "friction_solve.h"
#include "implicit_pair_assembly.h"
#include "implicit_partners.h"
#include "neighbor_safety.h"

#include <functional>
#include <vector>

namespace LAMMPS_NS {

class FixETDImplicit : public Fix, public etd::DpdFrictionIntegrator, public etd::ExternalPairs {
 public:
  FixETDImplicit(class LAMMPS *, int, char **);
  ~FixETDImplicit() override;
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup(int) override;
  void setup_post_neighbor() override;
  void post_neighbor() override;
  void post_integrate() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void post_run() override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void reset_dt() override;
  double compute_vector(int) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;

  // For compute dpd/split (which calls request_split() in its init; the extra work, one
  // application of G per step, is done from then on): per owned atom, inside the group or
  // not, the dissipative and random forces of the last friction step, [nlocal][6] = D xyz,
  // R xyz; they travel with the atoms.
  // Inertial: D = -G (v + v')/2 (atoms outside the group at their own v), R = B xi / sqrt(h), so
  // that for an atom of the group h (D + R) = M (v' - v) of the friction step. Overdamped:
  // D = -G v, R = B xi / sqrt(h) (D + R = -F on the group's atoms).
  void request_split() override { split_requested = true; }
  double **dissipative_random_split() const override { return split; }

  // The pairs the scheme found at this step's end positions, which the pair style reads in
  // place of its LAMMPS list (nullptr without the scheme's own search, or at another step)
  const etd::PairListView *pairs_for_step(std::int64_t step) const override
  {
    return (own.active && step == own.step) ? &own.view : nullptr;
  }

 protected:    // (the KOKKOS variant, fix_etd_implicit_kokkos.h, runs the solve in kernels)
  etd::ImplicitOptions options;
  double dt;
  class NeighList *list;    // LAMMPS's, where the scheme does not search the pairs itself
  bool list_newton_off;     // each image pair is listed from both ends
  // The scheme's own pair search (fix_etd_implicit_pairs.cpp): once per step at the end
  // positions, for the pair style's forces and, with a margin for the half drift to come, for
  // the next friction step; again at the friction step's positions where atoms moved farther.
  struct OwnPairs {
    bool active = false;
    etd::CellPairSearch search;
    etd::PairListView view;
    bigint step = -1;                 // the step whose pairs these are (-1: none)
    std::vector<double> positions;    // the owned atoms' positions at the search
    double cutoff = 0.0;              // the largest cutoff of the pair style and the friction
    double margin = 0.0;              // searched out to cutoff + margin
  } own;
  // Who runs the search's slabs and the step's loops over the atoms: `chunks` at once by
  // `runner` (the KOKKOS variant: its host threads); here one, in place, so that the CPU fix's
  // sums are those of plain loops
  etd::ParallelRanges threads;
  const char *own_pairs_unsupported() const;
  bool own_pairs_pay() const;    // the default's choice: the search's cells stay sparse
  void search_own_pairs(double margin);
  void refresh_own_pairs();
  etd::PairListView step_pairs() const;    // own.view, or LAMMPS's list
  std::vector<etd::DpdPairInterface *> dpd_styles;
  etd::FrictionPairAssembly assembly;    // this step's pairs (implicit_pair_assembly.h)
  int dofs;    // unknowns per atom: 3 (v), or 6 (v and Omega) when dpd/fpm pairs take part
  etd::NeighborSafety neighbor_safety;
  bool any_fixed_partner;       // some pair couples to an atom outside the group
  etd::PartnerMap partners;     // the atoms G acts on (implicit_partners.h)
  etd::GhostExchange ghosts;    // what the next forward (ghost) communication moves

  // per-partner vectors, dofs values each: G's operand; per owned atom, the preconditioner blocks
  std::vector<double> operand, diagonal;

  // work vectors reused from step to step (per-step allocation costs page faults at scale)
  struct Work {
    std::vector<double> inertia;    // per unknown, mass or moment of inertia (once per step)
    std::vector<double> u, gu_rhs, step_rhs, impulse, solution, predicted;    // the steps
    std::vector<double> ghost_u;        // per ghost: velocities
    std::vector<double> mean, gmean;    // the split and the virial
    std::vector<double> lead;    // post_integrate(): how far the next friction step moves each atom
    etd::FrictionSolveWorkspace solve;
  } work;

  bool split_requested;
  int split_rows;    // rows of split allocated (atom->nmax at the last grow)
  double **split;
  bool peratom_virial;    // a per-atom stress compute exists (stress/atom): fill vatom too
  bool virial_wanted() const;
  bool virial_this_step = false;    // virial_wanted(), decided once at the start of each step
  // The dissipative and random forces of the step's pairs, at the given velocities (owned atoms,
  // remote partners filled here): for compute dpd/split and the virial
  void record_friction_forces(const std::vector<double> &mean_velocity,
                              const std::vector<double> &random_force, double random_scale);

  int last_iterations;
  double last_residual;
  double iterations_sum;
  double friction_step_temperature = 0.0;    // kinetic temperature right after the friction step
  long solves;
  long predictor_steps;    // overdamped steps that kept the predictor (singular midpoint)

  // per-atom output (array_atom): v + h/2 F/m at the end of each step, whose mean is the
  // streaming velocity (v, the friction step's output, lags it by h/2 <F>/m)
  double **end_velocity;
  bool warned_force_fixes = false;    // the lag under a steady force is said once per fix
  void record_end_velocity();
  void add_drift_kinetic_stress();    // into the virial, at a step that tallies it
  double atom_mass(int i) const;    // per-atom or per-type mass

  // init()'s parts
  void check_integrators();
  void warn_force_fixes();
  void check_rotation();
  void request_neighbor_list();

  void kick(double fraction);
  void drift(double fraction);
  void build_pairs();
  // this step's pairs into the assembly (or elsewhere, KOKKOS); whether one has an atom
  // outside the group
  virtual bool assemble_pairs(const etd::FrictionPairAssembly::Context &context);
  void check_missing_pairs(bool local_fixed_partner);
  void dof_inertia(std::vector<double> &inertia) const;
  double *dof_pointer(int i, int k) const;
  void apply_friction(const double *u, std::vector<double> &gu, bool group_only);
  void gather_operand(const double *u, bool group_only);

  // the step (fix_etd_implicit_step.cpp)
  void friction_noise_step();
  void friction_step_rhs();
  virtual void friction_rhs();    // work.step_rhs, work.gu_rhs and work.impulse from work.u
  void conserve_momentum_and_measure();
  void overdamped_step();
  virtual void overdamped_impulse(std::vector<double> &impulse);
  virtual const std::vector<double> &fixed_friction(const std::vector<double> &u,
                                                    std::vector<double> &gu);
  bool overdamped_solve(const std::vector<double> &impulse, std::vector<double> &velocity,
                        bool singular_ok);
  void overdamped_split(const std::vector<double> &velocity, const std::vector<double> &impulse);
  // the linear solve alone (solve() keeps the counts and reports)
  virtual etd::SolverResult solve_system(const std::vector<double> &rhs,
                                         std::vector<double> &solution, double mass_weight,
                                         double friction_weight, bool deflate,
                                         const std::vector<double> *start,
                                         const std::vector<double> *start_friction);
  std::function<void(double *, int)> sum_over_ranks() const;
  bool solve(const std::vector<double> &rhs, std::vector<double> &solution, double mass_weight,
             double friction_weight, bool deflate, bool singular_ok = false,
             const std::vector<double> *start = nullptr,
             const std::vector<double> *start_friction = nullptr);
};

}    // namespace LAMMPS_NS

#endif
