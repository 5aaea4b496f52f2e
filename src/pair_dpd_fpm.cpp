// ETD-DPD: pair_style dpd/fpm. Thin LAMMPS adapter over fpm_kernel.h and dpd_random.h.
#include "pair_dpd_fpm.h"

#include "close_neighbors.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
constexpr int NCOEFF = 5;    // a, gamma_C, gamma_S, s, cutoff
}    // namespace

PairDPDFPM::PairDPDFPM(LAMMPS *lmp) :
    PairDPDBase(lmp, "dpd/fpm", true), a0(nullptr), gamma_c(nullptr), gamma_s(nullptr),
    exponent_d(nullptr), stride(0)
{
}

PairDPDFPM::~PairDPDFPM()
{
  if (copymode) return;
  if (allocated) {
    memory->destroy(a0);
    memory->destroy(gamma_c);
    memory->destroy(gamma_s);
    memory->destroy(exponent_d);
  }
}

void PairDPDFPM::allocate()
{
  allocate_base();
  const int n = atom->ntypes;
  memory->create(a0, n + 1, n + 1, "pair:a0");
  memory->create(gamma_c, n + 1, n + 1, "pair:gamma_c");
  memory->create(gamma_s, n + 1, n + 1, "pair:gamma_s");
  memory->create(exponent_d, n + 1, n + 1, "pair:exponent_d");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) {
      a0[i][j] = gamma_c[i][j] = gamma_s[i][j] = 0.0;
      exponent_d[i][j] = 2.0;
    }
  stride = n + 1;
  coeffs.assign(static_cast<size_t>(stride) * stride, etd::FpmCoefficients());
}

/* ----------------------------------------------------------------------
   pair_coeff I J a gamma_C gamma_S s [cutoff]
------------------------------------------------------------------------- */

void PairDPDFPM::coeff(int narg, char **arg)
{
  if (narg < 6 || narg > 7)
    error->all(FLERR,
               "Incorrect args for pair_coeff dpd/fpm: expected I J a gamma_C gamma_S s "
               "[cutoff], got {} arguments",
               narg);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  const double a_one = utils::numeric(FLERR, arg[2], false, lmp);
  const double gamma_c_one = utils::numeric(FLERR, arg[3], false, lmp);
  const double gamma_s_one = utils::numeric(FLERR, arg[4], false, lmp);
  const double s_one = utils::numeric(FLERR, arg[5], false, lmp);
  if (gamma_c_one < 0.0)
    error->all(FLERR, "pair_coeff dpd/fpm: gamma_C must be >= 0, got {}", arg[3]);
  if (gamma_s_one < 0.0)
    error->all(FLERR, "pair_coeff dpd/fpm: gamma_S must be >= 0, got {}", arg[4]);
  if (s_one <= 0.0)
    error->all(FLERR, "pair_coeff dpd/fpm: dissipative exponent s must be > 0, got {}", arg[5]);
  double cut_one = cut_global;
  if (narg == 7) {
    cut_one = utils::numeric(FLERR, arg[6], false, lmp);
    if (cut_one <= 0.0) error->all(FLERR, "pair_coeff dpd/fpm: cutoff must be > 0, got {}", arg[6]);
  }

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      a0[i][j] = a_one;
      gamma_c[i][j] = gamma_c_one;
      gamma_s[i][j] = gamma_s_one;
      exponent_d[i][j] = s_one;
      cut[i][j] = cut_one;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0)
    error->all(FLERR, "pair_coeff dpd/fpm: no type pairs selected by {} {}", arg[0], arg[1]);
}

/* ---------------------------------------------------------------------- */

void PairDPDFPM::init_style()
{
  if (!atom->omega_flag || !atom->torque_flag)
    error->all(FLERR,
               "Pair style dpd/fpm requires atoms with angular velocity and torque "
               "(atom_style sphere, or hybrid with sphere)");
  PairDPDBase::init_style();
}

const etd::FpmCoefficients *PairDPDFPM::fpm_coefficients(int i, int j)
{
  return type_pair_set(i, j) ? &coeffs[i * stride + j] : nullptr;
}

double PairDPDFPM::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR,
               "Pair style dpd/fpm: pair coefficients for types {} {} are not set (no mixing)", i,
               j);

  const double kT = force->boltz * temperature;
  etd::FpmCoefficients c;
  c.set(a0[i][j], gamma_c[i][j], gamma_s[i][j], exponent_d[i][j], cut[i][j], kT);
  coeffs[i * stride + j] = c;
  coeffs[j * stride + i] = c;

  a0[j][i] = a0[i][j];
  gamma_c[j][i] = gamma_c[i][j];
  gamma_s[j][i] = gamma_s[i][j];
  exponent_d[j][i] = exponent_d[i][j];
  cut[j][i] = cut[i][j];
  return cut[i][j];
}

