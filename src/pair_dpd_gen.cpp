// ETD-DPD: pair_style dpd/gen. Thin LAMMPS adapter over dpd_kernel.h and dpd_random.h.
#include "pair_dpd_gen.h"

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
constexpr int NCOEFF = 6;    // a, gamma, s, exp_c, cutoff, cut_d (then the cut_d flag)

bool is_keyword(const char *word)
{
  return std::strcmp(word, "cut_d") == 0 || std::strcmp(word, "exp_c") == 0;
}
}    // namespace

PairDPDGen::PairDPDGen(LAMMPS *lmp) :
    PairDPDBase(lmp, "dpd/gen", false), a0(nullptr), gamma(nullptr), exponent_d(nullptr),
    exponent_c(nullptr), cut_d(nullptr), cut_d_set(nullptr), stride(0)
{
}

PairDPDGen::~PairDPDGen()
{
  if (copymode) return;
  if (allocated) {
    memory->destroy(a0);
    memory->destroy(gamma);
    memory->destroy(exponent_d);
    memory->destroy(exponent_c);
    memory->destroy(cut_d);
    memory->destroy(cut_d_set);
  }
}

void PairDPDGen::allocate()
{
  allocate_base();
  const int n = atom->ntypes;
  memory->create(a0, n + 1, n + 1, "pair:a0");
  memory->create(gamma, n + 1, n + 1, "pair:gamma");
  memory->create(exponent_d, n + 1, n + 1, "pair:exponent_d");
  memory->create(exponent_c, n + 1, n + 1, "pair:exponent_c");
  memory->create(cut_d, n + 1, n + 1, "pair:cut_d");
  memory->create(cut_d_set, n + 1, n + 1, "pair:cut_d_set");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) {
      cut_d_set[i][j] = 0;
      a0[i][j] = gamma[i][j] = 0.0;
      exponent_d[i][j] = 2.0;
      exponent_c[i][j] = 1.0;
      cut_d[i][j] = 0.0;
    }
  stride = n + 1;
  coeffs.assign(static_cast<size_t>(stride) * stride, etd::PairCoefficients());
}

/* ----------------------------------------------------------------------
   pair_coeff I J a gamma s [cutoff] [cut_d rcD] [exp_c p]
------------------------------------------------------------------------- */

void PairDPDGen::coeff(int narg, char **arg)
{
  if (narg < 5)
    error->all(FLERR,
               "Incorrect args for pair_coeff dpd/gen: expected I J a gamma s [cutoff] "
               "[cut_d rcD] [exp_c p], got {} arguments",
               narg);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  const double a_one = utils::numeric(FLERR, arg[2], false, lmp);
  const double gamma_one = utils::numeric(FLERR, arg[3], false, lmp);
  const double s_one = utils::numeric(FLERR, arg[4], false, lmp);
  if (gamma_one < 0.0) error->all(FLERR, "pair_coeff dpd/gen: gamma must be >= 0, got {}", arg[3]);
  if (s_one <= 0.0)
    error->all(FLERR, "pair_coeff dpd/gen: dissipative exponent s must be > 0, got {}", arg[4]);

  double cut_one = cut_global;
  double cut_d_one = -1.0;
  double p_one = 1.0;
  int iarg = 5;
  if (iarg < narg && !is_keyword(arg[iarg])) {
    cut_one = utils::numeric(FLERR, arg[iarg], false, lmp);
    if (cut_one <= 0.0)
      error->all(FLERR, "pair_coeff dpd/gen: cutoff must be > 0, got {}", arg[iarg]);
    iarg++;
  }
  while (iarg < narg) {
    if (std::strcmp(arg[iarg], "cut_d") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "pair_coeff dpd/gen: keyword cut_d needs a value");
      cut_d_one = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (cut_d_one <= 0.0)
        error->all(FLERR, "pair_coeff dpd/gen: cut_d must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (std::strcmp(arg[iarg], "exp_c") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "pair_coeff dpd/gen: keyword exp_c needs a value");
      p_one = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (p_one <= 0.0)
        error->all(FLERR, "pair_coeff dpd/gen: conservative exponent exp_c must be > 0, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else {
      error->all(FLERR, "pair_coeff dpd/gen: unknown keyword or extra argument '{}'", arg[iarg]);
    }
  }

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      a0[i][j] = a_one;
      gamma[i][j] = gamma_one;
      exponent_d[i][j] = s_one;
      exponent_c[i][j] = p_one;
      cut[i][j] = cut_one;
      cut_d_set[i][j] = cut_d_one > 0.0 ? 1 : 0;
      cut_d[i][j] = cut_d_one > 0.0 ? cut_d_one : cut_one;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0)
    error->all(FLERR, "pair_coeff dpd/gen: no type pairs selected by {} {}", arg[0], arg[1]);
}

