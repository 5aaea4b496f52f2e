#!/usr/bin/env bash
# The project's lmp and liblammps must load the liblammps.so.0 of their own prefix, even when a
# system liblammps.so.0 (Debian's liblammps0) is installed or LD_LIBRARY_PATH points elsewhere.
set -euo pipefail
prefix=$1
lmp="$prefix/bin/lmp"
resolved=$(LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu ldd "$lmp" | awk '/liblammps\.so/ {print $3}')
echo "lmp loads liblammps from: $resolved"
[ "$(readlink -f "$resolved")" = "$(readlink -f "$prefix/lib/liblammps.so.0")" ] || {
  echo "FAIL: $lmp resolves liblammps to $resolved, not $prefix/lib"; exit 1; }
if [ -e /usr/lib/x86_64-linux-gnu/liblammps.so.0 ]; then
  echo "a system liblammps.so.0 is installed and was not picked up"
else
  echo "no system liblammps.so.0 present; RPATH checked against LD_LIBRARY_PATH only"
fi
help=$("$lmp" -h)
for package in PLUGIN DPD-BASIC MOLECULE; do
  grep -q "$package" <<<"$help" || { echo "FAIL: lmp lacks the $package package"; exit 1; }
done
echo "PASS"