/* ---------------------------------------------------------------------- */

void PairDPDFPM::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const bool extras = prepare_extras();

  if (conservative_only) {
    if (evflag)
      eval<1, 0, 0>();
    else
      eval<0, 0, 0>();
  } else if (evflag) {
    if (extras)
      eval<1, 1, 1>();
    else
      eval<1, 0, 1>();
  } else {
    if (extras)
      eval<0, 1, 1>();
    else
      eval<0, 0, 1>();
  }

  finish_extras(extras);
  if (vflag_fdotr) virial_fdotr_compute();
}

// DISSIPATIVE = 0: only the central conservative force a (1 - r/rc) e, which makes no torque:
// what the implicit scheme of fix etd leaves to the pair style (it applies friction and noise)
template <int EVFLAG, int EXTRAS, int DISSIPATIVE> void PairDPDFPM::eval()
{
  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  double **omega = atom->omega;
  double **torque = atom->torque;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const double *special_lj = force->special_lj;
  const int newton_pair = forces_on_ghosts();
  const double inv_sqrt_dt = 1.0 / std::sqrt(update->dt);
  const std::int64_t step = update->ntimestep;

  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  if (inum == 0) return;         // (x may be unallocated on a rank without atoms)
  const double *xflat = x[0];    // LAMMPS's rows are contiguous: atom j's at 3 j

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    const tagint tag_i = tag[i];
    const etd::FpmCoefficients *crow = &coeffs[itype * stride];
    const double *cutsqi = cutsq[itype];
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    // atom i's sums stay in registers over its neighbours (stores to j could alias them in memory)
    const double xi[3] = {x[i][0], x[i][1], x[i][2]};
    const double vi[3] = {v[i][0], v[i][1], v[i][2]};
    const double omegai[3] = {omega[i][0], omega[i][1], omega[i][2]};
    double fi[3] = {0.0, 0.0, 0.0}, ti[3] = {0.0, 0.0, 0.0};
    double gi[3] = {0.0, 0.0, 0.0}, gri[3] = {0.0, 0.0, 0.0};

    // the neighbours within the cutoff first (close_neighbors.h), then the work on those only
    const int nclose = etd::gather_close_neighbors(
        jlist, jnum, NEIGHMASK, xflat, xi[0], xi[1], xi[2],
        [&](int j, double rsq) {
          return rsq < cutsqi[type[j]];
        },
        close_neighbors);
    const int *close = close_neighbors.data();

    for (int jj = 0; jj < nclose; jj++) {
      int j = close[jj];
      const double factor = special_lj[sbmask(j)];
      j &= NEIGHMASK;
      const double *xj = xflat + 3 * j;
      const double del[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      const int jtype = type[j];
      const double r = std::sqrt(rsq);
      if (r < MIN_DISTANCE) continue;
      const etd::FpmCoefficients &c = crow[jtype];
      if (!DISSIPATIVE) {
        const double fpair = factor * c.a * (1.0 - r * c.inv_rc) / r;
        for (int k = 0; k < 3; k++) fi[k] += del[k] * fpair;
        if (newton_pair || j < nlocal)
          for (int k = 0; k < 3; k++) f[j][k] -= del[k] * fpair;
        if (EVFLAG) {
          const double evdwl = eflag_either ? etd::fpm_energy(c, r, factor) : 0.0;
          ev_tally(i, j, nlocal, newton_pair, evdwl, 0.0, fpair, del[0], del[1], del[2]);
        }
        continue;
      }

      const double v_ij[3] = {vi[0] - v[j][0], vi[1] - v[j][1], vi[2] - v[j][2]};
      const double omega_sum[3] = {omegai[0] + omega[j][0], omegai[1] + omega[j][1],
                                   omegai[2] + omega[j][2]};
      double theta[4];
      noise.gaussians4(tag_i, tag[j], step, 0, theta);
      etd::FpmNoise pair_noise;
      pair_noise.central = theta[0];
      pair_noise.shear[0] = theta[1];
      pair_noise.shear[1] = theta[2];
      pair_noise.shear[2] = theta[3];
      const etd::FpmPairResult pr =
          etd::fpm_pair(c, del, r, v_ij, omega_sum, pair_noise, inv_sqrt_dt, factor);
      const double fx = pr.force(0), fy = pr.force(1), fz = pr.force(2);

      fi[0] += fx;
      fi[1] += fy;
      fi[2] += fz;
      ti[0] += pr.torque[0];
      ti[1] += pr.torque[1];
      ti[2] += pr.torque[2];
      const bool update_j = newton_pair || j < nlocal;
      if (update_j) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
        torque[j][0] += pr.torque[0];
        torque[j][1] += pr.torque[1];
        torque[j][2] += pr.torque[2];
      }

      if (EXTRAS) {
        const double rinv = 1.0 / r;
        const double e[3] = {del[0] * rinv, del[1] * rinv, del[2] * rinv};
        if (want_friction) {
          double g[3], gr[3];
          etd::fpm_translational_friction(pr.central_friction, pr.shear_friction, e, g);
          etd::fpm_rotational_friction(pr.shear_friction, rsq, e, gr);
          for (int k = 0; k < 3; k++) {
            gi[k] += g[k];
            gri[k] += gr[k];
            if (update_j) {
              friction[j][k] += g[k];
              rot_friction[j][k] += gr[k];
            }
          }
        }
        if (want_split) {
          const double *parts[3] = {pr.conservative, pr.dissipative, pr.random};
          for (int p = 0; p < 3; p++)
            for (int k = 0; k < 3; k++) {
              split[i][3 * p + k] += parts[p][k];
              if (update_j) split[j][3 * p + k] -= parts[p][k];
            }
          // the torque's dissipative and random parts, the same on i and j
          double torque_parts[2][3];
          etd::fpm_pair_torque(del, pr.dissipative, torque_parts[0]);
          etd::fpm_pair_torque(del, pr.random, torque_parts[1]);
          for (int p = 0; p < 2; p++)
            for (int k = 0; k < 3; k++) {
              split[i][FORCE_SPLIT_VALUES + 3 * p + k] += torque_parts[p][k];
              if (update_j) split[j][FORCE_SPLIT_VALUES + 3 * p + k] += torque_parts[p][k];
            }
        }
      }

      if (EVFLAG) {
        const double evdwl = eflag_either ? etd::fpm_energy(c, r, factor) : 0.0;
        ev_tally_xyz(i, j, nlocal, newton_pair, evdwl, 0.0, fx, fy, fz, del[0], del[1], del[2]);
      }
    }
    for (int k = 0; k < 3; k++) {
      f[i][k] += fi[k];
      torque[i][k] += ti[k];
    }
    if (EXTRAS && want_friction)
      for (int k = 0; k < 3; k++) {
        friction[i][k] += gi[k];
        rot_friction[i][k] += gri[k];
      }
  }
}

