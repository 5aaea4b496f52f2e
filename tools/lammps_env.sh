# Sourced by the study and benchmark drivers (validation/*/, bench/) for what they all need:
#   ETD_TOP  the repository's top folder
#   LMP      the LAMMPS executable: kept if set, else the one tools/bootstrap.sh builds (and the
#            plugin with it, both brought up to date first)
#   PLUGIN   the plugin module: kept if set, else build/etddpdplugin.so
ETD_TOP=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ -z "${LMP:-}" ]; then
  etd_bootstrap_log=${TMPDIR:-/tmp}/etd-dpd-bootstrap.log
  LMP="$(bash "$ETD_TOP/tools/bootstrap.sh" 2>"$etd_bootstrap_log" | sed -n 's/^LAMMPS_PREFIX=//p' || true)/bin/lmp"
fi
PLUGIN=${PLUGIN:-$ETD_TOP/build/etddpdplugin.so}
if [ ! -x "$LMP" ] || [ ! -f "$PLUGIN" ]; then
  echo "no LAMMPS executable at '$LMP' or no plugin at '$PLUGIN': set LMP and PLUGIN, or see why" \
       "tools/bootstrap.sh failed (${etd_bootstrap_log:-not run})" >&2
  exit 1
fi
