#!/usr/bin/python3
"""The package's example inputs, unchanged but for their run lengths, on the CPU styles and with
`-k on t N -sf kk` on one KOKKOS LAMMPS: both must run, and their last thermo rows must agree
to 1e-6 (the /kk styles follow the CPU styles to round-off). The runs are kept short, 10
steps each by default: beyond some tens of steps round-off differences (the order of sums, the
step at which the implicit solve's residual crosses its tolerance) grow as in any two MD runs,
and past 20 steps the /kk styles' own atom sort reorders the atoms, and with them the order in
which stock stochastic walls draw their numbers. Where an input's pair style has a /kk variant,
the KOKKOS run must have used it. Where the KOKKOS package cannot
run an input, the KOKKOS run must stop with an ERROR that names why.

usage: check_examples_kokkos.py LMP PLUGIN REPOSITORY [THREADS [STEPS [CASE ...]]]
ETD_EXAMPLES_LAUNCHER (environment): words put before LMP in both runs, e.g. "mpirun -np 2".
Exit status 0 when every case passes; on a failure the cases' logs stay in the scratch folder named.
"""
import datetime
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

# (case, input under examples/, -var settings, text replaced in the input, what the KOKKOS run
# stops with, else None): every shipped input that runs the package's styles (in.fene_check runs
# no pair style of the package), and the variants that switch integrators or wall conditions
MULTI = "neighbor        ${skin} multi"
BIN = "neighbor        ${skin} bin  "
NO_MULTI = "cannot use 'neighbor ... multi'"
CASES = [
    ("quickstart", "quickstart/in.quickstart", {}, {}, None),
    ("couette", "couette/in.couette", {}, {}, None),
    ("couette_layer", "couette/in.couette", {"wallbc": "layer"}, {}, None),
    ("poiseuille", "poiseuille/in.poiseuille", {}, {}, None),
    ("pipe", "pipe/in.pipe", {}, {}, None),
    ("shear_implicit", "shear/in.shear", {}, {}, None),
    ("shear_diagonal", "shear/in.shear", {"integ": "diag"}, {}, None),
    ("shear_tcaf", "shear/in.tcaf", {}, {}, None),
    ("tcaf", "tcaf/in.tcaf", {}, {}, None),
    ("fpm_colloid", "fpm_colloid/in.fpm_colloid", {}, {}, None),
    ("sphere_couette", "sphere-couette/in.sphere-couette", {}, {}, None),
    ("sphere_couette_implicit", "sphere-couette/in.sphere-couette",
     {"scheme": "implicit", "wallbc": "layer"}, {}, None),
    # neighbor multi (the colloid's long cutoff): not under KOKKOS; the same input with bin
    ("colloid_shear", "channel-sphere/in.colloid_shear", {}, {}, NO_MULTI),
    ("colloid_shear_bin", "channel-sphere/in.colloid_shear", {}, {MULTI: BIN}, None),
    ("colloid_fpm_shear", "channel-sphere/in.colloid_fpm_shear", {}, {}, NO_MULTI),
    ("colloid_fpm_shear_bin", "channel-sphere/in.colloid_fpm_shear", {}, {MULTI: BIN}, None),
    ("sphere_shear", "channel-sphere/in.sphere_shear", {}, {}, None),
    ("sphere_cylinder", "channel-sphere/in.sphere_cylinder", {}, {}, None),
    ("sphere_compliant", "channel-sphere/in.sphere_compliant", {}, {}, None),
]
# the cases whose input keeps stock fix wall/reflect/stochastic, which crashes at its first step
# from LAMMPS 4Jul2026 on (README, "The LAMMPS versions tested"): not run there
STOCHASTIC_WALLS = {"couette", "poiseuille", "sphere_couette", "colloid_shear",
                    "colloid_shear_bin", "colloid_fpm_shear", "colloid_fpm_shear_bin",
                    "sphere_shear"}
STOCHASTIC_WALLS_CRASH_FROM = datetime.date(2026, 7, 4)
# the pair styles with a /kk variant in the package (the KOKKOS run must list it)
KK_PAIR_STYLES = ("dpd/gen",)
RELATIVE_TOLERANCE = 1e-6

RUN = re.compile(r'(^\s*|")run\s+([^"#\n]+)', re.MULTILINE)


def shortened(text, steps):
    """the input with every run but `run 0` set to `steps` steps"""
    def replace(match):
        words = match.group(2).split()
        if words and words[0] == "0":
            return match.group(0)
        return f"{match.group(1)}run {steps} "
    return RUN.sub(replace, text)


def last_thermo(log):
    """the header and last row of the last thermo block of a LAMMPS log"""
    header, row = None, None
    lines = log.splitlines()
    for k, line in enumerate(lines):
        words = line.split()
        if words[:1] == ["Step"]:
            block_header, block_row = words, None
            for following in lines[k + 1:]:
                values = following.split()
                if len(values) != len(words):
                    break
                try:
                    block_row = [float(v) for v in values]
                except ValueError:
                    break
            if block_row is not None:
                header, row = block_header, block_row
    return header, row


