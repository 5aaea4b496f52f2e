#!/usr/bin/env bash
# The pair law and its noise (src/kernels) compiled for a GPU with nvcc and, where a GPU is
# present, run there against the same code on the host (tools/kokkos/cuda/pair_law_device.cu:
# 2 x 2^20 random pairs, forces within 1e-12, so the device draws the host's Gaussians).
#   tools/kokkos/cuda_check.sh [ARCH]       ARCH: nvcc's -arch (default sm_90, an H100)
# Environment: NVCC (default nvcc), ETD_DPD_CUDA_BUILD (default ./build-cuda).
# On a GPU machine without nvcc it runs the program compiled earlier into ETD_DPD_CUDA_BUILD
# (carry build-cuda there with the working tree).
# Exit status: 0 when it compiled and (on a GPU) passed; 2 when it compiled but no GPU could run
# it; 1 on a compile error or a failed comparison.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
arch=${1:-sm_90}
nvcc=${NVCC:-nvcc}
build=${ETD_DPD_CUDA_BUILD:-$here/build-cuda}
mkdir -p "$build"
if command -v "$nvcc" >/dev/null; then
  "$nvcc" --version | tail -1
  "$nvcc" -arch="$arch" -std=c++17 -O2 -Werror all-warnings -I "$here/src/kernels" \
    "$here/tools/kokkos/cuda/pair_law_device.cu" -o "$build/pair_law_device"
  echo "compiled for $arch: $build/pair_law_device"
elif [ -x "$build/pair_law_device" ]; then
  echo "no nvcc here: running the program compiled earlier, $build/pair_law_device"
else
  echo "no nvcc (set NVCC) and no program compiled earlier in $build" >&2
  exit 1
fi
if ! command -v nvidia-smi >/dev/null || ! nvidia-smi -L >/dev/null 2>&1; then
  echo "no GPU here: compiled, not run"
  exit 2
fi
nvidia-smi -L
"$build/pair_law_device"
