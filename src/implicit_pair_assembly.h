// ETD-DPD: the implicit scheme's pairs of one step, assembled from a neighbor list and the pair
// styles' coefficients: the geometry of G (friction_operator.h), each pair's noise, and what
// the virial and compute dpd/split read back.
#ifndef ETD_IMPLICIT_PAIR_ASSEMBLY_H
#define ETD_IMPLICIT_PAIR_ASSEMBLY_H

#include "cell_pair_search.h"
#include "dpd_pair_interface.h"
#include "dpd_random.h"
#include "friction_operator.h"
#include "lammps.h"
#include "lmptype.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace etd {

class PartnerMap;

class FrictionPairAssembly {
 public:
  // Each type pair's coefficients from the styles that supply them (ERROR for a style that
  // supplies none); dofs() is then 6 where dpd/fpm pairs take part, else 3.
  void set_coefficients(LAMMPS_NS::LAMMPS *lmp, const std::vector<DpdPairInterface *> &styles);
  void set_noise(const PairNoise &noise) { noise_ = noise; }
  int dofs() const { return dofs_; }
  bool rotation() const { return dofs_ == 6; }
  // a type pair's friction cutoff, 0 where the friction step has no pairs of those types
  double friction_cutoff(int itype, int jtype) const;
  double friction_cutoff_max() const;    // over all type pairs

  struct Context {
    PairListView list;
    const PartnerMap *partners;
    int groupbit;
    bool list_newton_off;    // each image pair is listed from both ends
    std::int64_t step;       // keys the noise
  };
  // This step's pairs at the current positions (ghosts included); true where some pair couples
  // the group to an atom outside it (on this rank).
  bool build(LAMMPS_NS::LAMMPS *lmp, const Context &context);

  // gu += scale G u over the owned atoms, u given on all partners (a remote partner's share is
  // its owner's to compute)
  void accumulate_friction(const double *u, double *gu, int nlocal, double scale = 1.0) const;
  // the random impulse sum_pairs B xi, times scale, on the owned atoms (a pair that crosses
  // ranks draws the same theta on both: the noise is keyed on the atom IDs)
  void random_impulse(double scale, std::vector<double> &impulse, int nlocal) const;
  // each owned atom's 3x3 block(s) of G (6 values each, v-v and with rotation Omega-Omega)
  void accumulate_blocks(std::vector<double> &diagonal, int block_values, int nlocal) const;
  // Under fix deform ... remap v: per owned atom (dofs values), G applied to the velocity
  // offsets of the moving periodic images its pairs use, this step's constant part of the
  // friction; empty without remap v
  const std::vector<double> &image_friction() const { return image_friction_; }

  // what the virial reads: per pair its geometry, noise sigma w_R theta, distance and moving
  // image's velocity offset (3 values, or none without remap v)
  const std::vector<FrictionPair> &pairs() const { return pairs_; }
  const std::vector<double> &pair_noise() const { return pair_noise_; }
  const std::vector<double> &pair_distance() const { return pair_distance_; }
  const std::vector<double> &pair_offset() const { return pair_offset_; }
  const std::vector<FpmFrictionPair> &fpm_pairs() const { return fpm_pairs_; }
  const std::vector<double> &fpm_noise() const { return fpm_noise_; }    // 3 per pair
  const std::vector<double> &fpm_offset() const { return fpm_offset_; }
  size_t memory_usage() const;

  // For an assembly elsewhere (the KOKKOS styles' kernels): each type pair's coefficients
  // (nullptr: none; types 1..ntypes, ntypes1() = ntypes + 1), the largest squared friction
  // cutoff, the noise, and the pairs it made, handed back (as build() would have made them,
  // without dpd/fpm pairs) for what reads them on the host; under moving images with each
  // pair's image velocity offset (3 values per pair; empty: none), from which the constant part
  // of G is summed as build() sums it
  const PairCoefficients *coefficients(int itype, int jtype) const
  {
    return pair_table_[itype * ntypes1_ + jtype];
  }
  bool has_fpm_pairs() const { return dofs_ == 6; }
  int ntypes1() const { return ntypes1_; }
  double friction_cutsq_max() const { return friction_cutsq_max_; }
  const PairNoise &noise() const { return noise_; }
  void adopt_pairs(std::vector<FrictionPair> pairs, std::vector<double> noise,
                   std::vector<double> distance, int nlocal, std::vector<double> offsets = {});

 private:
  std::vector<const PairCoefficients *> pair_table_;    // (ntypes+1)^2, nullptr: no DPD
  std::vector<const FpmCoefficients *> fpm_table_;      // the same for dpd/fpm pairs
  int ntypes1_ = 1;
  double friction_cutsq_max_ = 0.0;    // the largest squared friction cutoff of any type pair
  int dofs_ = 3;
  PairNoise noise_;
  std::vector<FrictionPair> pairs_;
  std::vector<PairRun> pair_runs_;    // stretches of pairs with the same i
  std::vector<double> pair_noise_;    // each pair's sigma w_R theta
  std::vector<std::pair<LAMMPS_NS::tagint, LAMMPS_NS::tagint>> pair_tags_;    // keys of theta
  std::vector<FpmFrictionPair> fpm_pairs_;
  std::vector<double> fpm_noise_;
  std::vector<double> pair_distance_;
  std::vector<double> pair_offset_, fpm_offset_;
  std::vector<double> image_friction_;
  std::vector<int> close_;    // one atom's neighbours within the friction cutoff

  void clear(bool moving_images, int nlocal);
  void add_dpd_pair(const PairCoefficients &c, int i, int partner, const double d[3], double rsq,
                    double factor, std::pair<LAMMPS_NS::tagint, LAMMPS_NS::tagint> tags);
  bool add_fpm_pair(const FpmCoefficients &c, int i, int j, const double d[3], double rsq,
                    double factor, LAMMPS_NS::tagint tag_i, LAMMPS_NS::tagint tag_j,
                    std::int64_t step);
};

}    // namespace etd

#endif
