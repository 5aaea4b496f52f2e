// ETD-DPD: the friction step's virial and force split (implicit_friction_tally.h).
#include "implicit_friction_tally.h"

#include <cmath>

namespace etd {

void tally_friction_virial(const FrictionPairAssembly &assembly, const double *u, int nlocal,
                           double dt, double virial[6], double **vatom)
{
  const int dofs = assembly.dofs();
  const double random_scale = 1.0 / std::sqrt(dt);
  for (int k = 0; k < 6; k++) virial[k] = 0.0;
  if (vatom)
    for (int i = 0; i < nlocal; i++)
      for (int k = 0; k < 6; k++) vatom[i][k] = 0.0;
  auto tally = [&](int i, int j, const double rij[3], const double f[3]) {
    const double w[6] = {rij[0] * f[0], rij[1] * f[1], rij[2] * f[2],
                         rij[0] * f[1], rij[0] * f[2], rij[1] * f[2]};
    const double share = (j < nlocal) ? 1.0 : 0.5;
    for (int k = 0; k < 6; k++) virial[k] += share * w[k];
    if (!vatom) return;
    for (int k = 0; k < 6; k++) vatom[i][k] += 0.5 * w[k];
    if (j < nlocal)
      for (int k = 0; k < 6; k++) vatom[j][k] += 0.5 * w[k];
  };
  const double no_offset[3] = {0.0, 0.0, 0.0};
  const std::vector<FrictionPair> &pairs = assembly.pairs();
  const std::vector<double> &pair_offset = assembly.pair_offset();
  for (size_t n = 0; n < pairs.size(); n++) {
    const FrictionPair &p = pairs[n];
    const double *offset = pair_offset.empty() ? no_offset : &pair_offset[3 * n];
    const double *uj = &u[dofs * p.j];
    const double moving_j[3] = {uj[0] + offset[0], uj[1] + offset[1], uj[2] + offset[2]};
    const double along =
        -pair_friction(p, &u[dofs * p.i], moving_j) + random_scale * assembly.pair_noise()[n];
    const double r = assembly.pair_distance()[n];
    const double rij[3] = {r * p.e[0], r * p.e[1], r * p.e[2]};
    const double f[3] = {along * p.e[0], along * p.e[1], along * p.e[2]};
    tally(p.i, p.j, rij, f);
  }
  const std::vector<FpmFrictionPair> &fpm_pairs = assembly.fpm_pairs();
  const std::vector<double> &fpm_offset = assembly.fpm_offset();
  for (size_t n = 0; n < fpm_pairs.size(); n++) {
    const FpmFrictionPair &p = fpm_pairs[n];
    const double *offset = fpm_offset.empty() ? no_offset : &fpm_offset[3 * n];
    const double *qj = &u[6 * p.j];
    const double moving_j[6] = {
        qj[0] + offset[0], qj[1] + offset[1], qj[2] + offset[2], qj[3], qj[4], qj[5]};
    double friction[3];
    fpm_pair_friction(p, &u[6 * p.i], moving_j, 1.0, friction);
    const double r = 2.0 * p.half_r;
    const double rij[3] = {r * p.e[0], r * p.e[1], r * p.e[2]};
    double f[3];
    for (int k = 0; k < 3; k++)
      f[k] = -friction[k] + random_scale * assembly.fpm_noise()[3 * n + k];
    tally(p.i, p.j, rij, f);
  }
}

void record_friction_split(const FrictionPairAssembly &assembly, const double *u, int nlocal,
                           const std::vector<double> &random_force, double random_scale,
                           std::vector<double> &gu, double **split)
{
  const int dofs = assembly.dofs();
  const std::vector<double> &image_friction = assembly.image_friction();
  gu.assign(dofs * nlocal, 0.0);
  assembly.accumulate_friction(u, gu.data(), nlocal);
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < 3; k++) {
      split[i][k] =
          -gu[dofs * i + k] - (image_friction.empty() ? 0.0 : image_friction[dofs * i + k]);
      split[i][3 + k] = random_scale * random_force[dofs * i + k];
    }
}

}    // namespace etd
