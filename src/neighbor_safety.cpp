// ETD-DPD: fix etd and LAMMPS's neighbor-list settings (neighbor_safety.h).
#include "neighbor_safety.h"

#include "lammps_compat.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <mpi.h>
#include <string>

using namespace LAMMPS_NS;

namespace etd {

void NeighborSafety::check_settings(LAMMPS *lmp, Fix *fix, bool inertial) const
{
  Neighbor *neighbor = lmp->neighbor;
  // every step: checked (check yes) or rebuilt (check no)
  if (neighbor->every == 1 && neighbor->delay == 0) return;
  const std::string settings =
      fmt::format("neigh_modify every {} delay {} check {}", neighbor->every, neighbor->delay,
                  neighbor->dist_check ? "yes" : "no");
  if (!inertial)
    lmp->error->all(FLERR,
                    "Fix {} with overdamped yes: {} leaves atoms unchecked between neighbor "
                    "list builds, and a zero-mass step has no speed to bound how far they go; use "
                    "neigh_modify every 1 delay 0 check yes",
                    fix->id, settings);
  double **v = lmp->atom->v;
  const int *mask = lmp->atom->mask;
  double local_max = 0.0, max_sq = 0.0;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if (mask[i] & fix->groupbit)
      local_max = std::max(local_max, v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
  MPI_Allreduce(&local_max, &max_sq, 1, MPI_DOUBLE, MPI_MAX, lmp->world);
  const double max_speed = std::sqrt(max_sq);
  const double dt = lmp->update->dt;
  if (settings_outrun_skin(neighbor->every, neighbor->delay, dt, max_speed, neighbor->skin))
    lmp->error->all(FLERR,
                    "Fix {}: {} lets atoms outrun the neighbor skin: the fastest atom moves "
                    "{:.3g} in the {} steps between checks at timestep {:.3g}, more than half the "
                    "skin ({:.3g}); use neigh_modify every 1 delay 0 check yes",
                    fix->id, settings,
                    unchecked_steps(neighbor->every, neighbor->delay) * dt * max_speed,
                    unchecked_steps(neighbor->every, neighbor->delay), dt, 0.5 * neighbor->skin);
}

void NeighborSafety::start_run(LAMMPS *lmp)
{
  danger_at_start = lmp->neighbor->ndanger;
  outruns = 0;
}

void NeighborSafety::record_build_positions(LAMMPS *lmp)
{
  const int nlocal = lmp->atom->nlocal;
  double **x = lmp->atom->x;
  build_positions.resize(3 * nlocal);
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < 3; k++) build_positions[3 * i + k] = x[i][k];
}

void NeighborSafety::largest_displacements(LAMMPS *lmp, int groupbit, double top[2],
                                           const std::vector<double> *lead) const
{
  top[0] = top[1] = 0.0;
  const int nlocal = lmp->atom->nlocal;
  if (static_cast<int>(build_positions.size()) != 3 * nlocal) return;
  double **x = lmp->atom->x;
  const int *mask = lmp->atom->mask;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double dsq = 0.0;
    for (int k = 0; k < 3; k++) {
      const double d = x[i][k] + (lead ? (*lead)[3 * i + k] : 0.0) - build_positions[3 * i + k];
      dsq += d * d;
    }
    keep_two_largest(top, std::sqrt(dsq));
  }
}

bool NeighborSafety::could_outrun(LAMMPS *lmp, int groupbit, const std::vector<double> &lead) const
{
  double local[3] = {0.0}, global[3];
  largest_displacements(lmp, groupbit, local + 1, &lead);
  reduce_with_flag(local, global, lmp->world);
  // the prediction uses the last force, not the coming one: a tenth of the skin is left for
  // the difference
  constexpr double predicted_share = 0.9;
  return global[1] + global[2] > predicted_share * lmp->neighbor->skin;
}

namespace {
  // MPI_Op over records of 3 doubles: {flag: max, two largest values}
  void flag_and_top_two(void *in, void *inout, int *len, MPI_Datatype *)
  {
    const double *a = static_cast<const double *>(in);
    double *b = static_cast<double *>(inout);
    for (int n = 0; n + 2 < *len; n += 3) {
      b[n] = std::max(a[n], b[n]);
      const double values[4] = {a[n + 1], a[n + 2], b[n + 1], b[n + 2]};
      double first = 0.0, second = 0.0;
      for (double v : values) {
        if (v > first) {
          second = first;
          first = v;
        } else if (v > second) {
          second = v;
        }
      }
      b[n + 1] = first;
      b[n + 2] = second;
    }
  }
}    // namespace

