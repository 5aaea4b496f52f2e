// ETD-DPD: the implicit scheme's pairs of one step (implicit_pair_assembly.h).
#include "implicit_pair_assembly.h"

#include "close_neighbors.h"
#include "implicit_partners.h"
#include "pair_law.h"

#include "atom.h"
#include "domain.h"
#include "dpd_kernel.h"
#include "error.h"
#include "force.h"
#include "fpm_kernel.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

namespace etd {

namespace {
  // j's share of a pair's sums is kept for owned atoms only: a remote partner's is its owner's
  struct OwnedOnly {
    int nlocal;
    bool operator()(int j) const { return j < nlocal; }
  };
}    // namespace

void FrictionPairAssembly::set_coefficients(LAMMPS *lmp,
                                            const std::vector<DpdPairInterface *> &styles)
{
  const int ntypes = lmp->atom->ntypes;
  ntypes1_ = ntypes + 1;
  pair_table_.assign(ntypes1_ * ntypes1_, nullptr);
  fpm_table_.assign(ntypes1_ * ntypes1_, nullptr);
  bool rotation = false;
  for (auto *p : styles) {
    bool supplies = false;
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++) {
        if (const PairCoefficients *c = p->dpd_coefficients(i, j)) {
          pair_table_[i * ntypes1_ + j] = c;
          supplies = true;
        }
        if (const FpmCoefficients *c = p->fpm_coefficients(i, j)) {
          fpm_table_[i * ntypes1_ + j] = c;
          supplies = rotation = true;
        }
      }
    // a style that cannot hand over its friction must not be silently reduced to its
    // conservative part
    if (!supplies)
      lmp->error->all(FLERR, "Fix etd scheme implicit: a pair style supplies no DPD coefficients");
    p->request_conservative_only();
  }
  friction_cutsq_max_ = 0.0;
  for (const PairCoefficients *c : pair_table_)
    if (c && c->gamma != 0.0) friction_cutsq_max_ = std::max(friction_cutsq_max_, c->rcsq_d);
  for (const FpmCoefficients *c : fpm_table_)
    if (c) friction_cutsq_max_ = std::max(friction_cutsq_max_, c->rcsq);
  dofs_ = rotation ? 6 : 3;
}

double FrictionPairAssembly::friction_cutoff(int itype, int jtype) const
{
  const PairCoefficients *c = pair_table_[itype * ntypes1_ + jtype];
  if (c) return c->gamma != 0.0 ? c->rc_d : 0.0;
  const FpmCoefficients *fc = fpm_table_[itype * ntypes1_ + jtype];
  return fc ? fc->rc : 0.0;
}

double FrictionPairAssembly::friction_cutoff_max() const
{
  return std::sqrt(friction_cutsq_max_);
}

void FrictionPairAssembly::clear(bool moving_images, int nlocal)
{
  pairs_.clear();
  pair_noise_.clear();
  pair_tags_.clear();
  fpm_pairs_.clear();
  fpm_noise_.clear();
  pair_distance_.clear();
  pair_offset_.clear();
  fpm_offset_.clear();
  image_friction_.assign(moving_images ? dofs_ * nlocal : 0, 0.0);
}

// inlined into build()'s pair loop: a call per pair there would keep the processor from
// overlapping the square roots of successive pairs
ETD_HOST_INLINE void FrictionPairAssembly::add_dpd_pair(const PairCoefficients &c, int i,
                                                        int partner, const double d[3], double rsq,
                                                        double factor,
                                                        std::pair<tagint, tagint> tags)
{
  const double r = std::sqrt(rsq);
  const double inv_r = 1.0 / r;
  const PairDissipation dissipation = pair_dissipation(c, r, factor);
  // written in place (a pair assembled on the stack and copied stalled on the copy)
  pairs_.emplace_back();
  FrictionPair &p = pairs_.back();
  p.i = i;
  p.j = partner;
  for (int k = 0; k < 3; k++) p.e[k] = static_cast<float>(d[k] * inv_r);
  p.friction = static_cast<float>(dissipation.friction);
  // the amplitude now, the Gaussian in a second pass: without the generator in it the pair
  // loop is short enough for the processor to overlap the square roots of successive pairs
  pair_noise_.push_back(dissipation.noise);
  pair_tags_.push_back(tags);
  pair_distance_.push_back(r);
}

