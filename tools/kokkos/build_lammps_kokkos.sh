#!/usr/bin/env bash
# Build a KOKKOS LAMMPS to build the package's /kk styles against, idempotently, into a cache
# prefix keyed by backend, version and configuration. Backends (ETD_DPD_KOKKOS_BACKEND):
#   openmp (default)  OpenMP + Serial, the packages of the whole test suite
#   cuda              CUDA for one GPU architecture, with OpenMP + Serial on the host (the fix's
#                     host loops and the pair style's CPU loop take the node's cores with
#                     -k on g 1 t N); the packages of the KOKKOS tests and tools/kokkos/gpu.sh
#                     alone (KOKKOS, DPD-BASIC, DPD-REACT, PLUGIN);
#                     needs nvcc 12.0 or newer (Kokkos 4.6.1 with nvcc 13: a patched copy of the
#                     source, kokkos-4.6.1-cuda13.patch) and compiles with Kokkos's nvcc_wrapper
# Steps:
#   1. Kokkos from Debian's kokkos source package (sid by default), fetched and verified by
#      tools/debian_lammps_source.sh:
#        InRelease (gpgv, debian-archive-keyring) -> main/source/Sources.xz -> orig tarball
#      and built as SHARED libraries (libkokkoscore.so, libkokkoscontainers.so, ...) into PREFIX.
#      Debian's LAMMPS tarball is dfsg-stripped and has no lib/kokkos; and LAMMPS's bundled or
#      downloaded Kokkos is always linked statically into liblammps, which would leave a plugin
#      no Kokkos to share. One shared Kokkos in PREFIX/lib is the single copy that liblammps,
#      the lmp executable and the plugin all link.
#   2. LAMMPS (Debian's 4Jul2026 source, see tools/debian_lammps_source.sh) with the options of
#      tools/bootstrap.sh (the packages the whole test suite needs) plus PKG_KOKKOS, Kokkos_ENABLE_OPENMP/SERIAL, BUILD_OMP=on and
#      EXTERNAL_KOKKOS=on against the Kokkos of step 1, installed into the same PREFIX.
# Usage: tools/kokkos/build_lammps_kokkos.sh        (prints LAMMPS_KOKKOS_PREFIX=... last)
#        tools/kokkos/build_lammps_kokkos.sh --print-prefix   (the prefix alone: fetches the
#                                        sources where needed, builds nothing)
# Environment:
#   ETD_DPD_LAMMPS   Debian suite of the LAMMPS source (default sid)
#   LAMMPS_SOURCE    use this LAMMPS source tree instead
#   ETD_DPD_KOKKOS_SUITE  Debian suite of the kokkos source package (default sid)
#   KOKKOS_SOURCE    use this Kokkos source tree (a kokkos release unpacked) instead of Debian's
#   ETD_DPD_KOKKOS_INSTALLED  build no Kokkos: use the installed one whose KokkosConfig.cmake is
#                    in this folder (Debian's libkokkos-dev: /usr/lib/<triplet>/cmake/Kokkos;
#                    its shared libraries are then the single copy); backend openmp only
#   ETD_DPD_CACHE    cache folder (default ~/.cache/etd-dpd)
#   ETD_DPD_JOBS     parallel build jobs (default: number of cores)
#   ETD_DPD_KOKKOS_BACKEND  openmp (default) or cuda
#   ETD_DPD_KOKKOS_ARCH     cuda: Kokkos's GPU architecture (default HOPPER90: H100, H200)
#   ETD_DPD_KOKKOS_AS_5=1  where this LAMMPS asks for Kokkos 5 and the Kokkos source is 4.6.x:
#                    build that Kokkos as its stand-in (kokkos-4.6.1-as-5.patch on a copy)
#   ETD_DPD_DEBIAN_MIRROR  (default http://deb.debian.org/debian)
set -euo pipefail
log() { printf '[etd-dpd] %s\n' "$*" >&2; }
die() { printf '[etd-dpd] ERROR: %s\n' "$*" >&2; exit 1; }
print_prefix=no
for arg in "$@"; do
  case "$arg" in
    --print-prefix) print_prefix=yes ;;
    *) die "build_lammps_kokkos.sh: unknown argument $arg (--print-prefix)" ;;
  esac
