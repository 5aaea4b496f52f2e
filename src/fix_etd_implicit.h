// ETD-DPD: fix etd ... scheme implicit: the exponential update with the full pairwise friction
// operator, solved by conjugate gradients, and its zero-mass limit (see doc/fix_etd.rst).
#ifndef ETD_FIX_ETD_IMPLICIT_H
#define ETD_FIX_ETD_IMPLICIT_H

#include "fix.h"

#include "dpd_pair_interface.h"
#include "dpd_random.h"
#include "friction_operator.h"
#include "friction_solve.h"
#include "neighbor_safety.h"
#include "partner_exchange.h"

#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class FixETDImplicit : public Fix, public etd::DpdFrictionIntegrator {
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

 private:
  bool overdamped;
  bool midpoint;      // overdamped: predictor-corrector (default) or a single solve
  bool warm_start;    // CG starts from the old velocities (else from the block-Jacobi solution)
  double tolerance;
  int max_iterations;
  double dt;
  class NeighList *list;
  bool list_newton_off;    // each image pair is listed from both ends
  std::vector<etd::DpdPairInterface *> dpd_styles;
  std::vector<const etd::PairCoefficients *> pair_table;    // (ntypes+1)^2, nullptr: no DPD
  std::vector<const etd::FpmCoefficients *> fpm_table;      // the same for dpd/fpm pairs
  double friction_cutsq_max = 0.0;    // the largest squared friction cutoff of any type pair
  int dofs;    // unknowns per atom: 3 (v), or 6 (v and Omega) when dpd/fpm pairs take part
  etd::PairNoise noise;
  std::vector<etd::FrictionPair> pairs;    // this step's geometry
  std::vector<etd::PairRun> pair_runs;     // its stretches of pairs with the same atom i
  std::vector<double> pair_noise;          // and each pair's sigma w_R theta
  std::vector<std::pair<tagint, tagint>> pair_tags;    // (its atom IDs, which key the noise)
  std::vector<etd::FpmFrictionPair> fpm_pairs;         // dpd/fpm pairs of this step
  std::vector<double> fpm_noise;                       // and their random forces (3 per pair)
  std::vector<double> pair_distance;                   // r of each DPD pair (its virial)
  // under remap v, each pair's velocity offset of j's moving image (3 per pair, zero for most)
  std::vector<double> pair_offset, fpm_offset;
  etd::NeighborSafety neighbor_safety;
  bool any_fixed_partner;    // some pair couples to an atom outside the group
  // Under fix deform ... remap v: per owned atom (dofs values), G applied to the velocity
  // offsets of the moving periodic images its pairs use (friction_operator.h), this step's
  // constant part of the friction; empty without remap v
  std::vector<double> image_friction;
  bool image_velocity(int ghost, double offset[3]) const;

  // The atoms G acts on, "partners": the owned atoms [0, nlocal), then one slot for each atom
  // of another rank that a pair uses (partner_exchange.h). Images of owned atoms are the owned
  // atoms themselves, and a pair that crosses ranks is held by both, each updating its own atom,
  // so applying G needs one exchange of the slots' values and no reverse sum.
  std::unique_ptr<etd::PartnerExchange> partners;
  bigint partners_built;             // neighbor->ncalls of the list they were found from
  int partner_slots;                 // remote atoms
  std::vector<int> ghost_partner;    // per ghost (index - nlocal): its partner index, or -1
  std::vector<int> slot_ghost;       // per slot: one ghost that is an image of it
  void find_partners();
  int npartners() const;    // owned atoms and slots

  // per-partner vectors, dofs values each: G's operand; per owned atom, the preconditioner blocks
  std::vector<double> operand, diagonal;
  // What the next forward (ghost) communication moves: per atom, 'width' values of each slot's
  // vector, in one message for all slots (each exchange is a point where the ranks wait for
  // each other); it may also carry the positions (with the periodic shift).
  struct CommSlot {
    std::vector<double> *vector;
    int width;
    bool image_counts =
        false;    // 6 values per atom that gain the periodic shift (pbc) sent with it
  };
  static constexpr int max_comm_slots = 3;
  CommSlot comm_slots[max_comm_slots];
  int comm_nslots;
  bool comm_positions;
  void forward_exchange(std::initializer_list<CommSlot> slots, bool positions = false);
  void accumulate_blocks(int block_values);

  // work vectors reused from step to step (per-step allocation costs page faults at scale)
  struct Work {
    std::vector<double> masses;    // solve(): per unknown, mass or moment of inertia
    std::vector<double> u, gu_rhs, step_rhs, impulse, solution, inertia, predicted;    // the steps
    std::vector<double> ghost_u, ghost_owner;    // per ghost: velocities, owner (rank, index)
    std::vector<double> ghost_image;    // per ghost: its count of box vectors (pbc) from its owner
    std::vector<double> mean, gmean;    // record_split()
    std::vector<double> lead;    // post_integrate(): how far the next friction step moves each atom
    std::vector<int> close;      // build_pairs(): one atom's neighbours within the friction cutoff
    etd::FrictionSolveWorkspace solve;
  } work;

  bool split_requested;
  int split_rows;    // rows of split allocated (atom->nmax at the last grow)
  double **split;
  void overdamped_split(const std::vector<double> &velocity, const std::vector<double> &impulse);
  void record_split(const std::vector<double> &random_force, double random_scale);
  // The dissipative and random forces of the step's pairs, at the given velocities (owned atoms,
  // remote partners filled here): for compute dpd/split and the virial
  void record_friction_forces(const std::vector<double> &mean_velocity,
                              const std::vector<double> &random_force, double random_scale);
  bool peratom_virial;    // a per-atom stress compute exists (stress/atom): fill vatom too
  void tally_friction_virial();
  bool virial_wanted() const;
  bool virial_this_step = false;    // virial_wanted(), decided once at the start of each step

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
  double atom_mass(int i) const;    // per-atom or per-type mass

  void kick(double fraction);
  void drift(double fraction);
  void build_pairs();
  bool add_fpm_pair(const etd::FpmCoefficients &c, int i, int j, const double d[3], double rsq,
                    double factor, tagint tag_i, tagint tag_j, std::int64_t step);
  void random_impulse(double scale, std::vector<double> &impulse);
  void dof_inertia(std::vector<double> &inertia) const;
  double *dof_pointer(int i, int k) const;
  void apply_friction(const double *u, std::vector<double> &gu, bool group_only);
  void gather_operand(const double *u, bool group_only);
  void accumulate_friction(const double *u, double *gu, double scale = 1.0) const;
  void friction_noise_step();
  void overdamped_step();
  bool overdamped_solve(const std::vector<double> &impulse, std::vector<double> &velocity,
                        bool singular_ok);
  bool solve(const std::vector<double> &rhs, std::vector<double> &solution, double mass_weight,
             double friction_weight, bool deflate, bool singular_ok = false,
             const std::vector<double> *start = nullptr,
             const std::vector<double> *start_friction = nullptr);
};

}    // namespace LAMMPS_NS

#endif
