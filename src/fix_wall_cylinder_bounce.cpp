// ETD-DPD: fix wall/cylinder/bounce. After the position update (post_integrate, where the
// stock wall/reflect fixes act), every atom of the group that ended on the wall side of the
// cylinder surface is sent back along its path with its velocity reversed (bounce-back);
// the geometry is etd::cylinder_bounce in wall_geometry.h.
#include "fix_wall_cylinder_bounce.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "update.h"
#include "utils.h"
#include "wall_geometry.h"

#include <cmath>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

FixWallCylinderBounce::FixWallCylinderBounce(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), axis(2), radius(0.0), fluid_inside(true), dt(0.0), bounces_local(0.0),
    projections_local(0.0)
{
  // fix ID group wall/cylinder/bounce dim c1 c2 radius [side in|out]
  if (narg < 7)
    error->all(FLERR,
               "Illegal fix wall/cylinder/bounce command: expected dim c1 c2 radius "
               "[side in|out]");
  const std::string dim = arg[3];
  if (dim == "x")
    axis = 0;
  else if (dim == "y")
    axis = 1;
  else if (dim == "z")
    axis = 2;
  else
    error->all(FLERR, "Illegal fix wall/cylinder/bounce command: dim must be x, y or z, got {}",
               dim);
  centre[0] = centre[1] = centre[2] = 0.0;
  // c1 c2 are the two other coordinates in cyclic order, as for region cylinder: (y z) for an
  // x axis, (x z) for y, (x y) for z
  const int first = (axis == 0) ? 1 : 0;
  const int second = (axis == 2) ? 1 : 2;
  centre[first] = utils::numeric(FLERR, arg[4], false, lmp);
  centre[second] = utils::numeric(FLERR, arg[5], false, lmp);
  radius = utils::numeric(FLERR, arg[6], false, lmp);
  if (!(radius > 0.0))
    error->all(FLERR, "Illegal fix wall/cylinder/bounce command: radius must be > 0, got {}",
               arg[6]);

  int iarg = 7;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "side") {
      if (iarg + 2 > narg)
        error->all(FLERR, "Illegal fix wall/cylinder/bounce command: side needs in or out");
      const std::string value = arg[iarg + 1];
      if (value == "in")
        fluid_inside = true;
      else if (value == "out")
        fluid_inside = false;
      else
        error->all(FLERR,
                   "Illegal fix wall/cylinder/bounce command: side must be in or out, got {}",
                   value);
      iarg += 2;
    } else {
      error->all(FLERR, "Illegal fix wall/cylinder/bounce command: unknown keyword {}", key);
    }
  }

  vector_flag = 1;
  size_vector = 2;
  global_freq = 1;
  extvector = 1;
}

int FixWallCylinderBounce::setmask()
{
  return POST_INTEGRATE;
}

void FixWallCylinderBounce::init()
{
  dt = update->dt;
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix wall/cylinder/bounce does not support run_style respa");
  // a periodic cross-section smaller than the cylinder would wrap the surface onto itself
  const int first = (axis == 0) ? 1 : 0;
  const int second = (axis == 2) ? 1 : 2;
  for (int k : {first, second})
    if (domain->periodicity[k] && domain->prd[k] < 2.0 * radius)
      error->all(FLERR,
                 "Fix wall/cylinder/bounce: the cylinder (diameter {}) does not fit in "
                 "the periodic box length {} across it",
                 2.0 * radius, domain->prd[k]);
}

void FixWallCylinderBounce::post_integrate()
{
  double **x = atom->x;
  double **v = atom->v;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double rel[3];
    for (int k = 0; k < 3; k++) {
      if (k == axis) {
        rel[k] = 0.0;
        continue;
      }
      rel[k] = x[i][k] - centre[k];
      if (domain->periodicity[k]) rel[k] -= domain->prd[k] * std::round(rel[k] / domain->prd[k]);
    }
    const etd::CylinderBounce b = etd::cylinder_bounce(rel, v[i], dt, axis, radius, fluid_inside);
    if (!b.crossed) continue;
    for (int k = 0; k < 3; k++) {
      x[i][k] += b.x[k] - rel[k];
      v[i][k] = b.v[k];
    }
    bounces_local += 1.0;
    if (b.projected) projections_local += 1.0;
  }
}

// 0: atoms bounced since the fix was defined; 1: of those, put back along the radius
double FixWallCylinderBounce::compute_vector(int n)
{
  double local = (n == 0) ? bounces_local : projections_local, total = 0.0;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  return total;
}
