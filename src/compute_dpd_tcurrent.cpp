// ETD-DPD: compute dpd/tcurrent. Per-atom work is in transverse_current.h; this adapter loops
// over the group and sums over ranks.
#include "compute_dpd_tcurrent.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "transverse_current.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cstdlib>

using namespace LAMMPS_NS;

ComputeDPDTCurrent::ComputeDPDTCurrent(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nwave(0)
{
  if (narg != 4)
    error->all(FLERR,
               "Illegal compute dpd/tcurrent command: expected 'compute ID group "
               "dpd/tcurrent K', got {} arguments after the style",
               narg - 3);
  const std::string text = arg[3];
  if (!utils::is_integer(text))
    error->all(FLERR,
               "Compute dpd/tcurrent: K (number of wave numbers per axis) must be a "
               "positive integer, got '{}'",
               text);
  const long value = std::strtol(text.c_str(), nullptr, 10);
  if (value < 1 || value > 100000)
    error->all(FLERR,
               "Compute dpd/tcurrent: K (number of wave numbers per axis) must be "
               "between 1 and 100000, got {}",
               text);
  nwave = static_cast<int>(value);

  vector_flag = 1;
  size_vector = 12 * nwave;
  extvector = 1;    // sums over atoms
  vector = new double[size_vector];
  local.assign(size_vector, 0.0);
}

ComputeDPDTCurrent::~ComputeDPDTCurrent()
{
  delete[] vector;
}

void ComputeDPDTCurrent::init()
{
  if (domain->dimension != 3) error->all(FLERR, "Compute dpd/tcurrent requires a 3d system");
  if (domain->triclinic)
    error->all(FLERR, "Compute dpd/tcurrent requires an orthogonal box (k along the box axes)");
  if (!domain->xperiodic || !domain->yperiodic || !domain->zperiodic)
    error->all(FLERR,
               "Compute dpd/tcurrent requires a box periodic in x, y and z "
               "(k = 2 pi j / L is a wave vector of the periodic box only)");
}

void ComputeDPDTCurrent::compute_vector()
{
  invoked_vector = update->ntimestep;
  std::fill(local.begin(), local.end(), 0.0);
  double **x = atom->x;
  double **v = atom->v;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double *boxlo = domain->boxlo;
  // the box lengths are read now: a deforming box changes k
  const double prd[3] = {domain->xprd, domain->yprd, domain->zprd};
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double rel[3] = {x[i][0] - boxlo[0], x[i][1] - boxlo[1], x[i][2] - boxlo[2]};
    etd::add_transverse_current(rel, v[i], prd, nwave, local.data());
  }
  MPI_Allreduce(local.data(), vector, size_vector, MPI_DOUBLE, MPI_SUM, world);
}