void NeighborSafety::reduce_with_flag(const double local[3], double global[3], MPI_Comm comm)
{
  static MPI_Op op = MPI_OP_NULL;
  if (op == MPI_OP_NULL) MPI_Op_create(flag_and_top_two, 1, &op);
  MPI_Allreduce(const_cast<double *>(local), global, 3, MPI_DOUBLE, op, comm);
}

void NeighborSafety::count_if_outrun(LAMMPS *lmp, const double top[2])
{
  if (top[0] + top[1] > lmp->neighbor->skin) outruns++;
}

long NeighborSafety::missed_pairs(LAMMPS *lmp, int groupbit, const double top[2],
                                  const std::function<double(int, int)> &cutoff_of, int max_checked)
{
  // the same on every rank: the early returns stay collective
  if (lmp->neighbor->exclude || lmp->atom->molecular) return -1;
  const int nlocal = lmp->atom->nlocal;
  int unrecorded = static_cast<int>(build_positions.size()) != 3 * nlocal, any_unrecorded = 0;
  MPI_Allreduce(&unrecorded, &any_unrecorded, 1, MPI_INT, MPI_MAX, lmp->world);
  if (any_unrecorded) return -1;
  constexpr int values = 7;    // per qualifying atom: position now, at the build, type
  const int *type = lmp->atom->type;
  const double threshold = lmp->neighbor->skin - top[0];
  double **x = lmp->atom->x;
  const int *mask = lmp->atom->mask;
  // per qualifying atom: its position now and where the list was built
  std::vector<double> mine;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double dsq = 0.0;
    for (int k = 0; k < 3; k++) {
      const double d = x[i][k] - build_positions[3 * i + k];
      dsq += d * d;
    }
    if (threshold > 0.0 && dsq <= threshold * threshold) continue;    // (else every atom counts)
    for (int k = 0; k < 3; k++) mine.push_back(x[i][k]);
    for (int k = 0; k < 3; k++) mine.push_back(build_positions[3 * i + k]);
    mine.push_back(type[i]);
  }
  const int nprocs = lmp->comm->nprocs;
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(nprocs), offsets(nprocs, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, lmp->world);
  long total = 0;
  for (int p = 0; p < nprocs; p++) {
    offsets[p] = static_cast<int>(total);
    total += counts[p];
  }
  if (total / values > max_checked) return -1;
  std::vector<double> all(total);
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                 MPI_DOUBLE, lmp->world);
  const double reach = lmp->neighbor->cutneighmax;
  long missed = 0;
  const long n = total / values;
  for (long a = 0; a < n; a++)
    for (long b = a + 1; b < n; b++) {
      const double *pa = &all[values * a], *pb = &all[values * b];
      const double cutoff = cutoff_of(static_cast<int>(pa[6]), static_cast<int>(pb[6]));
      if (cutoff <= 0.0) continue;
      double now[3] = {pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]};
      compat::minimum_image(lmp->domain, now);
      if (now[0] * now[0] + now[1] * now[1] + now[2] * now[2] >= cutoff * cutoff) continue;
      double then[3] = {pa[3] - pb[3], pa[4] - pb[4], pa[5] - pb[5]};
      compat::minimum_image(lmp->domain, then);
      if (then[0] * then[0] + then[1] * then[1] + then[2] * then[2] >= reach * reach) missed++;
    }
  return missed;
}

void NeighborSafety::end_run(LAMMPS *lmp, const char *fix_id) const
{
  const bigint dangerous = lmp->neighbor->ndanger - danger_at_start;
  if ((dangerous == 0 && outruns == 0) || lmp->comm->me != 0) return;
  Neighbor *neighbor = lmp->neighbor;
  const bool every_step = neighbor->every == 1 && neighbor->delay == 0;
  lmp->error->warning(
      FLERR,
      "Fix {}: {} dangerous neighbor list builds in this run, and {} friction "
      "steps at positions two atoms could have reached unlisted (their displacements "
      "since the list was built add up to more than the skin {}): pairs may have "
      "been missed. Use {}a larger skin (neighbor command) or a smaller timestep",
      fix_id, dangerous, outruns, neighbor->skin,
      every_step ? "" : "neigh_modify every 1 delay 0 check yes, ");
}

}    // namespace etd
