// ETD-DPD: the implicit scheme's pairs of one step, assembled in Kokkos kernels. From the step's
// candidate pairs (a half list, j with LAMMPS's special bits) each pair's geometry, friction
// gamma w_D and noise sigma w_R theta, with the tests and arithmetic of
// FrictionPairAssembly::build() and in its order (atom by atom, in the list's order), so the
// noise and the solve's sums are the host assembly's. Pure Kokkos (no LAMMPS); dpd/gen-type
// pairs only (no dpd/fpm). Under moving images (fix deform ... remap v) each pair also carries
// the velocity its ghost's image has on top of its owner's. One pass over the candidates writes
// each atom's pairs from the slot of its first candidate on (stage_pairs), a scan of the counts
// places them (place_pairs), and a copy packs them together (pack_pairs).
#ifndef ETD_FRICTION_PAIRS_KOKKOS_H
#define ETD_FRICTION_PAIRS_KOKKOS_H

#include "dpd_kernel.h"
#include "dpd_random.h"
#include "friction_operator.h"
#include "kokkos_views.h"

#include <Kokkos_Core.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace etd {

template <class DeviceType> class FrictionPairsKokkos {
 public:
  using execution_space = typename DeviceType::execution_space;
  using Indices = kk::Indices<DeviceType>;
  using Values = kk::Values<DeviceType>;
  using Geometry = kk::Geometry<DeviceType>;
  using Tags = Kokkos::View<std::int64_t *, DeviceType>;
  using Table = Kokkos::View<PairCoefficients *, DeviceType>;

  // One step's inputs, in host memory (LAMMPS's arrays; nall = owned + ghost atoms)
  struct Input {
    int nlocal = 0, nall = 0;
    int inum = 0;
    const int *ilist = nullptr, *numneigh = nullptr;
    int *const *firstneigh = nullptr;
    int neighbor_mask = 0, special_shift = 0;    // LAMMPS's NEIGHMASK and SBBITS
    const double *special = nullptr;             // special_lj[4]
    const double *x = nullptr;                   // 3 nall
    const int *type = nullptr, *mask = nullptr;  // nall
    const int *ghost_partner = nullptr;          // nall - nlocal: the partner each ghost is
    int groupbit = 0;
    bool newton_off = false;    // an image pair is listed from both ends
    std::int64_t step = 0;
    double cutsq_max = 0.0;    // the largest squared friction cutoff
    // moving images: per atom (nall) 6 counts of box vectors from its owner (nullptr: no
    // moving images), the box vectors' rates (LAMMPS's h_rate) and the deforming group's bit
    const double *image = nullptr;
    double image_rate[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    int deform_groupbit = 0;
  };

  // Each type pair's coefficients (nullptr: no friction pair; ntypes1 = ntypes + 1) and the
  // noise, with the ziggurat's tables where DeviceType reads them; once per run
  void set_coefficients(const std::vector<const PairCoefficients *> &table, int ntypes1,
                        const PairNoise &noise)
  {
    ntypes1_ = ntypes1;
    coefficients_ = Table("etd:pair_coefficients", table.size());
    present_ = Indices("etd:pair_present", table.size());
    auto h_coefficients = Kokkos::create_mirror_view(coefficients_);
    auto h_present = Kokkos::create_mirror_view(present_);
    for (size_t k = 0; k < table.size(); k++) {
      h_present(k) = (table[k] && table[k]->gamma != 0.0) ? 1 : 0;
      h_coefficients(k) = table[k] ? *table[k] : PairCoefficients{};
    }
    Kokkos::deep_copy(coefficients_, h_coefficients);
    Kokkos::deep_copy(present_, h_present);
    noise_ = noise;
    if constexpr (!reads_host) noise_ = kk::noise_with_device_tables(noise, ziggurat_);
  }

  // This step's pairs; tag: the atom IDs (nall). Returns whether a pair couples the group to an
  // atom outside it.
  template <typename Tag> bool build(const Input &in, const Tag *tag)
  {
    // where each listed atom's candidates start (the list's rows, end to end)
    const int ncandidates = row_starts(in);
    if (!list_in_place_) flatten_list(in, ncandidates);
    upload_atoms(in, tag);
    const bool any_fixed = stage_pairs(in, ncandidates);
    place_pairs(in.inum);
    pack_pairs(in.step);
    return any_fixed;
  }

  // (The kernels' launchers below are public: CUDA requires the function enclosing a device
  // lambda to be.)

  // The step's atoms in DeviceType's memory: the listed rows, positions, types, masks, the
  // ghosts' partners and, under moving images, their image counts; tag: the atom IDs (nall)
  template <typename Tag> void upload_atoms(const Input &in, const Tag *tag)
  {
    kk::upload(ilist_, in.ilist, in.inum);
    kk::upload(x_, in.x, 3 * in.nall);
    kk::upload(type_, in.type, in.nall);
    kk::upload(mask_, in.mask, in.nall);
    kk::upload(ghost_partner_, in.ghost_partner, in.nall - in.nlocal);
    moving_images_ = in.image != nullptr;
    if (moving_images_) kk::upload(image_, in.image + 6 * in.nlocal, 6 * (in.nall - in.nlocal));
    kk::grow(tag_, in.nall);
    auto h_tag = Kokkos::create_mirror_view(tag_);
    for (int a = 0; a < in.nall; a++) h_tag(a) = static_cast<std::int64_t>(tag[a]);
    Kokkos::deep_copy(tag_, h_tag);
  }

  // One pass over the candidates: each listed atom's pairs written from its first candidate's
  // slot on (staged_), and how many it has (pair_start_); returns whether a pair has an atom
  // outside the group
  bool stage_pairs(const Input &in, int ncandidates)
  {
    const Candidates candidates = candidates_of(in);
    auto candidate_start = list_start_;
    kk::grow(pair_start_, in.inum + 1);
    staged_.grow(ncandidates, moving_images_);
    kk::grow(staged_tag_j_, ncandidates);
    auto staged_tag_j = staged_tag_j_;
    auto pair_start = pair_start_;
    const PairArrays staged = staged_;
    const bool moving = moving_images_;
    auto image = image_;
    const int nlocal = in.nlocal, deform_groupbit = in.deform_groupbit;
    double rate[6];
    for (int k = 0; k < 6; k++) rate[k] = in.image_rate[k];
    auto tags = tag_;
    int fixed = 0;
    Kokkos::parallel_reduce(
        "etd:pairs_fill", Kokkos::RangePolicy<execution_space>(0, in.inum),
        KOKKOS_LAMBDA(const int ii, int &any_fixed) {
          const int first = candidate_start(ii);
          int at = first;
          candidates.visit(ii, [&](int i, int j, int partner, const double *d, double rsq,
                                   double factor, bool held) {
            const double r = std::sqrt(rsq);
            const double inv_r = 1.0 / r;
            const PairDissipation dissipation =
                pair_dissipation(candidates.coefficients(i, j), r, factor);
            staged.partner(at) = partner;
            for (int k = 0; k < 3; k++) staged.geometry(at, k) = static_cast<float>(d[k] * inv_r);
            staged.geometry(at, 3) = static_cast<float>(dissipation.friction);
            staged.noise(at) = dissipation.noise;    // (its Gaussian as the pairs are packed)
            staged_tag_j(at) = tags(j);
            staged.distance(at) = r;
            if (moving) {
              // (as PartnerMap::image_velocity adds it: zero for an owned atom)
              double offset[3] = {0.0, 0.0, 0.0};
              if (j >= nlocal && (candidates.mask(j) & deform_groupbit))
                image_velocity_offset(&image(6 * (j - nlocal)), rate, offset);
              for (int k = 0; k < 3; k++) staged.offset(3 * at + k) = offset[k];
            }
            at++;
            if (held) any_fixed = 1;
          });
          pair_start(ii) = at - first;
        },
        Kokkos::Max<int>(fixed));
    return fixed > 0;    // (Max starts from the lowest int, where no atom is listed)
  }

  // where each of the inum listed atoms' pairs start (an exclusive scan of the counts that
  // stage_pairs() left in pair_start_; the last entry is the total)
  void place_pairs(int inum)
  {
    auto pair_start = pair_start_;
    const int listed = inum;
    int total = 0;
    Kokkos::parallel_scan(
        "etd:pairs_place", Kokkos::RangePolicy<execution_space>(0, inum + 1),
        KOKKOS_LAMBDA(const int ii, int &sum, const bool final) {
          const int count = ii < listed ? pair_start(ii) : 0;
          if (final) pair_start(ii) = sum;
          sum += count;
        },
        total);
    npairs_ = total;
    inum_ = inum;
  }

  // The staged pairs moved together, in the list's order, each noise amplitude times its
  // Gaussian for this step (a pass of its own, as the host assembly draws them: the staging
  // pass, without the generator, overlaps the square roots of successive pairs)
  void pack_pairs(std::int64_t step)
  {
    kk::grow(pair_i_, npairs_);
    packed_.grow(npairs_, moving_images_);
    auto pair_i = pair_i_;
    const PairArrays packed = packed_;
    const PairArrays staged = staged_;
    auto staged_tag_j = staged_tag_j_;
    auto ilist = ilist_;
    auto tags = tag_;
    auto pair_start = pair_start_;
    auto candidate_start = list_start_;
    const bool moving = moving_images_;
    const PairNoise noise = noise_;
    Kokkos::parallel_for(
        "etd:pairs_pack", Kokkos::RangePolicy<execution_space>(0, inum_),
        KOKKOS_LAMBDA(const int ii) {
          const int i = ilist(ii);
          const std::int64_t tag_i = tags(i);
          for (int to = pair_start(ii), at = candidate_start(ii); to < pair_start(ii + 1); to++, at++) {
            pair_i(to) = i;
            packed.copy(to, staged, at, moving);
            packed.noise(to) = staged.noise(at) * noise.gaussian(tag_i, staged_tag_j(at), step);
          }
        });
  }

  int pairs() const { return npairs_; }
  // the pairs' rows: row r (of listed()) holds the pairs [row_starts(r), row_starts(r + 1)) of
  // atom rows(r), its i
  const Indices &rows() const { return ilist_; }
  const Indices &row_starts() const { return pair_start_; }
  int listed() const { return inum_; }
  const Indices &pair_i() const { return pair_i_; }
  const Indices &pair_j() const { return packed_.partner; }
  const Geometry &geometry() const { return packed_.geometry; }
  const Values &noise() const { return packed_.noise; }    // sigma w_R theta per pair
  // under moving images, each pair's image velocity offset (3 values per pair), else nullptr
  const Values *offsets() const { return moving_images_ ? &packed_.offset : nullptr; }

  // the pairs in host memory, as FrictionPairAssembly holds them (for the virial and the split);
  // offsets: under moving images, 3 per pair (else left empty)
  void copy_to_host(std::vector<FrictionPair> &pairs, std::vector<double> &noise,
                    std::vector<double> &distance, std::vector<double> *offsets = nullptr) const
  {
    if (offsets) {
      offsets->assign(moving_images_ ? 3 * npairs_ : 0, 0.0);
      if (moving_images_ && npairs_ > 0) kk::download(packed_.offset, offsets->data(), 3 * npairs_);
    }
    const int n = npairs_;
    auto h_i = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), pair_i_);
    auto h_j = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), packed_.partner);
    auto h_geometry = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), packed_.geometry);
    auto h_noise = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), packed_.noise);
    auto h_distance = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), packed_.distance);
    pairs.resize(n);
    noise.resize(n);
    distance.resize(n);
    for (int p = 0; p < n; p++) {
      pairs[p].i = h_i(p);
      pairs[p].j = h_j(p);
      for (int k = 0; k < 3; k++) pairs[p].e[k] = h_geometry(p, k);
      pairs[p].friction = h_geometry(p, 3);
      noise[p] = h_noise(p);
      distance[p] = h_distance(p);
    }
  }

  // whether DeviceType's kernels read host memory: then they read LAMMPS's list in place
  static constexpr bool reads_host =
      Kokkos::SpaceAccessibility<execution_space, Kokkos::HostSpace>::accessible;
  // the bytes its views hold (the step's pairs, their staging, the inputs' copies)
  std::size_t memory_usage() const
  {
    return packed_.memory_usage() + staged_.memory_usage() +
        kk::bytes_of(ziggurat_, coefficients_, present_, ilist_, list_start_, list_,
                     list_start_host_, x_, type_, mask_, ghost_partner_, tag_, image_,
                     pair_start_, pair_i_, staged_tag_j_);
  }

  // (a test takes a GPU's path on the host: the list copied into compressed rows)
  void copy_the_list(bool copy) { list_in_place_ = reads_host && !copy; }

  // The candidate pairs of one listed atom and the tests build() applies to them (public: a
  // device lambda captures it)
  struct Candidates {
    int inum, nlocal, neighbor_mask, special_shift, groupbit, ntypes1;
    // the list: LAMMPS's rows in place where the kernels read host memory, else compressed rows
    bool in_place;
    const int *numneigh;
    int *const *firstneigh;
    bool newton_off;
    double cutsq_max;
    double special[4];
    Indices ilist, list_start, list, type, mask, ghost_partner, present;
    Values x;
    Tags tag;
    Table table;

    KOKKOS_INLINE_FUNCTION const PairCoefficients &coefficients(int i, int j) const
    {
      return table(type(i) * ntypes1 + type(j));
    }
    // pair(i, j, partner, d = x_i - x_j, rsq, special factor, held: an atom outside the group)
    // for each friction pair of listed atom ii, in the list's order (j: the atom or its ghost
    // image, partner: the partner index it stands for)
    // The candidates within the largest cutoff are gathered first, in chunks, with the count
    // advanced by the test's result and no branch (close_neighbors.h: the margin of the list
    // holds a fair share of them), then the work is done on those alone, in the list's order.
    template <class Pair> KOKKOS_INLINE_FUNCTION void visit(int ii, Pair pair) const
    {
      const int i = ilist(ii);
      const bool i_mobile = (mask(i) & groupbit) != 0;
      const double xi0 = x(3 * i), xi1 = x(3 * i + 1), xi2 = x(3 * i + 2);
      const int first = in_place ? 0 : list_start(ii);
      const int last = in_place ? numneigh[i] : list_start(ii + 1);
      constexpr int CHUNK = 64;
      int close[CHUNK];
      for (int start = first; start < last; start += CHUNK) {
        const int end = start + CHUNK < last ? start + CHUNK : last;
        int nclose = 0;
        for (int n = start; n < end; n++) {
          const int j_bits = in_place ? firstneigh[i][n] : list(n);
          const int j = j_bits & neighbor_mask;
          const double d0 = xi0 - x(3 * j), d1 = xi1 - x(3 * j + 1), d2 = xi2 - x(3 * j + 2);
          close[nclose] = j_bits;
          nclose += (d0 * d0 + d1 * d1 + d2 * d2 < cutsq_max) ? 1 : 0;
        }
        for (int c = 0; c < nclose; c++) visit_close(i, i_mobile, xi0, xi1, xi2, close[c], pair);
      }
    }
    // the tests after the distance's, and pair(), for one gathered candidate
    template <class Pair>
    KOKKOS_INLINE_FUNCTION void visit_close(int i, bool i_mobile, double xi0, double xi1,
                                            double xi2, int j_bits, Pair &pair) const
    {
      const int j = j_bits & neighbor_mask;
      const double d[3] = {xi0 - x(3 * j), xi1 - x(3 * j + 1), xi2 - x(3 * j + 2)};
      const double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const double factor = special[(j_bits >> special_shift) & 3];
      if (factor == 0.0) return;
      int partner = j;
      if (j >= nlocal) {
        partner = ghost_partner(j - nlocal);
        if (partner < nlocal && newton_off && tag(i) >= tag(partner)) return;
      }
      const bool j_mobile = (mask(j) & groupbit) != 0;
      if (!i_mobile && !j_mobile) return;
      const int k = type(i) * ntypes1 + type(j);
      if (!present(k)) return;
      if (rsq >= table(k).rcsq_d || rsq == 0.0) return;
      pair(i, j, partner, d, rsq, factor, !i_mobile || !j_mobile);
    }
  };

  // Per pair: the atom or slot it pairs with (partner), its geometry (e and gamma w_D), noise
  // sigma w_R theta, distance and, under moving images, the image's velocity offset (3 values)
  // (public: a device lambda captures it)
  struct PairArrays {
    Indices partner;
    Geometry geometry;
    Values noise, distance, offset;
    void grow(int n, bool moving)
    {
      kk::grow(partner, n);
      kk::grow(geometry, n);
      kk::grow(noise, n);
      kk::grow(distance, n);
      if (moving) kk::grow(offset, 3 * n);
    }
    std::size_t memory_usage() const
    {
      return kk::bytes_of(partner, geometry, noise, distance, offset);
    }
    // pair `to` of these arrays from pair `at` of `from`
    KOKKOS_INLINE_FUNCTION void copy(int to, const PairArrays &from, int at, bool moving) const
    {
      partner(to) = from.partner(at);
      for (int k = 0; k < 4; k++) geometry(to, k) = from.geometry(at, k);
      noise(to) = from.noise(at);
      distance(to) = from.distance(at);
      if (moving)
        for (int k = 0; k < 3; k++) offset(3 * to + k) = from.offset(3 * at + k);
    }
  };

 private:
  int ntypes1_ = 1, npairs_ = 0, inum_ = 0;
  bool list_in_place_ = reads_host;
  PairNoise noise_;
  Values ziggurat_;
  Table coefficients_;
  Indices present_;
  // where each listed atom's candidates start (inum + 1), and, where the kernels cannot read
  // LAMMPS's list, the candidates in those compressed rows
  Indices ilist_, list_start_, list_;
  typename Indices::host_mirror_type list_start_host_;
  Values x_;
  Indices type_, mask_, ghost_partner_;
  Tags tag_;
  bool moving_images_ = false;
  Values image_;    // the ghosts' image counts (6 each)
  Indices pair_start_, pair_i_;
  PairArrays packed_;    // the step's pairs, in the list's order
  PairArrays staged_;    // the pairs at their atoms' candidate slots, before they are packed
  Tags staged_tag_j_;    // and their j's atom IDs (the noise's key with i's)

  Candidates candidates_of(const Input &in) const
  {
    Candidates c;
    c.inum = in.inum;
    c.nlocal = in.nlocal;
    c.neighbor_mask = in.neighbor_mask;
    c.special_shift = in.special_shift;
    c.in_place = list_in_place_;
    c.numneigh = in.numneigh;
    c.firstneigh = in.firstneigh;
    c.groupbit = in.groupbit;
    c.ntypes1 = ntypes1_;
    c.newton_off = in.newton_off;
    c.cutsq_max = in.cutsq_max;
    for (int k = 0; k < 4; k++) c.special[k] = in.special[k];
    c.ilist = ilist_;
    c.list_start = list_start_;
    c.list = list_;
    c.type = type_;
    c.mask = mask_;
    c.ghost_partner = ghost_partner_;
    c.present = present_;
    c.x = x_;
    c.tag = tag_;
    c.table = coefficients_;
    return c;
  }

  // Where each listed atom's candidates start, end to end (list_start_ and its host copy);
  // returns how many there are
  int row_starts(const Input &in)
  {
    kk::grow(list_start_, in.inum + 1);
    list_start_host_ = Kokkos::create_mirror_view(list_start_);
    auto &h_start = list_start_host_;
    h_start(0) = 0;
    for (int ii = 0; ii < in.inum; ii++) h_start(ii + 1) = h_start(ii) + in.numneigh[in.ilist[ii]];
    Kokkos::deep_copy(list_start_, h_start);
    return h_start(in.inum);
  }

  // the list in compressed rows (row_starts' rows), in DeviceType's memory (where its kernels
  // cannot read LAMMPS's)
  void flatten_list(const Input &in, int entries)
  {
    const auto &h_start = list_start_host_;
    kk::grow(list_, entries);
    auto h_list = Kokkos::create_mirror_view(list_);
    Kokkos::parallel_for(
        "etd:pairs_flatten", Kokkos::RangePolicy<Kokkos::DefaultHostExecutionSpace>(0, in.inum),
        [&](const int ii) {
          const int *neighbors = in.firstneigh[in.ilist[ii]];
          for (int n = h_start(ii); n < h_start(ii + 1); n++)
            h_list(n) = neighbors[n - h_start(ii)];
        });
    Kokkos::deep_copy(list_, h_list);
  }

};

}    // namespace etd

#endif