done
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cache=${ETD_DPD_CACHE:-$HOME/.cache/etd-dpd}
jobs=${ETD_DPD_JOBS:-$(nproc)}
mirror=${ETD_DPD_DEBIAN_MIRROR:-http://deb.debian.org/debian}
ksuite=${ETD_DPD_KOKKOS_SUITE:-sid}

# ---- Kokkos source: Debian's kokkos orig tarball, verified ------------------------------
ksrcdir="$cache/src-$ksuite-kokkos"
kinstalled=
if [ -n "${ETD_DPD_KOKKOS_INSTALLED:-}" ]; then
  kinstalled=$(cd "$ETD_DPD_KOKKOS_INSTALLED" 2>/dev/null && pwd) \
    || die "ETD_DPD_KOKKOS_INSTALLED=$ETD_DPD_KOKKOS_INSTALLED is no folder"
  [ -f "$kinstalled/KokkosConfigVersion.cmake" ] \
    || die "ETD_DPD_KOKKOS_INSTALLED=$kinstalled has no KokkosConfigVersion.cmake (an installed Kokkos's cmake/Kokkos folder)"
  kver=$(sed -n 's/^set(PACKAGE_VERSION "\([0-9.]*\)")/\1/p' "$kinstalled/KokkosConfigVersion.cmake")
  [ -n "$kver" ] || die "no PACKAGE_VERSION in $kinstalled/KokkosConfigVersion.cmake"
  [ "${ETD_DPD_KOKKOS_BACKEND:-openmp}" = openmp ] \
    || die "ETD_DPD_KOKKOS_INSTALLED: an installed Kokkos serves the openmp backend only"
elif [ -n "${KOKKOS_SOURCE:-}" ]; then
  ksrc=$(cd "$KOKKOS_SOURCE" 2>/dev/null && pwd) || die "KOKKOS_SOURCE=$KOKKOS_SOURCE is no folder"
  kver=
  [ ! -f "$ksrc/CMakeLists.txt" ] \
    || kver=$(sed -n 's/^set(Kokkos_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\))/\2/p' "$ksrc/CMakeLists.txt" | paste -sd.)
  [ -n "$kver" ] || die "$ksrc is no Kokkos source tree (no Kokkos_VERSION in CMakeLists.txt)"
elif [ ! -f "$ksrcdir/kokkos/CMakeLists.txt" ]; then
  ETD_DPD_DEBIAN_MIRROR=$mirror bash "$here/tools/debian_lammps_source.sh" "$ksuite" "$ksrcdir" \
    kokkos >/dev/null \
    || die "no Kokkos source from Debian's $ksuite (above); unpack a Kokkos release that this
  LAMMPS accepts (its cmake/Modules/Packages/KOKKOS.cmake: find_package(Kokkos VERSION ...)) and
  set KOKKOS_SOURCE to it"
fi
if [ -z "${KOKKOS_SOURCE:-}" ] && [ -z "$kinstalled" ]; then ksrc="$ksrcdir/kokkos"; kver=$(cat "$ksrc/.debian-version"); fi

# ---- LAMMPS source -----------------------------------------------------------------------
suite=${ETD_DPD_LAMMPS:-sid}
if [ -n "${LAMMPS_SOURCE:-}" ]; then
  src=$(cd "$LAMMPS_SOURCE" 2>/dev/null && pwd) || die "LAMMPS_SOURCE=$LAMMPS_SOURCE is no folder"
  tag="custom-$(printf '%s' "$src" | sha1sum | cut -c1-8)"
else
  src="$cache/src-$suite/lammps"
  [ -f "$src/src/version.h" ] || bash "$here/tools/debian_lammps_source.sh" "$suite" "$cache/src-$suite" >/dev/null
  tag="debian-$suite"
fi
for file in src/version.h cmake/Modules/Packages/KOKKOS.cmake; do
  [ -f "$src/$file" ] || die "$src is no LAMMPS source tree with a KOKKOS package (no $file)"
done
version=$(sed -n 's/#define LAMMPS_VERSION "\(.*\)"/\1/p' "$src/src/version.h" | tr -d ' ')

# LAMMPS 4Jul2026 asks for Kokkos 5; a Kokkos 4.6 stands in for it only when asked to
wanted_major=$(sed -n 's/.*find_package(Kokkos \([0-9]*\)\..*/\1/p' "$src/cmake/Modules/Packages/KOKKOS.cmake" | head -1)
as5=no
if [ "${wanted_major:-4}" -ge 5 ] && [ "${kver%%.*}" -lt 5 ]; then
  [ "${kver%.*}" = 4.6 ] && [ "${ETD_DPD_KOKKOS_AS_5:-0}" = 1 ] \
    || die "LAMMPS $version asks for Kokkos $wanted_major (cmake/Modules/Packages/KOKKOS.cmake) and the
  Kokkos source is $kver: set KOKKOS_SOURCE to a Kokkos $wanted_major.x, or, with Kokkos 4.6.x,
  ETD_DPD_KOKKOS_AS_5=1 to build it as a stand-in (tools/kokkos/kokkos-4.6.1-as-5.patch)"
  as5=yes
fi

backend=${ETD_DPD_KOKKOS_BACKEND:-openmp}
case "$backend" in
  openmp)
    kokkos_cmake_options=(
      -D CMAKE_BUILD_TYPE=Release -D BUILD_SHARED_LIBS=on -D CMAKE_CXX_STANDARD=20
      -D CMAKE_CXX_EXTENSIONS=off -D Kokkos_ENABLE_OPENMP=on -D Kokkos_ENABLE_SERIAL=on
      -D Kokkos_ENABLE_IMPL_VIEW_LEGACY=on
    )
    lammps_cmake_options=(
      -D CMAKE_BUILD_TYPE=Release -D BUILD_SHARED_LIBS=on -D BUILD_MPI=on -D BUILD_OMP=on
      -D LAMMPS_EXCEPTIONS=on -D PKG_PLUGIN=on -D PKG_DPD-BASIC=on -D PKG_MOLECULE=on
      -D PKG_EXTRA-FIX=on -D PKG_RIGID=on -D PKG_DPD-REACT=on -D PKG_EXTRA-PAIR=off
      -D PKG_KOKKOS=on -D EXTERNAL_KOKKOS=on -D Kokkos_ENABLE_OPENMP=on -D Kokkos_ENABLE_SERIAL=on
    )
    name=lammps-kokkos ;;
  cuda)
    command -v nvcc >/dev/null || die "backend cuda: no nvcc on PATH (the CUDA toolkit, 12.0 or newer)"
    cuda_version=$(nvcc --version | sed -n 's/.*release \([0-9]*\.[0-9]*\).*/\1/p')
    cuda_major=${cuda_version%%.*}
    [ "${cuda_major:-0}" -ge 12 ] || die "backend cuda: nvcc $cuda_version; Kokkos $kver needs CUDA 12.0 or newer"
    arch=${ETD_DPD_KOKKOS_ARCH:-HOPPER90}
    case "$arch" in  # nvcc's name of the architecture, for nvcc_wrapper's default
      HOPPER90) sm=sm_90 ;; ADA89) sm=sm_89 ;; AMPERE86) sm=sm_86 ;; AMPERE80) sm=sm_80 ;;
      *) die "backend cuda: ETD_DPD_KOKKOS_ARCH=$arch is not one of HOPPER90 ADA89 AMPERE86 AMPERE80" ;;
    esac
    # C++17: LAMMPS's KOKKOS package needs no more, and nvcc 12 takes C++20 only with newer GCCs
    kokkos_cmake_options=(
      -D CMAKE_BUILD_TYPE=Release -D BUILD_SHARED_LIBS=on -D CMAKE_CXX_STANDARD=17
      -D CMAKE_CXX_EXTENSIONS=off -D Kokkos_ENABLE_CUDA=on -D Kokkos_ENABLE_OPENMP=on
      -D Kokkos_ENABLE_SERIAL=on -D "Kokkos_ARCH_$arch=on" -D Kokkos_ENABLE_IMPL_VIEW_LEGACY=on
    )
    lammps_cmake_options=(
      -D CMAKE_BUILD_TYPE=Release -D BUILD_SHARED_LIBS=on -D BUILD_MPI=on -D BUILD_OMP=on
      -D LAMMPS_EXCEPTIONS=on -D PKG_PLUGIN=on -D PKG_DPD-BASIC=on -D PKG_DPD-REACT=on
      -D PKG_KOKKOS=on -D EXTERNAL_KOKKOS=on
    )
    name=lammps-kokkos-cuda ;;
  *) die "ETD_DPD_KOKKOS_BACKEND=$backend: openmp or cuda" ;;
