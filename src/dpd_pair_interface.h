// ETD-DPD: the contracts between the package's pair styles, its integrators and its computes.
//
// Every DPD pair style of the package implements it (through PairDPDBase); fix etd and compute
// dpd/split find those styles, alone or inside pair hybrid / hybrid/overlay, by this type
// (dpd_style_lookup.h), never by their names.
#ifndef ETD_DPD_PAIR_INTERFACE_H
#define ETD_DPD_PAIR_INTERFACE_H

#include <cstdint>

namespace etd {

struct PairCoefficients;
struct FpmCoefficients;
struct PairListView;    // solver/cell_pair_search.h

// Pairs found by an integrator for the positions of the current step (fix etd scheme
// implicit's own search), which a pair style can read instead of its LAMMPS list.
class ExternalPairs {
 public:
  // the pairs for this step, or nullptr where there are none (a minimization, a rerun, or
  // before the integrator's first search of a run)
  virtual const PairListView *pairs_for_step(std::int64_t step) const = 0;

 protected:
  ~ExternalPairs() = default;
};

// Per-atom extras a pair style accumulates during compute() on request (owned atoms complete,
// ghost contributions already reverse-communicated):
//   diagonal friction Gamma_i,alpha = sum_j gamma_ij w_D e_alpha^2      (fix etd)
//   conservative, dissipative and random parts of the pair force,
//   and of the torque where the style has rotation                      (compute dpd/split)
class DpdPairInterface {
 public:
  // Each user sets its flag once in init(); the pair style then fills the arrays every compute().
  virtual void request_diagonal_friction() = 0;
  virtual void request_force_split() = 0;
  virtual double **diagonal_friction() = 0;    // [nlocal][3]
  virtual double **force_split() = 0;    // [nlocal][force_split_columns()]: C xyz, D xyz, R xyz
  // 9, or 15 where the style has rotation: then also the torque's D xyz and R xyz (its
  // conservative part is zero: central forces make no torque)
  virtual int force_split_columns() const = 0;
  // Angular counterparts (dpd/fpm): nullptr where the style has no rotation.
  virtual double **rotational_friction() { return nullptr; }

  // For fix etd's implicit scheme, which applies friction and noise itself: the style's DPD
  // coefficients per type pair (nullptr where it does not handle the pair), the seed of its
  // noise, and a switch (set in each init, cleared by the style's own init) that leaves the
  // style computing only its non-dissipative forces.
  virtual const PairCoefficients *dpd_coefficients(int /*itype*/, int /*jtype*/) { return nullptr; }
  // the same for dpd/fpm's central and shear friction with rotation (nullptr elsewhere)
  virtual const FpmCoefficients *fpm_coefficients(int /*itype*/, int /*jtype*/) { return nullptr; }
  virtual std::uint64_t noise_seed() const { return 0; }
  virtual void request_conservative_only() {}
  // Where the scheme needs a newton-off list (several ranks) and newton is on: the style's own
  // list made newton off for this run (its forces then stay on owned atoms and its virial is
  // summed pair by pair), so that LAMMPS builds one list for both.
  virtual void request_newton_off_list() {}
  // Where the scheme searches the pairs itself: the style's list is made occasional for this
  // run (LAMMPS no longer builds it at each reneighboring), and compute() reads the scheme's
  // pairs, or builds that list itself at a step where the scheme has none. Styles that cannot
  // return false.
  virtual bool use_external_pairs(const ExternalPairs * /*source*/) { return false; }

 protected:
  // never deleted through this interface; non-virtual so that it does not constrain the
  // exception specification of LAMMPS's virtual destructors (which differs between versions)
  ~DpdPairInterface() = default;
};

// An integrator that applies the DPD friction and noise itself, so that the pair styles compute
// only their conservative part (fix etd scheme implicit): compute dpd/split reads the
// dissipative and random parts from it. Found among the fixes by this type.
class DpdFrictionIntegrator {
 public:
  // set once in the user's init(); the integrator then records the split every friction step
  virtual void request_split() = 0;
  virtual double **dissipative_random_split() const = 0;    // [nlocal][6]: D xyz, R xyz

 protected:
  ~DpdFrictionIntegrator() = default;
};

}    // namespace etd

#endif
