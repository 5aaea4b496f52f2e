#!/usr/bin/env bash
# Set up everything ETD-DPD needs on a Debian 12 machine, idempotently:
#   1. Debian packages (compiler, CMake, Open MPI, GoogleTest, Random123, numpy/scipy/matplotlib)
#   2. LAMMPS 29Sep2021 update 2 from Debian's source package, built as a shared library with
#      MPI, PLUGIN, DPD-BASIC, DPD-REACT (fix shardlow, the peer), MOLECULE, EXTRA-FIX and
#      RIGID, installed into a cache prefix keyed by version and configuration (reused on the
#      next call)
#   3. the ETD-DPD plugin and its tests, built incrementally in ./build
# Environment:
#   ETD_DPD_LAMMPS  which Debian suite's LAMMPS source: bookworm (default; LAMMPS 29Sep2021
#                   update 2, by apt-get source) or a newer suite such as sid or forky
#                   (4Jul2026 as of 2026-11) or trixie (4Feb2025), fetched and verified by
#                   tools/debian_lammps_source.sh; delete $ETD_DPD_CACHE/src-SUITE to refresh it
#   LAMMPS_SOURCE   use this LAMMPS source tree instead of Debian's (a newer one, say)
#   ETD_DPD_BUILD   the plugin's build folder (default ./build; ./build-SUITE for other suites)
#   ETD_DPD_CACHE   where LAMMPS is cached (default ~/.cache/etd-dpd)
#   ETD_DPD_JOBS    parallel build jobs (default: number of cores)
# Each LAMMPS build is cached under a prefix keyed by version and configuration.
# Prints "ETD_DPD_BUILD=..." and, as the last line, "LAMMPS_PREFIX=..." (also written to
# BUILD/lammps-prefix).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cache=${ETD_DPD_CACHE:-$HOME/.cache/etd-dpd}
jobs=${ETD_DPD_JOBS:-$(nproc)}
log() { printf '[etd-dpd] %s\n' "$*" >&2; }

# ---- 1. Debian packages ------------------------------------------------------------------
source "$here/tools/debian_packages.sh"
missing=()
for p in "${debian_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
sudo_cmd=""; [ "$(id -u)" = 0 ] || sudo_cmd="sudo"
if [ ${#missing[@]} -gt 0 ]; then
  log "installing Debian packages: ${missing[*]}"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

# ---- 2. LAMMPS ---------------------------------------------------------------------------
lammps_cmake_options=(
  -D CMAKE_BUILD_TYPE=Release -D BUILD_SHARED_LIBS=on -D BUILD_MPI=on -D BUILD_OMP=off
  -D LAMMPS_EXCEPTIONS=on -D PKG_PLUGIN=on -D PKG_DPD-BASIC=on -D PKG_MOLECULE=on
  -D PKG_EXTRA-FIX=on -D PKG_RIGID=on -D PKG_DPD-REACT=on -D PKG_EXTRA-PAIR=off
)
suite=${ETD_DPD_LAMMPS:-bookworm}
if [ -n "${LAMMPS_SOURCE:-}" ]; then
  src=$(cd "$LAMMPS_SOURCE" && pwd)
  tag="custom-$(printf '%s' "$src" | sha1sum | cut -c1-8)"
elif [ "$suite" != bookworm ]; then
  src="$cache/src-$suite/lammps"
  if [ ! -f "$src/src/version.h" ]; then
    log "fetching Debian's $suite LAMMPS source"
    bash "$here/tools/debian_lammps_source.sh" "$suite" "$cache/src-$suite" >/dev/null
  fi
  tag="debian-$suite"
else
  srcdir="$cache/src"
  src="$srcdir/lammps"
  if [ ! -f "$src/src/version.h" ]; then
    if ! apt-get source --print-uris lammps >/dev/null 2>&1 || \
       [ -z "$(apt-get source --print-uris lammps 2>/dev/null | grep orig)" ]; then
      log "adding a deb-src entry for Debian's archive (needed by apt-get source)"
      . /etc/os-release
      $sudo_cmd tee /etc/apt/sources.list.d/etd-dpd-src.sources >/dev/null <<SRC
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: ${VERSION_CODENAME:-bookworm} ${VERSION_CODENAME:-bookworm}-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
      $sudo_cmd apt-get update -qq
    fi
    log "fetching Debian's LAMMPS source package"
    rm -rf "$srcdir"; mkdir -p "$srcdir"
    (cd "$srcdir" && apt-get source --download-only lammps >&2 && \
       dpkg-source -x lammps_*.dsc lammps >&2)
  fi
  tag="debian"
fi
version=$(sed -n 's/#define LAMMPS_VERSION "\(.*\)"/\1/p' "$src/src/version.h" | tr -d ' ')
confhash=$(printf '%s\n' "${lammps_cmake_options[@]}" "$tag" | sha1sum | cut -c1-10)
prefix="$cache/lammps-$version-$confhash"
if [ ! -f "$prefix/.complete" ]; then
  log "building LAMMPS $version ($tag) into $prefix (about 10 minutes on 2 cores)"
  rm -rf "$prefix"; mkdir -p "$prefix"
  cmake -S "$src/cmake" -B "$prefix/build" "${lammps_cmake_options[@]}" \
        -D CMAKE_INSTALL_PREFIX="$prefix" -D CMAKE_INSTALL_LIBDIR=lib \
        -D CMAKE_INSTALL_RPATH="$prefix/lib" -D CMAKE_BUILD_WITH_INSTALL_RPATH=off \
        -D CMAKE_EXE_LINKER_FLAGS="-Wl,--disable-new-dtags" \
        -D CMAKE_SHARED_LINKER_FLAGS="-Wl,--disable-new-dtags" >"$prefix/configure.log" 2>&1 \
    || { tail -30 "$prefix/configure.log" >&2; exit 1; }
  cmake --build "$prefix/build" -j "$jobs" >"$prefix/build.log" 2>&1 \
    || { tail -30 "$prefix/build.log" >&2; exit 1; }
  cmake --install "$prefix/build" >"$prefix/install.log" 2>&1 \
    || { tail -30 "$prefix/install.log" >&2; exit 1; }
  printf '%s\n' "$src" >"$prefix/source-dir"
  touch "$prefix/.complete"
else
  log "reusing LAMMPS $version at $prefix"
fi

# ---- 3. the plugin -----------------------------------------------------------------------
default_build="$here/build"
[ -n "${LAMMPS_SOURCE:-}" ] || [ "$suite" = bookworm ] || default_build="$here/build-$suite"
build=${ETD_DPD_BUILD:-$default_build}
if [ ! -f "$build/CMakeCache.txt" ] || ! grep -q "LAMMPS_SOURCE_DIR:PATH=$src\$" "$build/CMakeCache.txt" \
   || ! grep -q "LAMMPS_PREFIX:PATH=$prefix\$" "$build/CMakeCache.txt"; then
  rm -rf "$build"
  cmake -S "$here" -B "$build" -D CMAKE_BUILD_TYPE=Release -D LAMMPS_SOURCE_DIR="$src" \
        -D LAMMPS_PREFIX="$prefix" >&2
fi
log "building the ETD-DPD plugin in $build"
cmake --build "$build" -j "$jobs" >&2
printf '%s\n' "$prefix" >"$build/lammps-prefix"
echo "ETD_DPD_BUILD=$build"
echo "LAMMPS_PREFIX=$prefix"