bool FrictionPairAssembly::build(LAMMPS *lmp, const Context &context)
{
  Atom *atom = lmp->atom;
  const PairListView &list = context.list;
  const int *type = atom->type;
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;
  const double *special_lj = lmp->force->special_lj;
  const int nlocal = atom->nlocal;
  const int groupbit = context.groupbit;
  const bool moving_images = lmp->domain->deform_vremap;
  clear(moving_images, nlocal);
  const OwnedOnly keep_j{nlocal};
  // j's velocity on top of its owner's (a moving image); zero for owned atoms and resting images
  double offset[3];
  auto moving_image = [&](int j) {
    if (j >= nlocal && context.partners->image_velocity(lmp, j, offset)) return true;
    offset[0] = offset[1] = offset[2] = 0.0;
    return false;
  };
  bool fixed_partner = false;
  const double *xflat = nlocal + atom->nghost > 0 ? atom->x[0] : nullptr;    // rows at 3 j
  for (int ii = 0; ii < list.inum; ii++) {
    const int i = list.ilist[ii];
    const bool i_mobile = mask[i] & groupbit;
    const double xi0 = xflat[3 * i], xi1 = xflat[3 * i + 1], xi2 = xflat[3 * i + 2];
    // about half of the list lies in its skin: rejected by distance alone, before any of the
    // per-pair lookups below (close_neighbors.h)
    const int nclose = gather_close_neighbors(
        list.firstneigh[i], list.numneigh[i], NEIGHMASK, xflat, xi0, xi1, xi2,
        [&](int, double rsq) {
          return rsq < friction_cutsq_max_;
        },
        close_);
    for (int jj = 0; jj < nclose; jj++) {
      const int j_bits = close_[jj];
      const int j = j_bits & NEIGHMASK;
      const double *xj = xflat + 3 * j;
      const double d[3] = {xi0 - xj[0], xi1 - xj[1], xi2 - xj[2]};
      const double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const double factor = special_lj[(j_bits >> SBBITS) & 3];
      if (factor == 0.0) continue;
      int partner = j;
      if (j >= nlocal) {
        partner = context.partners->of_ghost(j, nlocal);
        // an image of an owned atom: a newton-off list holds the pair from both ends, one is
        // kept (an atom and its own image have no relative velocity and opposite noise)
        if (partner < nlocal && context.list_newton_off && tag[i] >= tag[partner]) continue;
      }
      const bool j_mobile = mask[j] & groupbit;
      if (!i_mobile && !j_mobile) continue;
      const PairCoefficients *c = pair_table_[type[i] * ntypes1_ + type[j]];
      if (!c) {
        const FpmCoefficients *fc = fpm_table_[type[i] * ntypes1_ + type[j]];
        if (fc && add_fpm_pair(*fc, i, partner, d, rsq, factor, tag[i], tag[j], context.step)) {
          if (!i_mobile || !j_mobile) fixed_partner = true;
          if (moving_images) {
            if (moving_image(j))
              accumulate_fpm_image_offset(fpm_pairs_.back(), offset, image_friction_.data(),
                                          keep_j);
            fpm_offset_.insert(fpm_offset_.end(), offset, offset + 3);
          }
        }
        continue;
      }
      if (c->gamma == 0.0) continue;
      if (rsq >= c->rcsq_d || rsq == 0.0) continue;
      add_dpd_pair(*c, i, partner, d, rsq, factor, {tag[i], tag[j]});
      if (!i_mobile || !j_mobile) fixed_partner = true;
      if (moving_images) {
        if (moving_image(j))
          accumulate_image_offset(pairs_.back(), offset, image_friction_.data(), keep_j, dofs_);
        pair_offset_.insert(pair_offset_.end(), offset, offset + 3);
      }
    }
  }
  for (size_t n = 0; n < pairs_.size(); n++)
    pair_noise_[n] *= noise_.gaussian(pair_tags_[n].first, pair_tags_[n].second, context.step);
  find_runs(pairs_, pair_runs_);
  return fixed_partner;
}

