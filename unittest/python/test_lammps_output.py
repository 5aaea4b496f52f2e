#!/usr/bin/python3
"""The readers of python/etddpd/lammps_output.py on small synthetic files in the layouts LAMMPS
writes (fix ave/time in scalar and vector mode, fix ave/chunk, fix ave/correlate, the thermo
tables and loop times of a log, a dump), and on the committed output of the examples."""
import os
import shutil
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "python"))
from etddpd import lammps_output as lo  # noqa: E402
from etddpd import study_records  # noqa: E402

AVE_TIME = """# Time-averaged data for fix drag
# TimeStep c_f[1] c_f[2] v_u
100 1.5 -2 0.25
200 2.5 -3 0.5
300 3.5 -4e-1 0.75
"""

AVE_TIME_VECTOR = """# Time-averaged data for fix rdf_out
# TimeStep Number-of-rows
# Row c_rdf[1] c_rdf[2]
1000 3
1 0.5 0
2 1.5 1.25
3 2.5 1
2000 3
1 0.5 0
2 1.5 1.75
3 2.5 1
3000 3
1 0.5 0
"""

AVE_CHUNK = """# Chunk-averaged data for fix profile and group fluid
# Timestep Number-of-chunks Total-count
# Chunk Coord1 Ncount vx density/number
4000 2 100
  1 -0.5 40 -1.5 3.9
  2 0.5 60 1.5 4.1

6000 2 100
  1 -0.5 50 -2.5 4
  2 0.5 50 2.5 4
"""

AVE_CORRELATE = """# Time-correlated data for fix tcaf
# Timestep Number-of-time-windows
# Index TimeDelta Ncount c_J[1]*c_J[1] c_J[2]*c_J[2]
5130 3
1 0 1026 4 2
2 5 1025 3 1.5
3 10 1024 2 1
10260 3
1 0 1026 8 4
2 5 1025 6 3
3 10 1024 4 2
"""

LOG = """LAMMPS (29 Aug 2024)
units lj
Step Temp E_pair Press
         0   1.5   -2.0   3.0
       100   1.1   -2.5   2.5
WARNING: a warning inside the table (src/thermo.cpp:123)
       200   1.0   -2.6   2.4
Loop time of 1.25 on 2 procs for 200 steps with 4000 atoms

Performance: 1.0 tau/day
   Step          Temp          c_t
       200   1.0   0.9
       300   0.98  0.95
Loop time of 0.5 on 2 procs for 100 steps with 4000 atoms
Total wall time: 0:00:02
"""

DUMP = """ITEM: TIMESTEP
0
ITEM: NUMBER OF ATOMS
2
ITEM: BOX BOUNDS pp pp pp
0 10
0 10
0 10
ITEM: ATOMS id xu yu zu
1 0.0 0.0 0.0
2 1.0 2.0 3.0
ITEM: TIMESTEP
50
ITEM: NUMBER OF ATOMS
2
ITEM: BOX BOUNDS pp pp pp
0 10
0 10
0 10
ITEM: ATOMS id xu yu zu
1 0.5 0.0 -0.5
2 1.5 2.0 3.5
ITEM: TIMESTEP
100
ITEM: NUMBER OF ATOMS
2
ITEM: BOX BOUNDS pp pp pp
0 10
0 10
0 10
ITEM: ATOMS id xu yu zu
1 0.75 0.0 -0.5
"""


