// ETD-DPD: the common part of the package's pair styles (see pair_dpd_base.h); their
// coefficients are in pair_dpd_coeffs.cpp.
#include "pair_dpd_base.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "lammps_compat.h"
#include "memory.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cstring>
#include <utility>

using namespace LAMMPS_NS;

PairDPDBase::PairDPDBase(LAMMPS *lmp, const etd::CoeffDescription &coefficients, bool rotation_) :
    Pair(lmp), description(coefficients), style_name(coefficients.style), rotation(rotation_),
    split_values(rotation_ ? FORCE_SPLIT_VALUES + TORQUE_SPLIT_VALUES : FORCE_SPLIT_VALUES),
    temperature(0.0), cut_global(0.0), seed(0), cut(nullptr), want_friction(false),
    want_split(false), conservative_only(false), neigh_request(), list_newton_off(false),
    fdotr_turned_off(false), external_pairs(nullptr), friction(nullptr), rot_friction(nullptr),
    split(nullptr), nmax_extras(0)
{
  writedata = 1;
  restartinfo = 1;
  comm_reverse = (rotation ? 2 : 1) * FRICTION_VALUES + split_values;
}

PairDPDBase::~PairDPDBase()
{
  if (copymode) return;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    for (double **values : coeff_values) memory->destroy(values);
    for (int **given : coeff_given) memory->destroy(given);
  }
  memory->destroy(friction);
  memory->destroy(rot_friction);
  memory->destroy(split);
}

void PairDPDBase::allocate_base()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) setflag[i][j] = 0;
  coeff_values.assign(description.count, nullptr);
  coeff_given.assign(description.count, nullptr);
  for (int p = 0; p < description.count; p++) {
    const etd::CoeffParam &param = description.params[p];
    memory->create(coeff_values[p], n + 1, n + 1, "pair:coeff");
    for (int i = 0; i <= n; i++)
      for (int j = 0; j <= n; j++) coeff_values[p][i][j] = param.default_value;
    if (param.default_from == etd::DEFAULT_CUTOFF) cut = coeff_values[p];
    if (param.default_from >= 0) {
      memory->create(coeff_given[p], n + 1, n + 1, "pair:coeff_given");
      for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) coeff_given[p][i][j] = 0;
    }
  }
}

bool PairDPDBase::type_pair_set(int i, int j) const
{
  if (!allocated || i < 1 || j < 1 || i > atom->ntypes || j > atom->ntypes) return false;
  return setflag[std::min(i, j)][std::max(i, j)] != 0;
}

/* ----------------------------------------------------------------------
   pair_style STYLE T cutoff seed
------------------------------------------------------------------------- */

void PairDPDBase::settings(int narg, char **arg)
{
  if (narg != 3)
    error->all(FLERR, "Illegal pair_style {} command: expected 3 arguments (T cutoff seed), got {}",
               style_name, narg);
  temperature = utils::numeric(FLERR, arg[0], false, lmp);
  cut_global = utils::numeric(FLERR, arg[1], false, lmp);
  seed = utils::inumeric(FLERR, arg[2], false, lmp);
  if (temperature < 0.0)
    error->all(FLERR, "Illegal pair_style {} command: temperature must be >= 0, got {}", style_name,
               arg[0]);
  if (cut_global <= 0.0)
    error->all(FLERR, "Illegal pair_style {} command: cutoff must be > 0, got {}", style_name,
               arg[1]);
  if (seed <= 0)
    error->all(FLERR, "Illegal pair_style {} command: seed must be a positive integer, got {}",
               style_name, arg[2]);
  // the scalar stream for every style: dpd/fpm's central noise is then the same number dpd/gen
  // draws for the pair
  noise = etd::PairNoise(static_cast<std::uint64_t>(seed), etd::NoiseStream::PairScalar);

  // as in stock pair styles: a new global cutoff resets the cutoffs already set
  if (allocated) {
    for (int i = 1; i <= atom->ntypes; i++)
      for (int j = i; j <= atom->ntypes; j++)
        if (setflag[i][j]) cut[i][j] = cut_global;
  }
}

/* ---------------------------------------------------------------------- */

void PairDPDBase::init_style()
{
  if (rotation && (!atom->omega_flag || !atom->torque_flag))
    error->all(FLERR,
               "Pair style {} requires atoms with angular velocity and torque "
               "(atom_style sphere, or hybrid with sphere)",
               style_name);
  if (comm->ghost_velocity == 0)
    error->all(FLERR,
               "Pair style {} requires ghost atoms store velocity: use 'comm_modify vel yes'",
               style_name);
  if (atom->tag_enable == 0)
    error->all(FLERR, "Pair style {} requires atom IDs (its noise is keyed on them)", style_name);
  if (update->dt <= 0.0)
    error->all(FLERR, "Pair style {} requires a positive timestep", style_name);
  // LAMMPS's KOKKOS neighbor build refuses 'multi' for its own lists and crashes binning a host
  // style's list with it (NBinMulti::bin_atoms, seen with 4Feb2025 and stock dpd/fdt)
  if (lmp->kokkos && neighbor->style == Neighbor::MULTI)
    error->all(FLERR,
               "Pair style {} with the KOKKOS package (-k on) cannot use 'neighbor ... multi', "
               "which LAMMPS's KOKKOS neighbor build does not support: use 'neighbor SKIN bin'",
               style_name);
  neigh_request = etd::compat::request_half_list(neighbor, this, instance_me);
  // requests from the package's fixes and computes are renewed by their own init(), which
  // LAMMPS calls after this one: a run without fix etd gets the full DPD force back
  want_friction = want_split = conservative_only = false;
  list_newton_off = false;
  external_pairs = nullptr;
  if (fdotr_turned_off) no_virial_fdotr_compute = 0;
  fdotr_turned_off = false;
}

