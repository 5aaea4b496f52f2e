#!/usr/bin/env bash
# The device tool's call of tools/kokkos/gpu.sh, rehearsed on this machine without a GPU: what
# travels (the tracked and untracked files that git does not ignore, and the packed files of
# build-gpu-sources) is copied to a scratch checkout, and gpu.sh runs there in a mount namespace
# that hides the folder above the packing checkout (prebuilt.root) and the LAMMPS cache, as on a
# fresh device machine. It checks what comes before the GPU: the link to the packing folder, the
# unpacked build, the packed lmp running, the tests and runs started, the files copied to $OUT.
# Without a GPU driver, the toolkit's stub stands in for libcuda.so.1, so every test and run then
# stops at Kokkos's CUDA initialisation ("CUDA driver is a stub library"); that is the expected
# end.
# Usage: tools/kokkos/rehearse_device.sh [SCRATCH]     (default /tmp/etd-dpd-device; needs root
#        for unshare, and a pack: gpu.sh --phases build,pack)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
scratch=${1:-/tmp/etd-dpd-device}
cache=${ETD_DPD_CACHE:-$HOME/.cache/etd-dpd}
die() { printf '[etd-dpd] ERROR: %s\n' "$*" >&2; exit 1; }
packed=(kokkos.tar.xz lammps.tar.xz deps.tar.xz openmpi.tar.xz prebuilt.tar.xz prebuilt.root)
for f in "${packed[@]}"; do
  [ -f "$root/build-gpu-sources/$f" ] || die "no build-gpu-sources/$f: pack_sources.sh, then gpu.sh --phases build,pack"
done
# the stub that the build linked against (build_lammps_kokkos.sh, on a machine without a driver)
packed_prefix=$(sed -n 's/^prebuilt_prefix=//p' "$root/build-kokkos-cuda/.prebuilt" 2>/dev/null || true)
stub=$(readlink -f "$packed_prefix/cuda-stubs/libcuda.so.1" 2>/dev/null || true)
[ -f "$stub" ] || die "no $packed_prefix/cuda-stubs/libcuda.so.1: the rehearsal is for the machine without a GPU driver that made the pack"
rm -rf "$scratch"
mkdir -p "$scratch/repo/build-gpu-sources" "$scratch/bin" "$scratch/stub" "$scratch/out"
(cd "$root" && git ls-files -co --exclude-standard -z | tar -cf - --null -T -) | tar -C "$scratch/repo" -xf -
for f in "${packed[@]}"; do cp "$root/build-gpu-sources/$f" "$scratch/repo/build-gpu-sources/"; done
printf 'what travels: %s\n' "$(du -sh "$scratch/repo" | cut -f1)"
ln -s "$stub" "$scratch/stub/libcuda.so.1"
printf '#!/bin/sh\necho "GPU 0: none (rehearsal)"\n' >"$scratch/bin/nvidia-smi"
chmod +x "$scratch/bin/nvidia-smi"
mkdir -p "$cache"
packed_parent=$(dirname "$(cat "$root/build-gpu-sources/prebuilt.root")")
case "$scratch/" in "$packed_parent"/*) die "SCRATCH must lie outside $packed_parent, which the rehearsal hides" ;; esac
unshare -m --propagation private bash -c '
  scratch=$1 cache=$2 packed_parent=$3
  mount -t tmpfs none "$packed_parent"
  mount -t tmpfs none "$cache"
  export PATH=$scratch/bin:$PATH OUT=$scratch/out LD_LIBRARY_PATH=$scratch/stub
  cd "$scratch/repo"
  u=$(( $(date +%s) + 520 ))    # as the device call
  tools/kokkos/gpu.sh --phases bench --sizes 4000 --cases gen-nve,etd-implicit --steps 10 --timeout 5 --warmup 10 \
    --until $((u - 200)) || echo "bench phase: exit $?"
  ETD_DPD_GPU_TEST_TIMEOUT=60 tools/kokkos/gpu.sh --phases test --until $u || echo "test phase: exit $?"
' rehearsal "$scratch" "$cache" "$packed_parent" 2>&1
echo "back in \$OUT:"; ls -l "$scratch/out"
mkdir -p "$scratch/logs" && tar -C "$scratch/logs" -xzf "$scratch/out/logs.tar.gz"
grep -h -m1 "CUDA driver is a stub library" "$scratch/logs"/*.out "$scratch/logs/test.log" 2>/dev/null | head -2 \
  && echo "REHEARSAL REACHED THE GPU" || { echo "REHEARSAL STOPPED BEFORE THE GPU"; exit 1; }