class Files(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def write(self, name, text):
        path = os.path.join(self.dir.name, name)
        with open(path, "w") as f:
            f.write(text)
        return path


class AveTime(Files):
    def test_scalar_mode(self):
        table = lo.read_ave_time(self.write("drag", AVE_TIME))
        self.assertEqual(table.names, ["TimeStep", "c_f[1]", "c_f[2]", "v_u"])
        self.assertEqual(table.data.shape, (3, 4))
        np.testing.assert_array_equal(table.column("TimeStep"), [100, 200, 300])
        np.testing.assert_array_equal(table.column("c_f[2]"), [-2, -3, -0.4])
        # column: the first of the names that exists; get: None when none does
        np.testing.assert_array_equal(table.column("c_g[1]", "c_f[1]"), [1.5, 2.5, 3.5])
        self.assertIsNone(table.get("c_g[1]"))
        with self.assertRaises(lo.LammpsOutputError) as caught:
            table.column("c_g[1]")
        self.assertIn("no column c_g[1]", str(caught.exception))
        self.assertIn("c_f[1] c_f[2] v_u", str(caught.exception))

    def test_a_header_that_does_not_name_every_column_gives_no_names(self):
        table = lo.read_ave_time(self.write("drag", AVE_TIME.replace(" v_u", "")))
        self.assertIsNone(table.names)
        self.assertEqual(table.data.shape, (3, 4))
        with self.assertRaises(lo.LammpsOutputError):
            table.column("c_f[1]")

    def test_other_files_are_refused(self):
        for text, message in (("nothing here\n", "not a fix ave/time file: 'nothing here'"),
                              ("# TimeStep v_a\n", "not a fix ave/time file with data"),
                              (AVE_CHUNK, "rows of different lengths"),
                              (AVE_TIME + "400 1 2\n", "rows of different lengths")):
            with self.assertRaises(lo.LammpsOutputError) as caught:
                lo.read_ave_time(self.write("bad", text))
            self.assertIn(message, str(caught.exception))
            self.assertIsInstance(caught.exception, ValueError)

    def test_vector_mode(self):
        blocks = lo.read_ave_time_vector(self.write("rdf", AVE_TIME_VECTOR))
        self.assertEqual(blocks.names, ["Row", "c_rdf[1]", "c_rdf[2]"])
        # the third block is cut short (a run still writing): left out
        np.testing.assert_array_equal(blocks.steps, [1000, 2000])
        self.assertEqual(blocks.data.shape, (2, 3, 3))
        np.testing.assert_array_equal(blocks.column("c_rdf[2]"), [[0, 1.25, 1], [0, 1.75, 1]])


class AveChunk(Files):
    def test_blocks(self):
        blocks = lo.read_ave_chunk(self.write("profile", AVE_CHUNK))
        self.assertEqual(blocks.names, ["Chunk", "Coord1", "Ncount", "vx", "density/number"])
        np.testing.assert_array_equal(blocks.steps, [4000, 6000])
        self.assertEqual(blocks.data.shape, (2, 2, 5))
        np.testing.assert_array_equal(blocks.column("vx"), [[-1.5, 1.5], [-2.5, 2.5]])
        np.testing.assert_array_equal(blocks.column("Coord1")[0], [-0.5, 0.5])
        self.assertIsNone(blocks.get("temp"))

    def test_a_block_cut_short_is_left_out(self):
        blocks = lo.read_ave_chunk(self.write("profile", AVE_CHUNK + "8000 2 100\n  1 -0.5 40 -1 4\n"))
        np.testing.assert_array_equal(blocks.steps, [4000, 6000])
        blocks = lo.read_ave_chunk(self.write("profile", AVE_CHUNK + "8000 2 100\n"))
        np.testing.assert_array_equal(blocks.steps, [4000, 6000])

    def test_other_files_are_refused(self):
        for text, message in ((AVE_TIME, 'expected "step rows ...", got \'100 1.5 -2 0.25\''),
                              ("# Chunk Coord1\n", "not a fix ave/chunk file with data"),
                              (AVE_CHUNK + "8000 1 50\n  1 0 50 0 4\n", "blocks or rows of different lengths"),
                              (AVE_CHUNK.replace("  2 0.5 50 2.5 4", "  2 0.5 50 2.5"),
                               "blocks or rows of different lengths")):
            with self.assertRaises(lo.LammpsOutputError) as caught:
                lo.read_ave_chunk(self.write("bad", text))
            self.assertIn(message, str(caught.exception))


class AveCorrelate(Files):
    def test_blocks_per_time_origin(self):
        blocks = lo.read_ave_correlate(self.write("tcaf", AVE_CORRELATE))
        self.assertEqual(blocks.names[:3], ["Index", "TimeDelta", "Ncount"])
        np.testing.assert_array_equal(blocks.steps, [5130, 10260])
        np.testing.assert_array_equal(blocks.column("TimeDelta")[1], [0, 5, 10])
        np.testing.assert_array_equal(blocks.column("c_J[1]*c_J[1]"), [[4, 3, 2], [8, 6, 4]])
        np.testing.assert_array_equal(blocks.column("Ncount")[0], [1026, 1025, 1024])


class Log(Files):
    def test_thermo_tables(self):
        tables = lo.read_thermo(self.write("log.lammps", LOG))
        self.assertEqual(len(tables), 2)
        first, second = tables
        self.assertEqual(first.names, ["Step", "Temp", "E_pair", "Press"])
        # the warning line is skipped
        np.testing.assert_array_equal(first.column("Step"), [0, 100, 200])
        np.testing.assert_array_equal(first.column("Temp"), [1.5, 1.1, 1.0])
        self.assertEqual(second.names, ["Step", "Temp", "c_t"])
        np.testing.assert_array_equal(second.column("c_t"), [0.9, 0.95])
        self.assertEqual(lo.thermo_tables(LOG)[1].data.shape, (2, 3))

    def test_a_run_cut_short_has_its_rows(self):
        text = LOG[:LOG.index("Loop time of 0.5")]
        tables = lo.thermo_tables(text)
        np.testing.assert_array_equal(tables[-1].column("Step"), [200, 300])
        self.assertEqual(lo.thermo_tables("no thermo here\n"), [])

    def test_loop_times(self):
        loops = lo.loop_times(LOG)
        self.assertEqual(loops, [lo.LoopTime(1.25, 2, 200, 4000), lo.LoopTime(0.5, 2, 100, 4000)])
        self.assertEqual(loops[-1].steps * loops[-1].atoms / loops[-1].seconds, 800000.0)


    def test_timing_breakdowns(self):
        text = """Loop time of 5.27 on 2 procs for 1000 steps with 3000 atoms

MPI task timing breakdown:
Section |  min time  |  avg time  |  max time  |%varavg| %total
---------------------------------------------------------------
Pair    | 0.44       | 0.45       | 0.46       |   0.0 |  8.48
Neigh   | 2.1        | 2.2        | 2.3        |   0.0 | 41.16
Comm    | 0.12       | 0.13       | 0.14       |   0.0 |  2.43
Output  | 0.0001     | 0.0001     | 0.0001     |   0.0 |  0.00
Modify  | 2.5        | 2.6        | 2.7        |   0.0 | 47.52
Other   |            | 0.022      |            |       |  0.42

Nlocal:        1500.0 ave        1500 max        1500 min
"""
        sections = lo.timing_breakdowns("no breakdown\n" + text + text.replace("0.45 ", "0.5  "))
        self.assertEqual(len(sections), 2)
        self.assertEqual(sections[0], {"Pair": 0.45, "Neigh": 2.2, "Comm": 0.13, "Output": 0.0001,
                                       "Modify": 2.6, "Other": 0.022})
        self.assertEqual(sections[1]["Pair"], 0.5)
        self.assertEqual(lo.timing_breakdowns(LOG), [])


class Dump(Files):
    def test_frames(self):
        frames = lo.read_dump(self.write("track", DUMP))
        self.assertEqual(frames.names, ["id", "xu", "yu", "zu"])
        # the third frame is cut short: left out
        np.testing.assert_array_equal(frames.steps, [0, 50])
        self.assertEqual(frames.data.shape, (2, 2, 4))
        np.testing.assert_array_equal(frames.column("zu"), [[0, 3], [-0.5, 3.5]])


class CommittedFiles(unittest.TestCase):
    """Output LAMMPS wrote for the examples: every header names every column. A study that keeps
    its files in results/records.json (python/etddpd/study_records.py) has them read from there."""

    def path(self, name):
        path = os.path.join(ROOT, name)
        if os.path.exists(path):
            return path
        results, _, relative = name.partition("/results/")
        records = study_records.read(os.path.join(ROOT, results, "results", "records.json"))
        if relative not in records:
            self.skipTest(f"{name} is not in this checkout")
        directory = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, directory)
        path = os.path.join(directory, os.path.basename(relative))
        with open(path, "w") as handle:
            handle.write(records[relative])
        return path

    def test_ave_time(self):
        table = lo.read_ave_time(self.path("validation/channel-sphere/results/drag.U0.9"))
        self.assertEqual(table.names[:5], ["TimeStep", "c_fsphere[1]", "c_fsphere[2]", "c_fsphere[3]", "c_vfluid"])
        table = lo.read_ave_time(self.path("validation/sphere-couette/results/drag.sphere-couette"))
        self.assertEqual(table.data.shape[1], 11)

    def test_ave_time_vector(self):
        blocks = lo.read_ave_time_vector(self.path("validation/sphere-couette/results/rdf.sphere-couette"))
        self.assertEqual(blocks.names, ["Row"] + [f"c_rdf[{k}]" for k in range(1, 6)])
        self.assertEqual(blocks.data.shape[1:], (60, 6))

    def test_ave_chunk(self):
        blocks = lo.read_ave_chunk(self.path("validation/flows/results/profile.couette"))
        self.assertEqual(blocks.names[-1], "density/number")
        self.assertEqual(blocks.data.shape[1:], (120, 11))
        self.assertEqual(len(blocks.steps), blocks.data.shape[0])
        blocks = lo.read_ave_chunk(self.path("validation/channel-sphere/results/velocity_profile.d33_H1_f0.03"))
        self.assertEqual(blocks.names, ["Chunk", "Coord1", "Coord2", "Ncount", "vx"])

    def test_thermo(self):
        tables = lo.read_thermo(self.path("examples/quickstart/log.quickstart.g++.1"))
        self.assertIn("Temp", tables[-1].names)
        self.assertGreater(len(tables[-1].data), 1)
        with open(self.path("examples/quickstart/log.quickstart.g++.1")) as f:
            self.assertEqual(len(lo.loop_times(f.read())), len(tables))


if __name__ == "__main__":
    unittest.main()
