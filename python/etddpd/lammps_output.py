"""Readers of LAMMPS's output files, one per format.

  read_ave_time(path)         fix ave/time, scalar mode                 -> Table
  read_ave_time_vector(path)  fix ave/time, mode vector                 -> Blocks
  read_ave_chunk(path)        fix ave/chunk                             -> Blocks
  read_ave_correlate(path)    fix ave/correlate                         -> Blocks
  read_thermo(path)           the thermo tables of a log file           -> [Table, ...]
  thermo_tables(text)         the same from the text of a log
  loop_times(text)            the 'Loop time of ...' lines of a log     -> [LoopTime, ...]
  read_dump(path)             a dump custom/atom file                   -> Blocks (one per frame)

Table: path, names (the column names of the header) and data[row, column]. Blocks: path, names,
steps (the time step of each block) and data[block, row, column]; a block is the set of rows
written at one output step (the chunks of ave/chunk, the rows of mode vector, the time windows of
one time origin of ave/correlate, the atoms of a dump frame). A last block cut short (a run
still writing) is left out. Both look columns up by name: column(*names) gives the first of the
names that exists and fails with the file's column names when none does, get(*names) gives None
then. names is None when the header does not name every column (a file written by hand): its
columns are then reached by position only.

A file that is not of the format asked for raises LammpsOutputError (a ValueError) naming it.
"""
import re
from typing import NamedTuple

import numpy as np


class LammpsOutputError(ValueError):
    """A file that is not the LAMMPS output it was read as."""


def _index(path, names, candidates, required):
    for name in candidates:
        if names and name in names:
            return names.index(name)
    if required:
        listed = ' '.join(names) if names else 'the header does not name them'
        raise LammpsOutputError(f'{path}: no column {" or ".join(candidates)} (columns: {listed})')
    return None


class Table(NamedTuple):
    """Rows of numbers under one header line: data[row, column]."""
    path: str
    names: list
    data: np.ndarray

    def column(self, *candidates):
        return self.data[:, _index(self.path, self.names, candidates, True)]

    def get(self, *candidates):
        k = _index(self.path, self.names, candidates, False)
        return None if k is None else self.data[:, k]


class Blocks(NamedTuple):
    """Equal blocks of rows, one per output step: data[block, row, column]."""
    path: str
    names: list
    steps: np.ndarray
    data: np.ndarray

    def column(self, *candidates):
        return self.data[:, :, _index(self.path, self.names, candidates, True)]

    def get(self, *candidates):
        k = _index(self.path, self.names, candidates, False)
        return None if k is None else self.data[:, :, k]


class LoopTime(NamedTuple):
    seconds: float
    procs: int
    steps: int
    atoms: int


def _numbers(path, what, line):
    try:
        return [float(w) for w in line.split()]
    except ValueError:
        raise LammpsOutputError(f'{path} is not a {what} file: {line.strip()!r}') from None


def _checked_names(names, ncolumns):
    """The header's names when they name every column, else None: a column is then found by
    its position only, never by a name that may belong to another."""
    return names if names is not None and len(names) == ncolumns else None


def read_ave_time(path):
    """A fix ave/time file in scalar mode: one row per output step under the header
    '# TimeStep name ...' (TimeStep is the first column)."""
    what = 'fix ave/time'
    names, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith('#'):
                words = line[1:].split()
                if words and words[0] == 'TimeStep':
                    names = words
            elif line.strip():
                rows.append(_numbers(path, what, line))
    if not rows:
        raise LammpsOutputError(f'{path} is not a {what} file with data')
    try:
        data = np.array(rows)
    except ValueError:
        raise LammpsOutputError(f'{path}: rows of different lengths: not a {what} file') from None
    if data.ndim != 2:
        raise LammpsOutputError(f'{path}: rows of different lengths: not a {what} file')
    return Table(path, _checked_names(names, data.shape[1]), data)


def _take_rows(lines, count, path, what):
    """The next count rows of numbers from the iterator lines; None where the file ends first
    (a block or frame still being written)."""
    rows = []
    for row in lines:
        rows.append(_numbers(path, what, row))
        if len(rows) == count:
            break
    return None if len(rows) < count else rows


def _stacked(blocks, path, what, mismatch):
    """data[block, row, column] of blocks of rows; an error naming the mismatch where they differ
    in shape."""
    if not blocks:
        raise LammpsOutputError(f'{path} is not a {what} file with data')
    try:
        data = np.array(blocks, dtype=float)
    except ValueError:
        data = None
    if data is None or data.ndim != 3:
        raise LammpsOutputError(f'{path}: {mismatch} ({what})')
    return data