/* ---------------------------------------------------------------------- */

const etd::PairCoefficients *PairDPDGen::dpd_coefficients(int i, int j)
{
  return type_pair_set(i, j) ? &coeffs[i * stride + j] : nullptr;
}

double PairDPDGen::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "Pair style dpd/gen: pair coefficients for types {} {} are not set", i, j);

  const double rc_d = cut_d_set[i][j] ? cut_d[i][j] : cut[i][j];
  cut_d[i][j] = rc_d;
  const double kT = force->boltz * temperature;
  etd::PairCoefficients c;
  c.set(a0[i][j], gamma[i][j], exponent_d[i][j], exponent_c[i][j], cut[i][j], rc_d, kT);
  coeffs[i * stride + j] = c;
  coeffs[j * stride + i] = c;

  a0[j][i] = a0[i][j];
  gamma[j][i] = gamma[i][j];
  exponent_d[j][i] = exponent_d[i][j];
  exponent_c[j][i] = exponent_c[i][j];
  cut[j][i] = cut[i][j];
  cut_d[j][i] = cut_d[i][j];
  cut_d_set[j][i] = cut_d_set[i][j];
  return MAX(cut[i][j], rc_d);
}

/* ---------------------------------------------------------------------- */

void PairDPDGen::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const bool extras = prepare_extras();

  // the extras are template flags so that the plain force loop carries none of their work
  if (conservative_only) {
    if (evflag) {
      if (want_split)
        eval<1, 0, 1, 0>();
      else
        eval<1, 0, 0, 0>();
    } else {
      if (want_split)
        eval<0, 0, 1, 0>();
      else
        eval<0, 0, 0, 0>();
    }
  } else if (evflag) {
    if (want_split)
      eval<1, 1, 1, 1>();
    else if (want_friction)
      eval<1, 1, 0, 1>();
    else
      eval<1, 0, 0, 1>();
  } else {
    if (want_split)
      eval<0, 1, 1, 1>();
    else if (want_friction)
      eval<0, 1, 0, 1>();
    else
      eval<0, 0, 0, 1>();
  }

  finish_extras(extras);
  if (vflag_fdotr) virial_fdotr_compute();
}

template <int EVFLAG, int FRICTION, int SPLIT, int DISSIPATIVE> void PairDPDGen::eval()
{
  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  if (list->inum == 0) return;    // (x may be unallocated on a rank without atoms)
  // LAMMPS stores x, v and f contiguously: atom j's row is at 3 j (one load, not two)
  const double *xflat = x[0];
  const double *vflat = v[0];
  double *fflat = f[0];
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

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2];
    const double vxi = v[i][0], vyi = v[i][1], vzi = v[i][2];
    const int itype = type[i];
    const tagint tag_i = tag[i];
    const etd::PairCoefficients *crow = &coeffs[itype * stride];
    const double *cutsqi = cutsq[itype];
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    double fxi = 0.0, fyi = 0.0, fzi = 0.0;
    double gxi = 0.0, gyi = 0.0, gzi = 0.0;    // atom i's diagonal friction, kept in registers

    // the neighbours within the cutoff first (close_neighbors.h), then the work on those only
    const int nclose = etd::gather_close_neighbors(
        jlist, jnum, NEIGHMASK, xflat, xi, yi, zi,
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
      const double delx = xi - xj[0];
      const double dely = yi - xj[1];
      const double delz = zi - xj[2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const int jtype = type[j];
      const double r = std::sqrt(rsq);
      if (r < MIN_DISTANCE) continue;
      const double rinv = 1.0 / r;
      const etd::PairCoefficients &c = crow[jtype];

      const double e_dot_v = (delx * (vxi - vflat[3 * j]) + dely * (vyi - vflat[3 * j + 1]) +
                              delz * (vzi - vflat[3 * j + 2])) *
          rinv;
      const double theta = (DISSIPATIVE && rsq < c.rcsq_d) ? noise.gaussian(tag_i, tag[j], step)
                                                           : 0.0;
      etd::PairForce pf = etd::pair_force(c, rsq, r, e_dot_v, theta, inv_sqrt_dt, factor);
      if (!DISSIPATIVE) pf.dissipative = pf.random = pf.friction = 0.0;
      const double fpair = pf.total() * rinv;

      fxi += delx * fpair;
      fyi += dely * fpair;
      fzi += delz * fpair;
      const bool update_j = newton_pair || j < nlocal;
      if (update_j) {
        double *fj = fflat + 3 * j;
        fj[0] -= delx * fpair;
        fj[1] -= dely * fpair;
        fj[2] -= delz * fpair;
      }

      if (FRICTION || SPLIT) {
        const double ex = delx * rinv, ey = dely * rinv, ez = delz * rinv;
        if (FRICTION && want_friction) {
          const double friction_per_rsq = pf.friction * rinv * rinv;
          const double gx = friction_per_rsq * delx * delx, gy = friction_per_rsq * dely * dely,
                       gz = friction_per_rsq * delz * delz;
          gxi += gx;
          gyi += gy;
          gzi += gz;
          if (update_j) {
            friction[j][0] += gx;
            friction[j][1] += gy;
            friction[j][2] += gz;
          }
        }
        if (SPLIT) {
          const double parts[3] = {pf.conservative, pf.dissipative, pf.random};
          for (int k = 0; k < 3; k++) {
            split[i][3 * k + 0] += parts[k] * ex;
            split[i][3 * k + 1] += parts[k] * ey;
            split[i][3 * k + 2] += parts[k] * ez;
            if (update_j) {
              split[j][3 * k + 0] -= parts[k] * ex;
              split[j][3 * k + 1] -= parts[k] * ey;
              split[j][3 * k + 2] -= parts[k] * ez;
            }
          }
        }
      }

      if (EVFLAG) {
        const double evdwl = eflag_either ? etd::pair_energy(c, rsq, r, factor) : 0.0;
        ev_tally(i, j, nlocal, newton_pair, evdwl, 0.0, fpair, delx, dely, delz);
      }
    }
    f[i][0] += fxi;
    f[i][1] += fyi;
    f[i][2] += fzi;
    if (FRICTION && want_friction) {
      friction[i][0] += gxi;
      friction[i][1] += gyi;
      friction[i][2] += gzi;
    }
  }
}

