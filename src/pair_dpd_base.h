// ETD-DPD: what the package's DPD pair styles share. As LAMMPS's dpd/tstat derives from dpd,
// every pair style of the package derives from this class (through PairDPDStyle,
// pair_dpd_style.h), which holds the settings (T, cutoff, seed) with their restart record and
// noise stream; the coefficients per type pair as the style describes them
// (pair_coeff_description.h) with pair_coeff, restart, write_data and extract; the per-atom
// extras of DpdPairInterface (diagonal friction, rotational friction, force split) with their
// growth and reverse communication; init_style's checks and neighbor request; and the one pair
// loop, eval(), over the style's law (pair_law.h).
#ifndef ETD_PAIR_DPD_BASE_H
#define ETD_PAIR_DPD_BASE_H

#include "close_neighbors.h"
#include "dpd_pair_interface.h"
#include "dpd_random.h"
#include "lammps_compat.h"
#include "pair.h"
#include "pair_coeff_description.h"
#include "pair_law.h"

#include "atom.h"
#include "cell_pair_search.h"
#include "force.h"
#include "neigh_list.h"
#include "update.h"

#include <cmath>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class PairDPDBase : public Pair, public etd::DpdPairInterface {
 public:
  ~PairDPDBase() override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  void *extract(const char *, int &) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // With rotation the translational and rotational diagonals come together: whoever integrates
  // translation with the friction diagonal needs the rotational one for the angular velocities.
  void request_diagonal_friction() override { want_friction = true; }
  void request_force_split() override { want_split = true; }
  double **diagonal_friction() override { return friction; }
  double **force_split() override { return split; }
  int force_split_columns() const override { return split_values; }
  double **rotational_friction() override { return rot_friction; }
  std::uint64_t noise_seed() const override { return static_cast<std::uint64_t>(seed); }
  void request_conservative_only() override { conservative_only = true; }
  void request_newton_off_list() override;
  bool use_external_pairs(const etd::ExternalPairs *source) override;

 protected:
  // coefficients: the style's name and its per type pair coefficients; rotation: the style
  // acts on angular velocities (its diagonal friction comes with a rotational one)
  PairDPDBase(class LAMMPS *, const etd::CoeffDescription &coefficients, bool rotation);

  static constexpr double MIN_DISTANCE = 1.0e-10;    // coincident atoms (possible in DPD): no force
  static constexpr int FRICTION_VALUES = 3;
  static constexpr int FORCE_SPLIT_VALUES = 9;     // C, D, R of the force
  static constexpr int TORQUE_SPLIT_VALUES = 6;    // D, R of the torque (with rotation)

  const etd::CoeffDescription description;
  const char *const style_name;
  const bool rotation;
  const int split_values;    // columns of split

  double temperature, cut_global;
  int seed;
  etd::PairNoise noise;
  std::vector<int> close_neighbors;    // the force loop's scratch: one atom's neighbours within rc
  // per parameter of the description its value per type pair (upper triangle as set, mirrored
  // in init_one), and for a parameter that defaults to another whether pair_coeff gave it
  std::vector<double **> coeff_values;
  std::vector<int **> coeff_given;
  double **cut;    // the cutoff parameter's values

  bool want_friction, want_split;
  bool conservative_only;    // friction and noise (and torques) left to fix etd's implicit scheme
  // the neighbor request of this init, and whether a user of the style made it newton off
  // (then the force loops leave ghost atoms alone, and LAMMPS's f dot r virial, which needs
  // their forces, is turned off until the next init)
  etd::compat::NeighRequestHandle neigh_request;
  bool list_newton_off, fdotr_turned_off;
  // fix etd's pairs for the step, in place of LAMMPS's list (made occasional), where it has them
  const etd::ExternalPairs *external_pairs;
  etd::PairListView pair_list;    // what the force loop reads this compute (select_pairs)
  void select_pairs();
  // The conservative-only loop (fix etd's implicit scheme) in chunks of rows run by runner
  // (the KOKKOS style's host threads), each into forces of its own, summed after; without a
  // runner it runs on one thread
  using ChunkRunner = etd::CellPairSearch::ChunkRunner;
  void run_in_chunks(int chunks, ChunkRunner runner);
  int loop_chunks = 1;
  ChunkRunner loop_runner;
  std::vector<std::vector<double>> chunk_forces;
  std::vector<std::vector<int>> chunk_close;
  double **friction;        // [nmax][3] translational diagonal
  double **rot_friction;    // [nmax][3] rotational diagonal (with rotation only)
  double **split;           // [nmax][split_values]
  int nmax_extras;

  // the per type pair arrays: allocate_base() and the style's own
  virtual void allocate() = 0;
  void allocate_base();
  // init_one's part for the coefficients: the pair set (else an error), the values defaulting
  // to another parameter resolved, [j][i] mirrored; returns the pair's range (largest cutoff)
  double init_type_pair(int i, int j);
  void type_pair_values(int i, int j, double *values) const;    // in the description's order

  bool type_pair_set(int i, int j) const;    // i, j in range and their coefficients set
  // compute(): the extras requested grown and zeroed before the force loop (true if any), and
  // after it the ghost atoms' contributions summed onto their owners
  bool prepare_extras();
  // whether the force loop adds to ghost atoms (and their sums are communicated back)
  bool forces_on_ghosts() const;
  void finish_extras(bool extras);

  // compute() for a style with law Law; table: its coefficients, row-major (ntypes+1)^2
  template <class Law>
  void compute_pairs(const typename Law::Coefficients *table, int stride, int eflag, int vflag);
  template <class Law, int EVFLAG>
  void eval_with_extras(const typename Law::Coefficients *table, int stride);
  // the force loop over the rows [first_row, last_row) (last_row < 0: all), into forces
  // (nullptr: atom->f) with close as its scratch (nullptr: close_neighbors)
  template <class Law, int EVFLAG, int FRICTION, int SPLIT, int DISSIPATIVE>
  void eval(const typename Law::Coefficients *table, int stride, int first_row = 0,
            int last_row = -1, double *forces = nullptr, std::vector<int> *close = nullptr);
  template <class Law> void eval_conservative_in_chunks(const typename Law::Coefficients *table, int stride);
  template <class Law, int DISSIPATIVE>
  void tally(const Law &pair, const typename Law::Coefficients &c, const etd::PairGeometry &g,
             int i, int j, int nlocal, int newton_pair);
  template <class Law, int FRICTION, int SPLIT>
  void add_extras(const Law &pair, int i, int j, bool update_j, double *gi, double *gri);

 private:
  std::string coeff_usage() const;
  double parse_coeff(const etd::CoeffParam &, const char *arg);
  void write_type_pair(FILE *, int i, int j);
  void read_type_pair(FILE *, int i, int j);    // reads on rank 0, broadcasts
  void write_type_pair_data(FILE *, int i, int j);
};

