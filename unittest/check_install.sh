#!/usr/bin/env bash
# Install layout and plugin loading, as a cluster user would use them:
#   1. `cmake --install BUILD --prefix P` puts etddpdplugin.so (and the etddpd.so link) in
#      P/lib/lammps/plugins, the docs in P/share/doc/etd-dpd, examples and potentials in
#      P/share/etd-dpd;
#   2. the installed module loads with `plugin load` and, where LAMMPS supports it, is found by
#      LAMMPS_PLUGIN_PATH with no `plugin load` at all, registering all eight styles; each way the
#      run's thermo output is identical to that of the build tree's module;
#   3. without LAMMPS_PLUGIN_PATH the styles are unknown (the check above is not vacuous).
# usage: check_install.sh BUILD_DIR LMP INPUT AUTOLOAD(0|1)
set -euo pipefail
build=$1 lmp=$2 input=$3 autoload=$4
prefix="$build/install-check"
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
fail() { echo "FAIL: $*"; exit 1; }
plugindir="$prefix/lib/lammps/plugins"
for f in "$plugindir/etddpdplugin.so" "$plugindir/etddpd.so" \
         "$prefix/share/doc/etd-dpd/README.md" "$prefix/share/doc/etd-dpd/fix_etd.rst" \
         "$prefix/share/etd-dpd/examples/quickstart/in.quickstart" \
         "$prefix/share/etd-dpd/potentials/colloid_dpdgen_maiduy2013.in"; do
  [ -e "$f" ] || fail "cmake --install did not create $f"
done
echo "install layout: OK ($prefix)"

work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work"
thermo() { awk '/^ *Step/{p=1} p&&/^Loop/{p=0} p' "$1"; }
run() {  # NAME [lmp arguments]: runs in a clean environment for LAMMPS_PLUGIN_PATH
  local name=$1; shift
  env -u LAMMPS_PLUGIN_PATH "$@" -in "$input" -log none -echo none >"$name.out" 2>&1 || true
}
run reference "$lmp" -var load "plugin load $build/etddpdplugin.so"
thermo reference.out | grep -q '^ *30 ' || { cat reference.out; fail "the build tree's module did not run"; }
for module in etddpdplugin.so etddpd.so; do
  run "installed-$module" "$lmp" -var load "plugin load $plugindir/$module"
  diff <(thermo reference.out) <(thermo "installed-$module.out") >/dev/null \
    || { cat "installed-$module.out"; fail "plugin load $plugindir/$module: thermo differs"; }
done
echo "plugin load of the installed module: same thermo as the build tree's"

run unloaded "$lmp"
grep -q "dpd/gen" unloaded.out && ! thermo unloaded.out | grep -q '^ *30 ' \
  || { cat unloaded.out; fail "without the plugin, pair_style dpd/gen was not refused"; }
if [ "$autoload" = 1 ]; then
  for dir in "$plugindir" "$build"; do
    env LAMMPS_PLUGIN_PATH="$dir" "$lmp" -in "$input" -log none -echo none >auto.out 2>&1 || true
    diff <(thermo reference.out) <(thermo auto.out) >/dev/null \
      || { cat auto.out; fail "LAMMPS_PLUGIN_PATH=$dir: styles not auto-loaded or thermo differs"; }
    # `plugin list` prints one "<kind> style plugin <name>" line per registered style
    for style in "pair dpd/gen" "pair dpd/fpm" "fix etd" "fix wall/thermal/layer" \
                 "fix wall/cylinder/bounce" "compute dpd/split" "compute dpd/tcurrent" "command dpd/design"; do
      grep -Eq "${style% *} style plugin ${style#* }\$" auto.out \
        || { cat auto.out; fail "LAMMPS_PLUGIN_PATH=$dir: ${style} not among the loaded plugins"; }
    done
    echo "LAMMPS_PLUGIN_PATH=$dir: eight styles auto-loaded, same thermo"
  done
else
  echo "this LAMMPS has no LAMMPS_PLUGIN_PATH auto-loading (added in 4May2022): not checked"
fi
echo PASS