void PairDPDBase::request_newton_off_list()
{
  if (list_newton_off) return;
  etd::compat::make_request_newton_off(neighbor, neigh_request);
  list_newton_off = true;
  if (!no_virial_fdotr_compute) {
    no_virial_fdotr_compute = 1;
    fdotr_turned_off = true;
  }
}

void PairDPDBase::run_in_chunks(int chunks, ChunkRunner runner)
{
  loop_chunks = chunks;
  loop_runner = std::move(runner);
}

bool PairDPDBase::use_external_pairs(const etd::ExternalPairs *source)
{
  etd::compat::make_request_occasional(neighbor, neigh_request);
  external_pairs = source;
  return true;
}

void PairDPDBase::select_pairs()
{
  const etd::PairListView *given =
      external_pairs ? external_pairs->pairs_for_step(update->ntimestep) : nullptr;
  if (given) {
    pair_list = *given;
    return;
  }
  if (external_pairs) neighbor->build_one(list);    // occasional: built here when needed
  pair_list = etd::view_of(*list);
}

bool PairDPDBase::forces_on_ghosts() const
{
  return force->newton_pair && !list_newton_off;
}

/* ---------------------------------------------------------------------- */

bool PairDPDBase::prepare_extras()
{
  const bool extras = want_friction || want_split;
  if (!extras) return false;
  if (!friction && want_friction) nmax_extras = 0;
  if (!split && want_split) nmax_extras = 0;
  if (atom->nmax > nmax_extras) {
    nmax_extras = atom->nmax;
    if (want_friction) {
      memory->grow(friction, nmax_extras, FRICTION_VALUES, "pair:friction");
      if (rotation) memory->grow(rot_friction, nmax_extras, FRICTION_VALUES, "pair:rot_friction");
    }
    if (want_split) memory->grow(split, nmax_extras, split_values, "pair:split");
  }
  const int nzero = forces_on_ghosts() ? atom->nlocal + atom->nghost : atom->nlocal;
  if (want_friction && nzero > 0) {
    std::memset(&friction[0][0], 0, sizeof(double) * FRICTION_VALUES * nzero);
    if (rotation) std::memset(&rot_friction[0][0], 0, sizeof(double) * FRICTION_VALUES * nzero);
  }
  if (want_split && nzero > 0) std::memset(&split[0][0], 0, sizeof(double) * split_values * nzero);
  return true;
}

void PairDPDBase::finish_extras(bool extras)
{
  if (extras && forces_on_ghosts()) etd::compat::reverse_comm(comm, this);
}

int PairDPDBase::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  const int last = first + n;
  for (int i = first; i < last; i++) {
    if (want_friction) {
      for (int k = 0; k < FRICTION_VALUES; k++) buf[m++] = friction[i][k];
      if (rotation)
        for (int k = 0; k < FRICTION_VALUES; k++) buf[m++] = rot_friction[i][k];
    }
    if (want_split)
      for (int k = 0; k < split_values; k++) buf[m++] = split[i][k];
  }
  return m;
}

void PairDPDBase::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    if (want_friction) {
      for (int k = 0; k < FRICTION_VALUES; k++) friction[j][k] += buf[m++];
      if (rotation)
        for (int k = 0; k < FRICTION_VALUES; k++) rot_friction[j][k] += buf[m++];
    }
    if (want_split)
      for (int k = 0; k < split_values; k++) split[j][k] += buf[m++];
  }
}

/* ---------------------------------------------------------------------- */

void PairDPDBase::write_restart_settings(FILE *fp)
{
  fwrite(&temperature, sizeof(double), 1, fp);
  fwrite(&cut_global, sizeof(double), 1, fp);
  fwrite(&seed, sizeof(int), 1, fp);
  fwrite(&mix_flag, sizeof(int), 1, fp);
}

void PairDPDBase::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &temperature, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &cut_global, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &seed, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &mix_flag, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&temperature, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&cut_global, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&seed, 1, MPI_INT, 0, world);
  MPI_Bcast(&mix_flag, 1, MPI_INT, 0, world);
  noise = etd::PairNoise(static_cast<std::uint64_t>(seed), etd::NoiseStream::PairScalar);
}

// the settings, then per type pair i <= j its flag and, where set, the style's values
void PairDPDBase::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) write_type_pair(fp, i, j);
    }
}

void PairDPDBase::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j]) read_type_pair(fp, i, j);
    }
}

/* ---------------------------------------------------------------------- */

double PairDPDBase::memory_usage()
{
  double bytes = Pair::memory_usage();
  bytes += static_cast<double>(nmax_extras) *
      ((friction ? FRICTION_VALUES : 0) + (rot_friction ? FRICTION_VALUES : 0) +
       (split ? split_values : 0)) *
      sizeof(double);
  return bytes;
}
