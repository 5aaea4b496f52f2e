#!/usr/bin/env bash
# The command pages build with Sphinx, every warning an error (doc/conf.py); and the check is not
# vacuous: a copy of the pages with a link to a LAMMPS page that does not exist must fail.
# usage: check_doc_build.sh SPHINX_BUILD DOC_DIR WORK_DIR   (LAMMPS_SOURCE_DIR in the environment)
set -euo pipefail
sphinx=$1 doc=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
"$sphinx" -q -W --keep-going -b html -d "$work/doctrees" "$doc" "$work/html"
grep -q 'href="https://docs.lammps.org/fix_nve.html"' "$work/html/fix_etd.html" \
  || { echo "FAIL: links to LAMMPS's pages were not resolved into its manual"; exit 1; }
echo "doc build: OK, no warnings"
cp -r "$doc" "$work/broken"
printf '\nSee :doc:`fix nothing <fix_no_such_command>`.\n' >>"$work/broken/fix_etd.rst"
if "$sphinx" -q -W -b html -d "$work/broken-doctrees" "$work/broken" "$work/broken-html" \
     >"$work/broken.log" 2>&1; then
  echo "FAIL: a link to a page that exists neither here nor in LAMMPS built without error"; exit 1
fi
grep -q "fix_no_such_command" "$work/broken.log" \
  || { cat "$work/broken.log"; echo "FAIL: the broken build failed for another reason"; exit 1; }
echo "a broken link fails the build: OK"
echo PASS
