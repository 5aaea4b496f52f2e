#!/usr/bin/env bash
# The KOKKOS test leg against a real Kokkos 5: Debian sid's own binary Kokkos (libkokkos-dev,
# shared libraries, OpenMP backend) and LAMMPS 4Jul2026, inside a Debian sid root made with
# debootstrap. Debian's kokkos source tarball is not on the mirror, and sid's binaries need a
# newer C library than bookworm's, so they run in a sid root of their own.
# In that root: Debian's packages (the compiler, Open MPI, GoogleTest, ... and libkokkos-dev),
# then tools/kokkos/test.sh with ETD_DPD_KOKKOS_INSTALLED pointing at Debian's Kokkos: LAMMPS
# 4Jul2026 built with EXTERNAL_KOKKOS against it, the package built with its /kk styles, the
# default suite and the tests labelled kokkos.
#   tools/kokkos/sid_chroot.sh [ctest args]        (as root: debootstrap, mount and chroot)
# Environment:
#   ETD_DPD_SID_ROOT        the sid root (default ~/.cache/etd-dpd/sid-root; made once, reused)
#   ETD_DPD_DEBIAN_MIRROR   (default http://deb.debian.org/debian)
#   ETD_DPD_KOKKOS_BUILD    the package's build folder, relative to the repository
#                           (default build-kokkos-sid-chroot)
set -euo pipefail
log() { printf '[etd-dpd] %s\n' "$*" >&2; }
die() { printf '[etd-dpd] ERROR: %s\n' "$*" >&2; exit 1; }
[ "$(id -u)" = 0 ] || die "sid_chroot.sh needs root (debootstrap, mount, chroot)"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cache=${ETD_DPD_CACHE:-$HOME/.cache/etd-dpd}
root=${ETD_DPD_SID_ROOT:-$cache/sid-root}
mirror=${ETD_DPD_DEBIAN_MIRROR:-http://deb.debian.org/debian}
build=${ETD_DPD_KOKKOS_BUILD:-build-kokkos-sid-chroot}
case "$build" in /*|*..*) die "ETD_DPD_KOKKOS_BUILD=$build: a folder inside the repository, relative to it" ;; esac
# tools/bootstrap.sh's packages, and Debian's Kokkos
source "$here/tools/debian_packages.sh"
packages=("${debian_packages[@]}" libkokkos-dev)

if [ ! -x "$root/usr/bin/apt-get" ]; then
  command -v debootstrap >/dev/null || die "debootstrap is needed (Debian package debootstrap)"
  mkdir -p "$cache"
  log "debootstrap sid into $root"
  debootstrap --variant=minbase --include=ca-certificates sid "$root" "$mirror" >"$cache/sid-debootstrap.log" 2>&1 \
    || { tail -20 "$cache/sid-debootstrap.log" >&2; die "debootstrap failed (log: $cache/sid-debootstrap.log)"; }
fi
missing=()
for p in "${packages[@]}"; do
  chroot "$root" dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  log "installing sid's packages in $root: ${missing[*]}"
  # (a mirror's sid may be a snapshot past its Release's Valid-Until; signatures are still checked)
  no_expiry=(-o Acquire::Check-Valid-Until=false)
  chroot "$root" apt-get "${no_expiry[@]}" update -qq
  chroot "$root" env DEBIAN_FRONTEND=noninteractive apt-get "${no_expiry[@]}" install -y -qq --no-install-recommends \
    "${missing[@]}" >"$cache/sid-packages.log" 2>&1 \
    || { tail -20 "$cache/sid-packages.log" >&2; die "installing sid's packages failed (log: $cache/sid-packages.log)"; }
fi
kokkos_dir=$(chroot "$root" sh -c 'dirname "$(dpkg -L libkokkos-dev | grep /KokkosConfig.cmake$)"')
[ -n "$kokkos_dir" ] || die "libkokkos-dev in $root has no KokkosConfig.cmake"
# libkokkos-dev 5.2.2-2's CMake targets name two static libraries that the package does not
# ship, libkokkosalgorithms.a and libkokkossimd.a. Kokkos builds each from one placeholder
# function (its algorithms and simd are headers), so each is made here from the same function.
for lib in algorithms:KOKKOS_ALGORITHMS simd:KOKKOS_SIMD; do
  archive="$root${kokkos_dir%/cmake/Kokkos}/libkokkos${lib%%:*}.a"
  [ ! -f "$archive" ] || continue
  log "libkokkos-dev lacks $(basename "$archive"), which its CMake targets name: made from Kokkos's placeholder"
  printf 'void %s_SRC_DUMMY_PREVENT_LINK_ERROR() {}\n' "${lib#*:}" >"$root/tmp/kokkos_${lib%%:*}.cpp"
  chroot "$root" sh -c "cd /tmp && g++ -O2 -fPIC -c kokkos_${lib%%:*}.cpp -o kokkos_${lib%%:*}.o && ar rcs '${archive#"$root"}' kokkos_${lib%%:*}.o"
done

# the repository at the same path inside, and what MPI and OpenMP read
mounted=()
unmount_all() {
  local k
  for ((k = ${#mounted[@]} - 1; k >= 0; k--)); do umount -l "${mounted[k]}" 2>/dev/null || true; done
}
trap unmount_all EXIT
bind() {  # SOURCE TARGET-INSIDE [mount options...]
  local target="$root$2" source=$1; shift 2
  mkdir -p "$target"
  mount "$@" "$source" "$target"
  mounted+=("$target")
}
bind proc /proc -t proc
bind /sys /sys --rbind
bind /dev /dev --rbind
bind "$here" "$here" --bind
cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true

log "KOKKOS leg in the sid root: Kokkos from libkokkos-dev ($kokkos_dir)"
chroot "$root" env -i HOME=/root PATH=/usr/local/bin:/usr/bin:/bin LANG=C.UTF-8 \
  ETD_DPD_LAMMPS=sid ETD_DPD_KOKKOS_INSTALLED="$kokkos_dir" ETD_DPD_KOKKOS_BUILD="$here/$build" \
  ETD_DPD_JOBS="${ETD_DPD_JOBS:-$(nproc)}" OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  bash "$here/tools/kokkos/test.sh" "$@"