esac
# The patches for a copy of the Kokkos source: Kokkos 4.6 with nvcc 13 needs one for CUDA 13's
# runtime API; the stand-in for Kokkos 5 is another (ETD_DPD_KOKKOS_AS_5)
patches=()
[ "$as5" = no ] || patches+=("$here/tools/kokkos/kokkos-4.6.1-as-5.patch")
if [ "$backend" = cuda ] && [ "$cuda_major" -ge 13 ] && [ "${kver%.*}" = 4.6 ]; then
  patches+=("$here/tools/kokkos/kokkos-4.6.1-cuda13.patch")
fi
# the prefix is keyed by what the build is made of, the patches' contents included, so that a
# changed patch builds anew instead of reusing a build made with the old one
patch_digests=()
for patch_file in "${patches[@]}"; do
  patch_digests+=("$(sha256sum <"$patch_file" | cut -d' ' -f1)")
done
[ -z "$kinstalled" ] || kokkos_cmake_options=(installed "$kinstalled")
confhash=$(printf '%s\n' "${kokkos_cmake_options[@]}" "kokkos-$kver" "${lammps_cmake_options[@]}" "$tag" \
           "${patch_digests[@]}" | sha1sum | cut -c1-10)
prefix="$cache/$name-$version-$confhash"
if [ "$print_prefix" = yes ]; then
  echo "LAMMPS_KOKKOS_PREFIX=$prefix"
  exit 0