template <class Law>
void PairDPDBase::compute_pairs(const typename Law::Coefficients *table, int stride, int eflag,
                                int vflag)
{
  ev_init(eflag, vflag);
  select_pairs();
  const bool extras = prepare_extras();

  if (evflag)
    eval_with_extras<Law, 1>(table, stride);
  else if (conservative_only && !extras && loop_runner && loop_chunks > 1 && !Law::rotation)
    eval_conservative_in_chunks<Law>(table, stride);
  else
    eval_with_extras<Law, 0>(table, stride);
  finish_extras(extras);
  if (vflag_fdotr) virial_fdotr_compute();
}

// The extras are template flags so that the plain force loop carries none of their work.
template <class Law, int EVFLAG>
void PairDPDBase::eval_with_extras(const typename Law::Coefficients *table, int stride)
{
  if (conservative_only) {
    if (want_split)
      eval<Law, EVFLAG, 0, 1, 0>(table, stride);
    else
      eval<Law, EVFLAG, 0, 0, 0>(table, stride);
  } else if (want_split) {
    eval<Law, EVFLAG, 1, 1, 1>(table, stride);
  } else if (want_friction) {
    eval<Law, EVFLAG, 1, 0, 1>(table, stride);
  } else {
    eval<Law, EVFLAG, 0, 0, 1>(table, stride);
  }
}

