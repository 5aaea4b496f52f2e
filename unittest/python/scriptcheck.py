"""Shared by the script-style Python tests (test_fpm_analysis.py, test_fpm_torque_field.py):
check() records a comparison within a tolerance, finish() reports and exits 1 on any mismatch;
write_ave_chunk() writes a synthetic one-block fix ave/chunk file."""
import sys

failures = []


def check(name, value, expected, tol):
    ok = abs(value - expected) <= tol
    print(f'{"ok  " if ok else "FAIL"} {name}: {value:.6g} (expected {expected:.6g} +- {tol:.2g})')
    if not ok:
        failures.append(name)


def finish():
    print('FAILED: ' + ', '.join(failures) if failures else 'all passed')
    sys.exit(1 if failures else 0)


def write_ave_chunk(path, names, rows, step=1000, total=1):
    """One block: the header naming the columns after 'Chunk' (names), then each row numbered
    from 1 (rows: sequences of numbers, written with 12 significant digits)."""
    with open(path, 'w') as f:
        f.write('# Chunk-averaged data\n# Timestep Number-of-chunks Total-count\n'
                f'# Chunk {" ".join(names)}\n{step} {len(rows)} {total}\n')
        for k, row in enumerate(rows):
            f.write(f'{k + 1} ' + ' '.join(f'{v:.12g}' for v in row) + '\n')