// One dpd/fpm pair (friction_operator.h): its geometry and its random force on i (without the
// time factor), sqrt(w) [sigma_C theta_C e + sigma_S theta_A x e]; false outside the cutoff.
bool FrictionPairAssembly::add_fpm_pair(const FpmCoefficients &c, int i, int j, const double d[3],
                                        double rsq, double factor, tagint tag_i, tagint tag_j,
                                        std::int64_t step)
{
  if (rsq >= c.rcsq || rsq == 0.0 || (c.gamma_c == 0.0 && c.gamma_s == 0.0)) return false;
  const double r = std::sqrt(rsq);
  const FpmDissipation dissipation = fpm_dissipation(c, r, factor);
  const double e[3] = {d[0] / r, d[1] / r, d[2] / r};
  FpmFrictionPair p;
  p.i = i;
  p.j = j;
  for (int k = 0; k < 3; k++) p.e[k] = static_cast<float>(e[k]);
  p.half_r = static_cast<float>(0.5 * r);
  p.central = static_cast<float>(dissipation.central);
  p.shear = static_cast<float>(dissipation.shear);
  fpm_pairs_.push_back(p);
  double theta[4];
  noise_.gaussians4(tag_i, tag_j, step, 0, theta);
  FpmNoise pair_noise;
  pair_noise.central = theta[0];
  for (int k = 0; k < 3; k++) pair_noise.shear[k] = theta[k + 1];
  const FpmRandomForce random = fpm_random_force(c, e, dissipation.noise, pair_noise);
  for (int k = 0; k < 3; k++) fpm_noise_.push_back(random.central * e[k] + random.shear[k]);
  return true;
}

void FrictionPairAssembly::accumulate_friction(const double *u, double *gu, int nlocal,
                                               double scale) const
{
  const OwnedOnly keep_j{nlocal};
  if (dofs_ == 3)
    accumulate_friction_by_runs<3>(pairs_, pair_runs_, u, gu, keep_j, scale);
  else
    accumulate_friction_by_runs<6>(pairs_, pair_runs_, u, gu, keep_j, scale);
  if (dofs_ == 6) accumulate_fpm_friction(fpm_pairs_, u, gu, keep_j, scale);
}

void FrictionPairAssembly::random_impulse(double scale, std::vector<double> &impulse,
                                          int nlocal) const
{
  impulse.assign(dofs_ * nlocal, 0.0);
  const OwnedOnly keep_j{nlocal};
  accumulate_noise(pairs_, pair_noise_, scale, impulse.data(), keep_j, dofs_);
  if (dofs_ == 6) accumulate_fpm_noise(fpm_pairs_, fpm_noise_, scale, impulse.data(), keep_j);
}

void FrictionPairAssembly::accumulate_blocks(std::vector<double> &diagonal, int block_values,
                                             int nlocal) const
{
  diagonal.assign(block_values * nlocal, 0.0);
  const OwnedOnly keep_j{nlocal};
  etd::accumulate_blocks(pairs_, diagonal.data(), keep_j, block_values);
  if (dofs_ == 6) accumulate_fpm_blocks(fpm_pairs_, diagonal.data(), keep_j);
}

void FrictionPairAssembly::adopt_pairs(std::vector<FrictionPair> pairs, std::vector<double> noise,
                                       std::vector<double> distance, int nlocal,
                                       std::vector<double> offsets)
{
  clear(!offsets.empty(), nlocal);
  pairs_ = std::move(pairs);
  pair_noise_ = std::move(noise);
  pair_distance_ = std::move(distance);
  pair_offset_ = std::move(offsets);
  // (build() sums the pairs with a moving image, in pair order)
  const OwnedOnly keep_j{nlocal};
  for (size_t n = 0; n < pair_offset_.size() / 3; n++) {
    const double *offset = &pair_offset_[3 * n];
    if (offset[0] != 0.0 || offset[1] != 0.0 || offset[2] != 0.0)
      accumulate_image_offset(pairs_[n], offset, image_friction_.data(), keep_j, dofs_);
  }
  find_runs(pairs_, pair_runs_);
}

size_t FrictionPairAssembly::memory_usage() const
{
  return sizeof(FrictionPair) * pairs_.capacity() + sizeof(double) * pair_noise_.capacity() +
      sizeof(FpmFrictionPair) * fpm_pairs_.capacity() + sizeof(double) * fpm_noise_.capacity();
}

}    // namespace etd