// The conservative-only loop in chunks of rows at once, each into forces of its own over all
// atoms (ghosts too where newton is on), then summed into f chunk after chunk, atoms split
// among the chunks
template <class Law>
void PairDPDBase::eval_conservative_in_chunks(const typename Law::Coefficients *table, int stride)
{
  const int chunks = loop_chunks;
  const std::size_t values = 3 * static_cast<std::size_t>(atom->nlocal + atom->nghost);
  const long rows = pair_list.inum;
  chunk_forces.resize(chunks);
  chunk_close.resize(chunks);
  loop_runner(chunks, [&](int k) {
    chunk_forces[k].assign(values, 0.0);
    eval<Law, 0, 0, 0, 0>(table, stride, static_cast<int>(k * rows / chunks),
                          static_cast<int>((k + 1) * rows / chunks), chunk_forces[k].data(),
                          &chunk_close[k]);
  });
  if (values == 0) return;
  double *f = atom->f[0];
  loop_runner(chunks, [&](int k) {
    for (std::size_t d = k * values / chunks; d < (k + 1) * values / chunks; d++)
      for (int c = 0; c < chunks; c++) f[d] += chunk_forces[c][d];
  });
}

// DISSIPATIVE = 0: only the law's conservative force, which is central and makes no torque:
// what fix etd's implicit scheme leaves to the pair style (it applies friction and noise).
template <class Law, int EVFLAG, int FRICTION, int SPLIT, int DISSIPATIVE>
void PairDPDBase::eval(const typename Law::Coefficients *table, int stride, int first_row,
                       int last_row, double *forces, std::vector<int> *close)
{
  if (pair_list.inum == 0) return;    // (x may be unallocated on a rank without atoms)
  if (last_row < 0) last_row = pair_list.inum;
  std::vector<int> &close_list = close ? *close : close_neighbors;
  // LAMMPS stores x, v, f, omega and torque contiguously: atom j's row is at 3 j
  const double *xflat = atom->x[0];
  const double *vflat = atom->v[0];
  double *fflat = forces ? forces : atom->f[0];
  const double *omegaflat = Law::rotation ? atom->omega[0] : nullptr;
  double *torqueflat = Law::rotation ? atom->torque[0] : nullptr;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const double *special_lj = force->special_lj;
  const int newton_pair = forces_on_ghosts();
  const etd::PairStep step{noise, update->ntimestep, 1.0 / std::sqrt(update->dt)};

  for (int ii = first_row; ii < last_row; ii++) {
    const int i = pair_list.ilist[ii];
    // atom i's values and sums stay in registers over its neighbours (stores to j could alias
    // them in memory)
    const double xi[3] = {xflat[3 * i], xflat[3 * i + 1], xflat[3 * i + 2]};
    const double vi[3] = {vflat[3 * i], vflat[3 * i + 1], vflat[3 * i + 2]};
    double omegai[3] = {0.0, 0.0, 0.0};
    if (Law::rotation)
      for (int k = 0; k < 3; k++) omegai[k] = omegaflat[3 * i + k];
    const int itype = type[i];
    const typename Law::Coefficients *crow = table + itype * stride;
    const double *cutsqi = cutsq[itype];
    double fi[3] = {0.0, 0.0, 0.0}, ti[3] = {0.0, 0.0, 0.0};
    double gi[3] = {0.0, 0.0, 0.0}, gri[3] = {0.0, 0.0, 0.0};    // diagonal friction

    // the neighbours within the cutoff first (close_neighbors.h), then the work on those only
    const int nclose = etd::gather_close_neighbors(
        pair_list.firstneigh[i], pair_list.numneigh[i], NEIGHMASK, xflat, xi[0], xi[1], xi[2],
        [&](int j, double rsq) {
          return rsq < cutsqi[type[j]];
        },
        close_list);
    const int *near = close_list.data();
    for (int jj = 0; jj < nclose; jj++) {
      int j = near[jj];
      const double factor = special_lj[sbmask(j)];
      j &= NEIGHMASK;
      const double *xj = xflat + 3 * j;
      etd::PairGeometry g;
      for (int k = 0; k < 3; k++) g.del[k] = xi[k] - xj[k];
      g.rsq = g.del[0] * g.del[0] + g.del[1] * g.del[1] + g.del[2] * g.del[2];
      const int jtype = type[j];
      g.r = std::sqrt(g.rsq);
      if (g.r < MIN_DISTANCE) continue;
      g.rinv = 1.0 / g.r;
      g.special = factor;

      Law pair(crow[jtype], g);
      const etd::PairMotion motion{
          vi, vflat + 3 * j, omegai, Law::rotation ? omegaflat + 3 * j : nullptr, tag[i], tag[j]};
      pair.template evaluate<DISSIPATIVE>(motion, step);
      for (int k = 0; k < 3; k++) fi[k] += pair.force[k];
      const bool update_j = newton_pair || j < nlocal;
      if (update_j)
        for (int k = 0; k < 3; k++) fflat[3 * j + k] -= pair.force[k];
      if constexpr (Law::rotation && DISSIPATIVE) {
        for (int k = 0; k < 3; k++) ti[k] += pair.torque[k];
        if (update_j)
          for (int k = 0; k < 3; k++) torqueflat[3 * j + k] += pair.torque[k];
      }

      if (FRICTION || SPLIT) add_extras<Law, FRICTION, SPLIT>(pair, i, j, update_j, gi, gri);
      if (EVFLAG) tally<Law, DISSIPATIVE>(pair, crow[jtype], g, i, j, nlocal, newton_pair);
    }
    for (int k = 0; k < 3; k++) fflat[3 * i + k] += fi[k];
    if constexpr (Law::rotation)
      for (int k = 0; k < 3; k++) torqueflat[3 * i + k] += ti[k];
    if (FRICTION && want_friction) {
      for (int k = 0; k < 3; k++) friction[i][k] += gi[k];
      if constexpr (Law::rotation)
        for (int k = 0; k < 3; k++) rot_friction[i][k] += gri[k];
    }
  }
}

