// ETD-DPD: what the package's DPD pair styles share. As LAMMPS's dpd/tstat derives from dpd,
// pair_style dpd/gen and dpd/fpm derive from this class, which holds the settings (T, cutoff,
// seed) with their restart record and noise stream, the per-atom extras of DpdPairInterface
// (diagonal friction, rotational friction, force split) with their growth and reverse
// communication, and init_style's checks and neighbor request. A style adds its coefficient
// tables (coeff, init_one, the per type pair restart values, data file, single, extract) and
// compute().
#ifndef ETD_PAIR_DPD_BASE_H
#define ETD_PAIR_DPD_BASE_H

#include "dpd_pair_interface.h"
#include "dpd_random.h"
#include "lammps_compat.h"
#include "pair.h"

#include <vector>

namespace LAMMPS_NS {

class PairDPDBase : public Pair, public etd::DpdPairInterface {
 public:
  ~PairDPDBase() override;
  void settings(int, char **) override;
  void init_style() override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
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

 protected:
  // style: the name in the messages ("dpd/gen"); rotation: the style acts on angular velocities
  // (its diagonal friction comes with a rotational one)
  PairDPDBase(class LAMMPS *, const char *style, bool rotation);

  static constexpr double MIN_DISTANCE = 1.0e-10;    // coincident atoms (possible in DPD): no force
  static constexpr int FRICTION_VALUES = 3;
  static constexpr int FORCE_SPLIT_VALUES = 9;     // C, D, R of the force
  static constexpr int TORQUE_SPLIT_VALUES = 6;    // D, R of the torque (with rotation)

  const char *const style_name;
  const bool rotation;
  const int split_values;    // columns of split

  double temperature, cut_global;
  int seed;
  etd::PairNoise noise;
  std::vector<int> close_neighbors;    // the force loop's scratch: one atom's neighbours within rc
  double **cut;    // cutoff per type pair (upper triangle as set, mirrored in init_one)

  bool want_friction, want_split;
  bool conservative_only;    // friction and noise (and torques) left to fix etd's implicit scheme
  // the neighbor request of this init, and whether a user of the style made it newton off
  // (then the force loops leave ghost atoms alone, and LAMMPS's f dot r virial, which needs
  // their forces, is turned off until the next init)
  etd::compat::NeighRequestHandle neigh_request;
  bool list_newton_off, fdotr_turned_off;
  double **friction;         // [nmax][3] translational diagonal
  double **rot_friction;     // [nmax][3] rotational diagonal (with rotation only)
  double **split;            // [nmax][split_values]
  int nmax_extras;

  // the style's per type pair arrays: allocate_base() and its own
  virtual void allocate() = 0;
  void allocate_base();
  // its coefficients of one set type pair in the restart file, after the settings and the flag
  virtual void write_type_pair(FILE *, int i, int j) = 0;
  virtual void read_type_pair(FILE *, int i, int j) = 0;    // reads on rank 0, broadcasts

  bool type_pair_set(int i, int j) const;    // i, j in range and their coefficients set
  // compute(): the extras requested grown and zeroed before the force loop (true if any), and
  // after it the ghost atoms' contributions summed onto their owners
  bool prepare_extras();
  // whether the force loop adds to ghost atoms (and their sums are communicated back)
  bool forces_on_ghosts() const;
  void finish_extras(bool extras);
};

}    // namespace LAMMPS_NS

#endif
