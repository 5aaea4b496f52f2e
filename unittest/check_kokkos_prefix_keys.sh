#!/usr/bin/env bash
# tools/kokkos/build_lammps_kokkos.sh keys its cache prefix by what the build is made of, so that
# a cached build is reused only for the same build: the Kokkos patches' contents are in the key
# (a changed patch gives another prefix; the same patches elsewhere give the same one), a build
# without patches has its own, and a prefix that is a link to a complete build elsewhere is
# reused under its real folder. The LAMMPS and Kokkos trees are stubs; nothing is built.
set -uo pipefail
unset ETD_DPD_KOKKOS_AS_5 ETD_DPD_KOKKOS_BACKEND ETD_DPD_KOKKOS_ARCH ETD_DPD_LAMMPS LAMMPS_SOURCE \
  KOKKOS_SOURCE ETD_DPD_KOKKOS_INSTALLED ETD_DPD_KOKKOS_SUITE
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() {  # WHAT CONDITION...
  local what=$1; shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; failures=$((failures + 1)); fi
}

# stubs: a LAMMPS that asks for Kokkos 5 (and one that asks for 4), a Kokkos 4.6.1
. "$root/unittest/kokkos_tool_stubs.sh"
stub_lammps "$work/lammps5" 5
stub_lammps "$work/lammps4" 4
stub_kokkos "$work/kokkos"
# a second copy of the tools, whose stand-in patch can be changed
mkdir -p "$work/copy/tools/kokkos"
cp "$root/tools/kokkos/build_lammps_kokkos.sh" "$root"/tools/kokkos/*.patch "$work/copy/tools/kokkos/"

prefix_of() {  # TOOLS_ROOT LAMMPS [ENV...]: the prefix --print-prefix names
  local tools=$1 lammps=$2; shift 2
  env ETD_DPD_CACHE="$work/cache" LAMMPS_SOURCE="$lammps" KOKKOS_SOURCE="$work/kokkos" "$@" \
    bash "$tools/tools/kokkos/build_lammps_kokkos.sh" --print-prefix 2>/dev/null |
    sed -n 's/^LAMMPS_KOKKOS_PREFIX=//p'
}
stand_in=$(prefix_of "$root" "$work/lammps5" ETD_DPD_KOKKOS_AS_5=1)
same_elsewhere=$(prefix_of "$work/copy" "$work/lammps5" ETD_DPD_KOKKOS_AS_5=1)
echo '# a changed line' >>"$work/copy/tools/kokkos/kokkos-4.6.1-as-5.patch"
changed_patch=$(prefix_of "$work/copy" "$work/lammps5" ETD_DPD_KOKKOS_AS_5=1)
no_patch=$(prefix_of "$root" "$work/lammps4")
echo "stand-in: $stand_in; same patch elsewhere: $same_elsewhere; changed patch: $changed_patch; no patch: $no_patch"
check "--print-prefix names a prefix" test -n "$stand_in" -a -n "$no_patch"
check "the same patches from another copy of the tools: the same prefix" test "$stand_in" = "$same_elsewhere"
check "a changed patch: another prefix" test -n "$changed_patch" -a "$changed_patch" != "$stand_in"
check "--print-prefix builds nothing" test ! -e "$work/cache"

# a prefix that is a link to a complete build elsewhere: reused, under the real folder
mkdir -p "$work/elsewhere/build" "$work/cache"
touch "$work/elsewhere/build/.complete"
ln -s "$work/elsewhere/build" "$no_patch"
reused=$(env ETD_DPD_CACHE="$work/cache" LAMMPS_SOURCE="$work/lammps4" KOKKOS_SOURCE="$work/kokkos" \
  bash "$root/tools/kokkos/build_lammps_kokkos.sh" 2>"$work/log" | sed -n 's/^LAMMPS_KOKKOS_PREFIX=//p')
check "a linked complete prefix is reused under its real folder ($reused)" \
  test "$reused" = "$work/elsewhere/build"
check "and nothing is built" grep -q "reusing the KOKKOS LAMMPS" "$work/log"
[ "$failures" -eq 0 ] && echo PASS
exit "$failures"