/* ----------------------------------------------------------------------
   restart file: per set type pair the six values and the cut_d flag
------------------------------------------------------------------------- */

void PairDPDGen::write_type_pair(FILE *fp, int i, int j)
{
  const double values[NCOEFF] = {a0[i][j],         gamma[i][j], exponent_d[i][j],
                                 exponent_c[i][j], cut[i][j],   cut_d[i][j]};
  fwrite(values, sizeof(double), NCOEFF, fp);
  fwrite(&cut_d_set[i][j], sizeof(int), 1, fp);
}

void PairDPDGen::read_type_pair(FILE *fp, int i, int j)
{
  double values[NCOEFF];
  if (comm->me == 0) {
    utils::sfread(FLERR, values, sizeof(double), NCOEFF, fp, nullptr, error);
    utils::sfread(FLERR, &cut_d_set[i][j], sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(values, NCOEFF, MPI_DOUBLE, 0, world);
  MPI_Bcast(&cut_d_set[i][j], 1, MPI_INT, 0, world);
  a0[i][j] = values[0];
  gamma[i][j] = values[1];
  exponent_d[i][j] = values[2];
  exponent_c[i][j] = values[3];
  cut[i][j] = values[4];
  cut_d[i][j] = values[5];
}

void PairDPDGen::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    fprintf(fp, "%d %.15g %.15g %.15g %.15g cut_d %.15g exp_c %.15g\n", i, a0[i][i], gamma[i][i],
            exponent_d[i][i], cut[i][i], cut_d[i][i], exponent_c[i][i]);
}

void PairDPDGen::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      fprintf(fp, "%d %d %.15g %.15g %.15g %.15g cut_d %.15g exp_c %.15g\n", i, j, a0[i][j],
              gamma[i][j], exponent_d[i][j], cut[i][j], cut_d[i][j], exponent_c[i][j]);
}

/* ----------------------------------------------------------------------
   conservative part only, as stock pair dpd: the other parts depend on velocities and noise
------------------------------------------------------------------------- */

double PairDPDGen::single(int, int, int itype, int jtype, double rsq, double, double factor_lj,
                          double &fforce)
{
  fforce = 0.0;
  const etd::PairCoefficients &c = coefficients(itype, jtype);
  if (rsq >= c.rcsq_c) return 0.0;
  const double r = std::sqrt(rsq);
  if (r < MIN_DISTANCE) return 0.0;
  const double q = 1.0 - r * c.inv_rc_c;
  fforce = factor_lj * c.a * etd::power_of(q, c.conservative_kind, c.p) / r;
  return etd::pair_energy(c, rsq, r, factor_lj);
}

void *PairDPDGen::extract(const char *name, int &dim)
{
  dim = 2;
  if (std::strcmp(name, "a0") == 0) return (void *) a0;
  if (std::strcmp(name, "gamma") == 0) return (void *) gamma;
  if (std::strcmp(name, "s") == 0) return (void *) exponent_d;
  if (std::strcmp(name, "exp_c") == 0) return (void *) exponent_c;
  if (std::strcmp(name, "cut_d") == 0) return (void *) cut_d;
  return nullptr;
}