def lammps_date(lmp):
    """the release date LAMMPS prints in its help text"""
    text = subprocess.run([lmp, "-h"], capture_output=True, text=True, timeout=60).stdout
    found = re.search(r"Simulator - (\d+ \w{3} \d{4})", text)
    if not found:
        raise SystemExit(f"{lmp} -h names no LAMMPS version")
    return datetime.datetime.strptime(found.group(1), "%d %b %Y").date()


def run(lmp, folder, name, args):
    log = os.path.join(folder, f"log.{name}")
    launcher = os.environ.get("ETD_EXAMPLES_LAUNCHER", "").split()
    result = subprocess.run([*launcher, lmp, *args, "-log", log, "-screen", "none"], cwd=folder,
                            capture_output=True, text=True, timeout=600)
    text = ""
    if os.path.exists(log):
        with open(log) as handle:
            text = handle.read()
    return result.returncode, text + result.stdout + result.stderr


def check_case(lmp, plugin, repository, threads, steps, case, scratch):
    name, path, settings, replacements, kk_error = case
    folder = os.path.join(scratch, name)
    os.makedirs(folder, exist_ok=True)
    source = os.path.join(repository, "examples", path)
    with open(source) as handle:
        text = shortened(handle.read(), steps)
    for old, new in replacements.items():
        if old not in text:
            return [f"the input has no line '{old}' to replace"]
        text = text.replace(old, new)
    with open(os.path.join(folder, "in.case"), "w") as handle:
        handle.write(text)
    potentials = os.path.join(repository, "potentials")
    variables = {"plugin": plugin, "potentials": potentials, "potdir": potentials, **settings}
    args = ["-in", "in.case"]
    for key, value in variables.items():
        args += ["-var", key, value]
    failures = []
    outputs = {}
    for label, extra in (("cpu", []), ("kk", ["-k", "on", "t", str(threads), "-sf", "kk"])):
        status, text = run(lmp, folder, f"{name}.{label}", args + extra)
        outputs[label] = text
        if label == "kk" and kk_error:
            if status != 1 or "ERROR: " not in text or kk_error not in text:
                failures.append(f"kk run: exit status {status}, expected an ERROR naming "
                                f"{kk_error!r}")
            return failures
        if status != 0 or "ERROR" in text:
            errors = [line for line in text.splitlines() if "ERROR" in line][:3]
            failures.append(f"{label} run: exit status {status} {errors}")
    if failures:
        return failures
    cpu_header, cpu_row = last_thermo(outputs["cpu"])
    kk_header, kk_row = last_thermo(outputs["kk"])
    if cpu_row is None or kk_row is None or cpu_header != kk_header:
        return [f"thermo output: cpu {cpu_header} and kk {kk_header} differ or are missing"]
    for column, a, b in zip(cpu_header, cpu_row, kk_row):
        if not (math.isfinite(a) and math.isfinite(b)):
            failures.append(f"{column}: cpu {a}, kk {b} (not finite)")
        elif abs(a - b) > RELATIVE_TOLERANCE * max(abs(a), abs(b), 1e-3):
            failures.append(f"{column}: cpu {a!r}, kk {b!r}")
    if cpu_row[0] == 0:
        failures.append("the last thermo row is step 0: nothing ran")
    # the pair styles that requested neighbor lists, as LAMMPS lists them ("(1) pair dpd/gen, ...")
    listed = set(re.findall(r"\(\d+\) pair (\S+?),", outputs["cpu"]))
    for style in sorted(listed & set(KK_PAIR_STYLES)):
        if f"pair {style}/kk," not in outputs["kk"]:
            failures.append(f"the KOKKOS run did not use pair_style {style}/kk")
    cpu_warnings = {line for line in outputs["cpu"].splitlines() if "WARNING" in line}
    for line in sorted({line for line in outputs["kk"].splitlines() if "WARNING" in line}
                       - cpu_warnings):
        print(f"  {name} (kk only): {line.strip()}")
    return failures


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    lmp, plugin, repository = sys.argv[1:4]
    threads = int(sys.argv[4]) if len(sys.argv) > 4 else 2
    steps = int(sys.argv[5]) if len(sys.argv) > 5 else 10
    wanted = set(sys.argv[6:])
    cases = [case for case in CASES if not wanted or case[0] in wanted]
    if wanted - {case[0] for case in CASES}:
        print(f"unknown cases: {sorted(wanted - {case[0] for case in CASES})}")
        return 2
    if lammps_date(lmp) >= STOCHASTIC_WALLS_CRASH_FROM:
        skipped = [case[0] for case in cases if case[0] in STOCHASTIC_WALLS]
        if skipped:
            print(f"not run (fix wall/reflect/stochastic crashes in this LAMMPS): {skipped}")
        cases = [case for case in cases if case[0] not in STOCHASTIC_WALLS]
    scratch = tempfile.mkdtemp(prefix="etd-examples-kk-")
    failed = 0
    for case in cases:
        failures = check_case(lmp, plugin, repository, threads, steps, case, scratch)
        print(f"{case[0]}: {'FAILED' if failures else 'ok'}")
        for failure in failures:
            print(f"  {failure}")
        failed += bool(failures)
    if failed:
        print(f"{len(cases) - failed} of {len(cases)} examples agree (logs in {scratch})")
        return 1
    shutil.rmtree(scratch)
    print(f"{len(cases)} of {len(cases)} examples agree")
    return 0


if __name__ == "__main__":
    sys.exit(main())