// The pair's contributions to the friction diagonal (i's summed in gi, gri) and to the split.
template <class Law, int FRICTION, int SPLIT>
ETD_HOST_INLINE void PairDPDBase::add_extras(const Law &pair, int i, int j, bool update_j,
                                             double *gi, double *gri)
{
  if (FRICTION && want_friction) {
    double gt[3], gr[3];
    pair.friction_diagonal(gt, gr);
    for (int k = 0; k < 3; k++) gi[k] += gt[k];
    if (update_j)
      for (int k = 0; k < 3; k++) friction[j][k] += gt[k];
    if constexpr (Law::rotation) {
      for (int k = 0; k < 3; k++) gri[k] += gr[k];
      if (update_j)
        for (int k = 0; k < 3; k++) rot_friction[j][k] += gr[k];
    }
  }
  if (SPLIT) {
    double parts[3][3], torque_parts[2][3];
    pair.split(parts, torque_parts);
    for (int p = 0; p < 3; p++)
      for (int k = 0; k < 3; k++) {
        split[i][3 * p + k] += parts[p][k];
        if (update_j) split[j][3 * p + k] -= parts[p][k];
      }
    if constexpr (Law::rotation)
      for (int p = 0; p < 2; p++)
        for (int k = 0; k < 3; k++) {
          split[i][FORCE_SPLIT_VALUES + 3 * p + k] += torque_parts[p][k];
          if (update_j) split[j][FORCE_SPLIT_VALUES + 3 * p + k] += torque_parts[p][k];
        }
  }
}

// The pair's energy and virial: from |F|/r where the force is central (as LAMMPS's pair styles
// tally), else from its components.
template <class Law, int DISSIPATIVE>
ETD_HOST_INLINE void PairDPDBase::tally(const Law &pair, const typename Law::Coefficients &c,
                                        const etd::PairGeometry &g, int i, int j, int nlocal,
                                        int newton_pair)
{
  const double evdwl = eflag_either ? Law::energy(c, g.rsq, g.r, g.special) : 0.0;
  if (Law::central || !DISSIPATIVE)
    ev_tally(i, j, nlocal, newton_pair, evdwl, 0.0, pair.fpair, g.del[0], g.del[1], g.del[2]);
  else
    ev_tally_xyz(i, j, nlocal, newton_pair, evdwl, 0.0, pair.force[0], pair.force[1], pair.force[2],
                 g.del[0], g.del[1], g.del[2]);
}

}    // namespace LAMMPS_NS

#endif