def _read_blocks(path, what):
    """Blocks of a file of '<step> <rows> ...' lines each followed by that many rows; the
    header's last comment line names the columns (LAMMPS writes it last)."""
    header, steps, blocks = [], [], []
    with open(path) as f:
        lines = (line for line in f if line.strip())
        for line in lines:
            if line.startswith('#'):
                if not steps:
                    header.append(line[1:].split())
                continue
            words = line.split()
            try:
                step, nrows = int(words[0]), int(words[1])
            except (ValueError, IndexError):
                raise LammpsOutputError(f'{path} is not a {what} file: expected '
                                        f'"step rows ...", got {line.strip()!r}') from None
            rows = _take_rows(lines, nrows, path, what)
            if rows is None:
                break
            steps.append(step)
            blocks.append(rows)
    data = _stacked(blocks, path, what, 'blocks or rows of different lengths')
    names = header[-1] if header else None
    return Blocks(path, _checked_names(names, data.shape[2]),
                  np.array(steps), data)


def read_ave_chunk(path):
    """A fix ave/chunk file: per block '<step> <chunks> <total count>', then one row per chunk
    under the header '# Chunk Coord1 ... Ncount name ...'."""
    return _read_blocks(path, 'fix ave/chunk')


def read_ave_time_vector(path):
    """A fix ave/time file in mode vector: per block '<step> <rows>', then the rows under the
    header '# Row name ...'."""
    return _read_blocks(path, 'fix ave/time (mode vector)')


def read_ave_correlate(path):
    """A fix ave/correlate file: per time origin '<step> <time windows>', then one row per time
    window under the header '# Index TimeDelta Ncount name ...'."""
    return _read_blocks(path, 'fix ave/correlate')


def thermo_tables(text, path='log'):
    """The thermo tables of the text of a LAMMPS log: the rows between each 'Step ...' header and
    its 'Loop time' line that have one number per column (warnings and the like are skipped)."""
    tables = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].split()[:1] == ['Step']:
            names = lines[i].split()
            rows = []
            i += 1
            while i < len(lines) and not lines[i].startswith('Loop time'):
                fields = lines[i].split()
                if len(fields) == len(names):
                    try:
                        rows.append([float(x) for x in fields])
                    except ValueError:
                        pass
                i += 1
            tables.append(Table(path, names, np.array(rows).reshape(len(rows), len(names))))
        i += 1
    return tables


def read_thermo(path):
    """The thermo tables of a LAMMPS log file, one per run."""
    with open(path) as f:
        return thermo_tables(f.read(), path)


_LOOP = re.compile(r'Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms')


def loop_times(text):
    """The 'Loop time of S on P procs for N steps with A atoms' lines of a log, in order."""
    return [LoopTime(float(s), int(p), int(n), int(a)) for s, p, n, a in _LOOP.findall(text)]


_SECTION = re.compile(r'^(Pair|Bond|Kspace|Neigh|Comm|Output|Modify|Other)\s*\|(.*)$', re.M)


def timing_breakdowns(text):
    """LAMMPS's 'MPI task timing breakdown' of each run of a log, in order: {section: average
    seconds over the ranks} (Pair, Neigh, Comm, Output, Modify, Other, ...)."""
    out = []
    for block in text.split('MPI task timing breakdown:')[1:]:
        sections = {}
        # the table ends at the first blank line; its second column is the average over ranks
        # (the only one filled for Other)
        for name, rest in _SECTION.findall(block.split('\n\n')[0]):
            try:
                sections[name] = float(rest.split('|')[1])
            except (ValueError, IndexError):
                continue
        out.append(sections)
    return out


def read_dump(path):
    """The frames of a dump file (custom or atom style): Blocks with the names of its
    'ITEM: ATOMS' line, the time steps and data[frame, atom, column]."""
    what = 'dump'
    names, steps, frames = None, [], []
    with open(path) as f:
        lines = iter(f)
        for line in lines:
            if line.startswith('ITEM: TIMESTEP'):
                steps.append(int(next(lines)))
            elif line.startswith('ITEM: NUMBER OF ATOMS'):
                natoms = int(next(lines))
            elif line.startswith('ITEM: ATOMS'):
                names = line.split()[2:]
                rows = _take_rows(lines, natoms, path, what)
                if rows is None:
                    break
                frames.append(rows)
    data = _stacked(frames, path, what, 'frames of different sizes')
    return Blocks(path, _checked_names(names, data.shape[2]),
                  np.array(steps[:len(frames)]), data)
