// ETD-DPD: compute dpd/split. The pair style accumulates the split during its force
// evaluation; this compute only reads it, so its values belong to the last force evaluation.
// Under fix etd scheme implicit the pair style computes only the conservative part; the
// dissipative and random parts then come from the fix, those of the friction step of the
// same timestep. With 'torque yes' (pair style dpd/fpm) the torque's dissipative and random
// parts follow as six more columns.
#include "compute_dpd_split.h"

#include "atom.h"
#include "dpd_style_lookup.h"
#include "error.h"
#include "fix.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;

static constexpr int FORCE_VALUES = 9;     // C, D, R of the force
static constexpr int TORQUE_VALUES = 6;    // D, R of the torque

ComputeDPDSplit::ComputeDPDSplit(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), dpd_style(nullptr), implicit(nullptr), implicit_id(nullptr),
    nvalues(FORCE_VALUES), nmax(0), per_atom(nullptr)
{
  bool torque = false;
  for (int iarg = 3; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (key != "torque")
      error->all(FLERR, "Illegal compute dpd/split command: unknown keyword {} (expected torque)",
                 key);
    if (iarg + 2 > narg)
      error->all(FLERR, "Illegal compute dpd/split command: keyword torque needs yes or no");
    const std::string value = arg[iarg + 1];
    if (value == "yes")
      torque = true;
    else if (value == "no")
      torque = false;
    else
      error->all(FLERR, "Illegal compute dpd/split command: torque must be yes or no, got {}",
                 value);
  }
  if (torque) nvalues = FORCE_VALUES + TORQUE_VALUES;
  vector_flag = 1;
  size_vector = nvalues;
  extvector = 1;
  peratom_flag = 1;
  size_peratom_cols = nvalues;
  vector = new double[nvalues];
  // the pair style fills the split every force evaluation once requested
  timeflag = 0;
}

ComputeDPDSplit::~ComputeDPDSplit()
{
  delete[] vector;
  memory->destroy(per_atom);
}

void ComputeDPDSplit::init()
{
  auto dpd_styles = etd::find_dpd_pair_styles(lmp);
  if (dpd_styles.empty())
    error->all(FLERR,
               "Compute dpd/split requires pair style dpd/gen or dpd/fpm (alone or in hybrid)");
  if (dpd_styles.size() > 1)
    error->all(FLERR, "Compute dpd/split supports one dpd/gen or dpd/fpm sub-style, found {}",
               dpd_styles.size());
  dpd_style = dpd_styles.front();
  if (nvalues > dpd_style->force_split_columns())
    error->all(FLERR,
               "Compute dpd/split torque yes requires pair style dpd/fpm (the pair style in use "
               "makes no torque)");
  dpd_style->request_force_split();
  implicit = nullptr;
  for (int i = 0; i < modify->nfix; i++)
    if (auto *integrator = dynamic_cast<etd::DpdFrictionIntegrator *>(modify->fix[i])) {
      if (implicit)
        error->all(FLERR, "Compute dpd/split supports one fix etd scheme implicit, found {} and {}",
                   implicit_id, modify->fix[i]->id);
      implicit = integrator;
      implicit_id = modify->fix[i]->id;
    }
  if (implicit && nvalues > FORCE_VALUES)
    error->all(FLERR,
               "Compute dpd/split torque yes is not supported with fix etd scheme implicit "
               "(fix {}), which applies the torques itself",
               implicit_id);
  if (implicit) implicit->request_split();
}

void ComputeDPDSplit::copy_split()
{
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(per_atom);
    memory->create(per_atom, nmax, nvalues, "dpd/split:per_atom");
    array_atom = per_atom;
  }
  double **split = dpd_style->force_split();
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < nvalues; k++)
      per_atom[i][k] = (split && (mask[i] & groupbit)) ? split[i][k] : 0.0;
  if (implicit) {    // the pair style's D and R columns are zero: the fix applied them
    double **dr = implicit->dissipative_random_split();
    for (int i = 0; i < nlocal; i++)
      if (mask[i] & groupbit)
        for (int k = 0; k < 6; k++) per_atom[i][3 + k] = dr[i][k];
  }
}

void ComputeDPDSplit::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  copy_split();
}

void ComputeDPDSplit::compute_vector()
{
  invoked_vector = update->ntimestep;
  copy_split();
  double local[FORCE_VALUES + TORQUE_VALUES] = {0.0};
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < nvalues; k++) local[k] += per_atom[i][k];
  MPI_Allreduce(local, vector, nvalues, MPI_DOUBLE, MPI_SUM, world);
}

double ComputeDPDSplit::memory_usage()
{
  return static_cast<double>(nmax) * nvalues * sizeof(double);
}
