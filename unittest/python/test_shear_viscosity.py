#!/usr/bin/python3
"""python/shear_viscosity.py on synthetic runs with known means and spreads: the grouping by
integrator and rate, the standard error, the spread pooled over groups at one rate, the ratio to
the reference and its error, and the refusal of malformed rows."""
import math
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from etddpd import shear_viscosity as sv  # noqa: E402


def write(rows):
    handle = tempfile.NamedTemporaryFile("w", suffix=".dat", delete=False)
    handle.write("# integrator dt rate seed kBT eta slope\n")
    for row in rows:
        handle.write(" ".join(str(x) for x in row) + "\n")
    handle.close()
    return handle.name


class ShearViscosity(unittest.TestCase):
    def setUp(self):
        # stock: 2.0 +- 0.1 (three runs), implicit: 2.04 +- 0.1 at rate 1; one stock run at rate 2
        self.path = write([
            ("stock", 0.0005, 1, 1, 1.0, 1.9, 1.0), ("stock", 0.0005, 1, 2, 1.0, 2.0, 1.0),
            ("stock", 0.0005, 1, 3, 1.0, 2.1, 1.0),
            ("implicit", 0.003, 1, 1, 0.99, 1.94, 0.98), ("implicit", 0.003, 1, 2, 0.99, 2.04, 1.0),
            ("implicit", 0.003, 1, 3, 0.99, 2.14, 1.02),
            ("stock", 0.0005, 2, 1, 1.0, 2.0, 1.0),
        ])

    def tearDown(self):
        os.unlink(self.path)

    def test_groups_means_and_errors(self):
        table = sv.summarise(sv.read_results(self.path))
        stock = table[("stock", 0.0005)][1.0]
        self.assertEqual(stock["n"], 3)
        self.assertAlmostEqual(stock["eta"], 2.0)
        self.assertAlmostEqual(stock["spread"], 0.1)
        self.assertAlmostEqual(stock["sem"], 0.1 / math.sqrt(3))
        self.assertAlmostEqual(table[("implicit", 0.003)][1.0]["slope"], 1.0)
        self.assertTrue(math.isnan(table[("stock", 0.0005)][2.0]["spread"]))    # one run

    def test_pooled_spread_and_ratio(self):
        table = sv.summarise(sv.read_results(self.path))
        pooled = sv.pooled_spread(table)
        self.assertAlmostEqual(pooled[1.0][0], 0.1)
        self.assertEqual(pooled[1.0][1], 4)
        self.assertNotIn(2.0, pooled)    # no degree of freedom at rate 2
        r, err = sv.ratio(table[("implicit", 0.003)][1.0], table[("stock", 0.0005)][1.0], 0.1)
        self.assertAlmostEqual(r, 1.02)
        expected = 1.02 * 0.1 * math.hypot(1 / (2.04 * math.sqrt(3)), 1 / (2.0 * math.sqrt(3)))
        self.assertAlmostEqual(err, expected)

    def test_markdown_carries_the_ratio(self):
        table = sv.summarise(sv.read_results(self.path))
        text = sv.markdown(table, ["stock"])
        self.assertIn("1.020 +-", text)

    def test_refuses_a_short_row(self):
        bad = write([("stock", 0.0005, 1, 1, 1.0, 2.0)])
        try:
            with self.assertRaises(ValueError):
                sv.read_results(bad)
        finally:
            os.unlink(bad)


if __name__ == "__main__":
    unittest.main()
