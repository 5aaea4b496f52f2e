// The package's pair law and noise (src/kernels) on a GPU against the same code on the host:
// random pairs of the standard fluid and of an s = 1/2 fluid with a separate dissipative
// cutoff, their forces (conservative, friction, noise) evaluated by a CUDA kernel and by the
// CPU, and compared. The noise must be the same draw on both (normal_ziggurat.h), so the forces
// agree to round-off; a different draw would show as a difference of order one.
// Built and run by tools/kokkos/cuda_check.sh; exits 0 when every pair agrees.
#include "pair_law.h"

#include <cuda_runtime.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

struct Pair {
  double del[3], vi[3], vj[3];
  std::int64_t tag_i, tag_j;
};

ETD_HOST_DEVICE void pair_force(const etd::PairCoefficients &c, const etd::PairNoise &noise,
                                std::int64_t timestep, const Pair &p, double out[3])
{
  etd::PairGeometry g;
  for (int k = 0; k < 3; k++) g.del[k] = p.del[k];
  g.rsq = g.del[0] * g.del[0] + g.del[1] * g.del[1] + g.del[2] * g.del[2];
  g.r = std::sqrt(g.rsq);
  g.rinv = 1.0 / g.r;
  g.special = 1.0;
  const etd::PairStep step{noise, timestep, 10.0};
  etd::DpdGenLaw law(c, g);
  law.evaluate<true>({p.vi, p.vj, nullptr, nullptr, p.tag_i, p.tag_j}, step);
  for (int k = 0; k < 3; k++) out[k] = law.force[k];
}

__global__ void pair_forces(etd::PairCoefficients c, etd::PairNoise noise, std::int64_t timestep,
                            const Pair *pairs, int n, double *forces)
{
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) pair_force(c, noise, timestep, pairs[i], forces + 3 * i);
}

bool check(const char *name, const etd::PairCoefficients &c, int n)
{
  std::mt19937_64 words(4711);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Pair> pairs(n);
  for (int i = 0; i < n; i++) {
    Pair &p = pairs[i];
    double r2;
    do {
      for (int k = 0; k < 3; k++) p.del[k] = unit(words);
      r2 = p.del[0] * p.del[0] + p.del[1] * p.del[1] + p.del[2] * p.del[2];
    } while (r2 >= c.rcsq_c || r2 < 1e-6);
    for (int k = 0; k < 3; k++) {
      p.vi[k] = 3 * unit(words);
      p.vj[k] = 3 * unit(words);
    }
    p.tag_i = 1 + i;
    p.tag_j = 1 + (i * 7919) % 100003 + n;
  }
  const std::int64_t timestep = 123456;
  etd::PairNoise noise(20261127);
  std::vector<double> host(3 * n), device(3 * n);
  for (int i = 0; i < n; i++) pair_force(c, noise, timestep, pairs[i], &host[3 * i]);

  // the ziggurat's tables in device memory
  const etd::ZigguratTables t = etd::ZigguratTables::host();
  const int N = etd::ZigguratTables::NORMAL_SIZE, E = etd::ZigguratTables::EXPONENTIAL_SIZE;
  double *tables;
  cudaMalloc(&tables, sizeof(double) * (2 * N + 2 * E));
  cudaMemcpy(tables, t.normal_x, sizeof(double) * N, cudaMemcpyHostToDevice);
  cudaMemcpy(tables + N, t.normal_y, sizeof(double) * N, cudaMemcpyHostToDevice);
  cudaMemcpy(tables + 2 * N, t.exponential_x, sizeof(double) * E, cudaMemcpyHostToDevice);
  cudaMemcpy(tables + 2 * N + E, t.exponential_y, sizeof(double) * E, cudaMemcpyHostToDevice);
  etd::PairNoise device_noise = noise;
  device_noise.use_tables({tables, tables + N, tables + 2 * N, tables + 2 * N + E});

  Pair *d_pairs;
  double *d_forces;
  cudaMalloc(&d_pairs, sizeof(Pair) * n);
  cudaMalloc(&d_forces, sizeof(double) * 3 * n);
  cudaMemcpy(d_pairs, pairs.data(), sizeof(Pair) * n, cudaMemcpyHostToDevice);
  pair_forces<<<(n + 127) / 128, 128>>>(c, device_noise, timestep, d_pairs, n, d_forces);
  const cudaError_t status = cudaMemcpy(device.data(), d_forces, sizeof(double) * 3 * n,
                                        cudaMemcpyDeviceToHost);
  cudaFree(d_pairs);
  cudaFree(d_forces);
  cudaFree(tables);
  if (status != cudaSuccess) {
    std::printf("%s: CUDA error %s\n", name, cudaGetErrorString(status));
    return false;
  }
  double worst = 0.0, scale = 0.0;
  int differ = 0;
  for (int i = 0; i < 3 * n; i++) {
    scale = std::fmax(scale, std::fabs(host[i]));
    const double d = std::fabs(host[i] - device[i]);
    worst = std::fmax(worst, d);
    differ += d > 1e-12 * (1.0 + std::fabs(host[i]));
  }
  std::printf("%s: %d pairs, max |F_device - F_host| = %.3e (largest |F| %.3e), %d components "
              "beyond 1e-12\n",
              name, n, worst, scale, differ);
  return differ == 0;
}

}    // namespace

int main()
{
  etd::PairCoefficients standard, mixed;
  standard.set(25.0, 4.5, 2.0, 1.0, 1.0, 1.0, 1.0);
  mixed.set(25.0, 4.5, 0.5, 0.5, 1.0, 0.9, 1.0);
  const bool ok = check("dpd/gen s = 2", standard, 1 << 20) &
      check("dpd/gen s = 1/2, cut_d 0.9, exp_c 0.5", mixed, 1 << 20);
  std::printf(ok ? "DEVICE LAW PASSED\n" : "DEVICE LAW FAILED\n");
  return ok ? 0 : 1;
}
