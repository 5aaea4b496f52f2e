// ETD-DPD: fix wall/thermal/layer. At the end of every step each atom of the group within a
// layer of given thickness next to a wall plane gets a new velocity: the wall velocity plus a
// Gaussian of variance kT/m per component (Fan et al.'s no-slip layer). The Gaussians come from
// the package's counter-based generator keyed on (seed, atom ID, timestep, face), so the result
// does not depend on the number of ranks.
#include "fix_wall_thermal_layer.h"

#include "atom.h"
#include "dpd_random.h"
#include "error.h"
#include "force.h"
#include "update.h"
#include "utils.h"
#include "wall_geometry.h"

#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

FixWallThermalLayer::FixWallThermalLayer(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), seed(0), redrawn_last(0.0), energy_change(0.0)
{
  // fix ID group wall/thermal/layer seed face position thickness kT vx vy vz [face ...]
  if (narg < 11)
    error->all(FLERR,
               "Illegal fix wall/thermal/layer command: expected seed and at least one "
               "face position thickness kT vx vy vz");
  const long long s = utils::inumeric(FLERR, arg[3], false, lmp);
  if (s <= 0)
    error->all(FLERR, "Illegal fix wall/thermal/layer command: seed must be > 0, got {}", arg[3]);
  seed = static_cast<std::uint64_t>(s);

  int iarg = 4;
  while (iarg < narg) {
    const std::string name = arg[iarg];
    Face face;
    if (name.size() != 3 || (name[0] != 'x' && name[0] != 'y' && name[0] != 'z') ||
        (name.substr(1) != "lo" && name.substr(1) != "hi"))
      error->all(FLERR,
                 "Illegal fix wall/thermal/layer command: unknown face {} (xlo, xhi, ylo, "
                 "yhi, zlo or zhi)",
                 name);
    face.dim = name[0] - 'x';
    face.lower = name.substr(1) == "lo";
    if (iarg + 7 > narg)
      error->all(FLERR,
                 "Illegal fix wall/thermal/layer command: face {} needs position thickness "
                 "kT vx vy vz",
                 name);
    face.position = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    face.thickness = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
    face.kT = utils::numeric(FLERR, arg[iarg + 3], false, lmp);
    for (int k = 0; k < 3; k++)
      face.velocity[k] = utils::numeric(FLERR, arg[iarg + 4 + k], false, lmp);
    if (!(face.thickness > 0.0))
      error->all(FLERR,
                 "Illegal fix wall/thermal/layer command: thickness of face {} must be > 0, "
                 "got {}",
                 name, arg[iarg + 2]);
    if (!(face.kT >= 0.0))
      error->all(FLERR,
                 "Illegal fix wall/thermal/layer command: kT of face {} must be >= 0, got {}", name,
                 arg[iarg + 3]);
    if (face.velocity[face.dim] != 0.0)
      error->all(FLERR,
                 "Illegal fix wall/thermal/layer command: the velocity of face {} must lie "
                 "in the wall plane ({} component 0)",
                 name, name.substr(0, 1));
    for (const Face &other : faces)
      if (other.dim == face.dim && other.lower == face.lower)
        error->all(FLERR, "Illegal fix wall/thermal/layer command: face {} given twice", name);
    faces.push_back(face);
    iarg += 7;
  }

  vector_flag = 1;
  size_vector = 2;
  global_freq = 1;
  extvector = 1;
  nevery = 1;
}

int FixWallThermalLayer::setmask()
{
  return END_OF_STEP;
}

void FixWallThermalLayer::init()
{
  if (!atom->tag_enable)
    error->all(FLERR,
               "Fix wall/thermal/layer requires atom IDs (its random numbers are keyed on them)");
}

void FixWallThermalLayer::end_of_step()
{
  double **x = atom->x;
  double **v = atom->v;
  const int *mask = atom->mask;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const double *rmass = atom->rmass;
  const double *mass = atom->mass;
  const int nlocal = atom->nlocal;
  const double boltz = force->boltz, mvv2e = force->mvv2e;
  const etd::PairNoise noise(seed, etd::NoiseStream::WallLayer);
  const std::int64_t step = update->ntimestep;

  double local[2] = {0.0, 0.0};    // atoms redrawn, kinetic energy change
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double m = rmass ? rmass[i] : mass[type[i]];
    for (size_t f = 0; f < faces.size(); f++) {
      const Face &face = faces[f];
      if (!etd::in_wall_layer(x[i][face.dim], face.position, face.thickness, face.lower)) continue;
      double g[4];
      noise.gaussians4(tag[i], tag[i], step, f, g);
      double before = 0.0, after = 0.0;
      for (int k = 0; k < 3; k++) {
        before += v[i][k] * v[i][k];
        v[i][k] = etd::wall_maxwellian(face.velocity[k], boltz * face.kT / mvv2e, m, g[k]);
        after += v[i][k] * v[i][k];
      }
      local[0] += 1.0;
      local[1] += 0.5 * m * mvv2e * (after - before);
    }
  }
  double total[2];
  MPI_Allreduce(local, total, 2, MPI_DOUBLE, MPI_SUM, world);
  redrawn_last = total[0];
  energy_change += total[1];
}

// 0: atoms redrawn in the last step; 1: kinetic energy the redraws added since the fix was
// defined (negative: heat taken out of the fluid by the walls)
double FixWallThermalLayer::compute_vector(int n)
{
  return n == 0 ? redrawn_last : energy_change;
}