/* ----------------------------------------------------------------------
   restart file: per set type pair its five values
------------------------------------------------------------------------- */

void PairDPDFPM::write_type_pair(FILE *fp, int i, int j)
{
  const double values[NCOEFF] = {a0[i][j], gamma_c[i][j], gamma_s[i][j], exponent_d[i][j],
                                 cut[i][j]};
  fwrite(values, sizeof(double), NCOEFF, fp);
}

void PairDPDFPM::read_type_pair(FILE *fp, int i, int j)
{
  double values[NCOEFF];
  if (comm->me == 0) utils::sfread(FLERR, values, sizeof(double), NCOEFF, fp, nullptr, error);
  MPI_Bcast(values, NCOEFF, MPI_DOUBLE, 0, world);
  a0[i][j] = values[0];
  gamma_c[i][j] = values[1];
  gamma_s[i][j] = values[2];
  exponent_d[i][j] = values[3];
  cut[i][j] = values[4];
}

void PairDPDFPM::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    fprintf(fp, "%d %.15g %.15g %.15g %.15g %.15g\n", i, a0[i][i], gamma_c[i][i], gamma_s[i][i],
            exponent_d[i][i], cut[i][i]);
}

void PairDPDFPM::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      fprintf(fp, "%d %d %.15g %.15g %.15g %.15g %.15g\n", i, j, a0[i][j], gamma_c[i][j],
              gamma_s[i][j], exponent_d[i][j], cut[i][j]);
}

/* ----------------------------------------------------------------------
   conservative part only, as stock pair dpd: the other parts depend on velocities and noise
------------------------------------------------------------------------- */

double PairDPDFPM::single(int, int, int itype, int jtype, double rsq, double, double factor_lj,
                          double &fforce)
{
  fforce = 0.0;
  const etd::FpmCoefficients &c = coefficients(itype, jtype);
  if (rsq >= c.rcsq) return 0.0;
  const double r = std::sqrt(rsq);
  if (r < MIN_DISTANCE) return 0.0;
  fforce = factor_lj * c.a * (1.0 - r * c.inv_rc) / r;
  return etd::fpm_energy(c, r, factor_lj);
}

void *PairDPDFPM::extract(const char *name, int &dim)
{
  dim = 2;
  if (std::strcmp(name, "a0") == 0) return (void *) a0;
  if (std::strcmp(name, "gamma_c") == 0) return (void *) gamma_c;
  if (std::strcmp(name, "gamma_s") == 0) return (void *) gamma_s;
  if (std::strcmp(name, "s") == 0) return (void *) exponent_d;
  return nullptr;
}