fi
# a prefix may be a link to a build made elsewhere; its files name the real folder
[ ! -L "$prefix" ] || prefix=$(readlink -f "$prefix")
linker_flags="-Wl,--disable-new-dtags"
# each step's time is appended to PREFIX/build-times as it ends, so that a build resumed after a
# stop keeps the times of the steps before (a step stopped midway counts from its resumption)
step() {  # NAME LOG COMMAND...
  local name=$1 logf=$2 started; shift 2
  started=$(date +%s)
  "$@" >"$logf" 2>&1 || { tail -40 "$logf" >&2; die "$name failed (log: $logf)"; }
  printf '%s: %s s with %s jobs (%s)\n' "$name" $(( $(date +%s) - started )) "$jobs" "$(date -u +%FT%TZ)" \
    >>"$prefix/build-times"
}
if [ ! -f "$prefix/.complete" ]; then
  log "building LAMMPS $version ($tag) with KOKKOS against Kokkos $kver (shared; ${kinstalled:-built here}) into $prefix"
  # a build stopped midway (a time limit) resumes: its build folders are incremental
  mkdir -p "$prefix"
  compiler=()
  # A copy of the Kokkos source where it needs changes: the patches above, and with CUDA
  # nvcc_wrapper's default architecture (Kokkos 4.6's is sm_70, which nvcc 13 no longer knows),
  # which must be this GPU's before CMake's first compiler check
  [ "$backend" != cuda ] || log "backend cuda: nvcc $cuda_version, Kokkos_ARCH_$arch ($sm)"
  if [ "$backend" = cuda ] || [ ${#patches[@]} -gt 0 ]; then
    if [ ! -f "$prefix/kokkos-source/.prepared" ]; then
      rm -rf "$prefix/kokkos-source"
      cp -a "$ksrc" "$prefix/kokkos-source"
      [ "$backend" != cuda ] \
        || sed -i "s/^default_arch=.*/default_arch=\"$sm\"/" "$prefix/kokkos-source/bin/nvcc_wrapper"
      for patch_file in "${patches[@]}"; do
        if command -v patch >/dev/null; then
          patch -d "$prefix/kokkos-source" -p1 <"$patch_file" >/dev/null
        else  # git apply outside a repository patches plain files too
          (cd "$prefix/kokkos-source" && git apply -p1 "$patch_file")
        fi || die "$(basename "$patch_file") does not apply to Kokkos $kver"
      done
      touch "$prefix/kokkos-source/.prepared"
    fi
    ksrc="$prefix/kokkos-source"
  fi
  if [ "$backend" = cuda ]; then
    compiler=(-D CMAKE_CXX_COMPILER="$ksrc/bin/nvcc_wrapper")
    # libkokkoscore links the driver's libcuda.so.1, which a machine without a GPU driver lacks:
    # executables then link against the toolkit's stub under that name (link time only)
    if ! ldconfig -p 2>/dev/null | grep -q 'libcuda\.so\.1 '; then
      stub=$(find "$(dirname "$(dirname "$(command -v nvcc)")")/" -path '*stubs/libcuda.so' 2>/dev/null | head -1)
      [ -n "$stub" ] || die "backend cuda: no libcuda.so.1 (GPU driver) and no stubs/libcuda.so in the toolkit"
      mkdir -p "$prefix/cuda-stubs" && ln -sf "$stub" "$prefix/cuda-stubs/libcuda.so.1"
      linker_flags+=" -Wl,-rpath-link,$prefix/cuda-stubs"
    fi
  fi
  common=(-D CMAKE_INSTALL_PREFIX="$prefix" -D CMAKE_INSTALL_LIBDIR=lib -D CMAKE_INSTALL_RPATH="$prefix/lib"
          -D CMAKE_EXE_LINKER_FLAGS="$linker_flags" -D CMAKE_SHARED_LINKER_FLAGS="$linker_flags")
  kokkos_dir=$prefix/lib/cmake/Kokkos
  if [ -n "$kinstalled" ]; then
    kokkos_dir=$kinstalled ksrc=$kinstalled
  else
    step "Kokkos configure" "$prefix/kokkos-configure.log" \
      cmake -S "$ksrc" -B "$prefix/build-kokkos" "${kokkos_cmake_options[@]}" "${common[@]}" "${compiler[@]}"
    step "Kokkos build" "$prefix/kokkos-build.log" cmake --build "$prefix/build-kokkos" -j "$jobs"
    step "Kokkos install" "$prefix/kokkos-install.log" cmake --install "$prefix/build-kokkos"
  fi
  step "LAMMPS configure" "$prefix/configure.log" \
    cmake -S "$src/cmake" -B "$prefix/build" "${lammps_cmake_options[@]}" "${common[@]}" \
          -D Kokkos_DIR="$kokkos_dir" "${compiler[@]}"
  step "LAMMPS build" "$prefix/build.log" cmake --build "$prefix/build" -j "$jobs"
  step "LAMMPS install" "$prefix/install.log" cmake --install "$prefix/build"
  printf '%s\n' "$src" >"$prefix/source-dir"
  printf '%s\n' "$ksrc" >"$prefix/kokkos-source-dir"
  printf '%s\n' "$backend" >"$prefix/backend"
  # where the package finds the Kokkos that this LAMMPS links, when not in the prefix (test.sh)
  [ -z "$kinstalled" ] || printf '%s\n' "$kinstalled" >"$prefix/kokkos-dir"
  touch "$prefix/.complete"
else
  log "reusing the KOKKOS LAMMPS $version at $prefix"
fi
echo "LAMMPS_KOKKOS_PREFIX=$prefix"
