#!/usr/bin/python3
"""One home per number: the speed-ups and validation ratios that README.md, doc/*.rst and the
bench/ and validation/ READMEs state must be numbers of the generated page bench/results.md
(bench/results_page.py), and one quantity must not be stated with two values. Runs without
LAMMPS: it reads text only.

What counts as a speed claim (SPEED): a number, or two joined by '-' or '/' (a range, or 1 rank /
2 ranks), directly followed by 'x' or 'times', with a word of speed or cost ('speed', 'faster',
'slower', 'throughput', 'cost', 'stock', 'shardlow', 'per time unit') within the 70 characters
before or the 50 after, and not about another quantity ('eta', 'viscosity', 'error', 'drag',
'torque', 'step', 'skin', 'thermal', 'smaller', 'larger' within the 35 characters after). Targets ('>= 2x', 'at least
1.3x') are not claims. A claim holds when each of its numbers, rounded to the decimals it is
written with, equals a number of the page rounded the same way.

Validation ratios: the ratio column of README.md's table "Published results that we do not
match" must hold, row by row, the ratio of the page's "Validation ratios" table for that result
(a row with no generated ratio leaves the column empty and points to its study).

Quantities stated in several places (QUANTITIES) must carry one value everywhere they appear.

The checks are run on the repository and, with made-up text, shown to fail (SelfCheck).
"""
import glob
import os
import re
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
PAGE = os.path.join(ROOT, "bench", "results.md")
NUM = r"\d+(?:\.\d+)?"
SPEED = re.compile(rf"(?<![\w.>=])({NUM})(?:\s*(?:-|/)\s*({NUM}))?\s*(?:x\b|times\b)")
SPEED_WORDS = re.compile(r"speed|faster|slower|throughput|cost|stock|shardlow|per time unit", re.I)
OTHER_QUANTITY = re.compile(r"\beta\b|viscosity|error|drag|torque|\bstep|skin|thermal|smaller|larger", re.I)
TARGET = re.compile(r"(>=|at least|target)\s*$", re.I)
# quantity: pattern whose first group is its value, wherever it is written
QUANTITIES = {
    "cost of a step of the implicit scheme, in stock steps":
        re.compile(rf"(?:implicit(?: scheme's)? step|step of (?:the )?(?:scheme implicit|implicit scheme)) "
                   rf"costs? (?:about )?({NUM}(?:\s*-\s*{NUM})?) stock steps", re.I),
    "seeds of the seed check":
        re.compile(r"(?:largest step|largest steps)[^.]{0,40}?re-run with (\w+) independent seeds", re.I),
}


def documents():
    paths = [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "doc", "*.rst")))
    for pattern in ("bench/README.md", "bench/*/README.md", "validation/*/README.md"):
        paths += sorted(glob.glob(os.path.join(ROOT, pattern)))
    return paths


def page_numbers(text):
    return [m.group(0) for m in re.finditer(NUM, text)]


def held(value, numbers):
    """Whether `value` (a string) is one of `numbers` rounded to value's decimals."""
    decimals = len(value.split(".")[1]) if "." in value else 0
    target = round(float(value), decimals)
    return any(abs(round(float(n), decimals) - target) < 1e-9 for n in numbers)


def speed_claims(text):
    """(line number, claim text, [numbers]) of the speed claims in `text`."""
    claims = []
    for match in SPEED.finditer(text):
        before = text[max(0, match.start() - 70):match.start()]
        after = text[match.end():match.end() + 50]
        if TARGET.search(before):
            continue
        if OTHER_QUANTITY.search(text[match.end():match.end() + 35]):
            continue
        if not (SPEED_WORDS.search(before) or SPEED_WORDS.search(after)):
            continue
        numbers = [g for g in match.groups() if g]
        claims.append((text.count("\n", 0, match.start()) + 1, match.group(0), numbers))
    return claims


def unheld_speed_claims(text, page):
    numbers = page_numbers(page)
    return [(line, claim) for line, claim, values in speed_claims(text)
            if not all(held(v, numbers) for v in values)]


def page_ratios(page):
    """The ratios of the page's validation table, by published result."""
    section = page.split("## Validation ratios", 1)[1].split("\n## ", 1)[0]
    ratios = []
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 5 and re.match(NUM, cells[2]):
            ratios.append(cells[2])
    return ratios


def unheld_readme_ratios(readme, page):
    """Ratio cells of README's published-results table that the page's validation table lacks."""
    section = readme.split("Published results that we do not match", 1)[1].split("\n## ", 1)[0]
    numbers = [n for r in page_ratios(page) for n in page_numbers(r)]
    bad = []
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 5 or cells[0] in ("published result",) or set(cells[0]) <= set("-"):
            continue
        for value in page_numbers(cells[3]):
            if not held(value, numbers):
                bad.append((cells[0][:50], cells[3]))
    return bad


def conflicting_quantities(texts):
    """{quantity: {value: [where, ...]}} for the quantities stated with more than one value."""
    found = {}
    for where, text in texts:
        for name, pattern in QUANTITIES.items():
            for match in pattern.finditer(text):
                value = re.sub(r"\s+", "", match.group(1))
                found.setdefault(name, {}).setdefault(value, []).append(where)
    return {name: values for name, values in found.items() if len(values) > 1}


class Repository(unittest.TestCase):
    def setUp(self):
        with open(PAGE) as handle:
            self.page = handle.read()
        self.texts = []
        for path in documents():
            with open(path) as handle:
                self.texts.append((os.path.relpath(path, ROOT), handle.read()))

    def test_speed_claims_are_numbers_of_the_page(self):
        bad = [(where, line, claim) for where, text in self.texts
               for line, claim in unheld_speed_claims(text, self.page)]
        self.assertEqual(bad, [], "speed-ups not on bench/results.md (link to the page instead)")

    def test_readme_validation_ratios_are_the_pages(self):
        readme = dict(self.texts)["README.md"]
        self.assertGreaterEqual(len(page_ratios(self.page)), 3)
        self.assertEqual(unheld_readme_ratios(readme, self.page), [])

    def test_one_value_per_quantity(self):
        self.assertEqual(conflicting_quantities(self.texts), {})

    def test_the_page_is_what_the_generator_writes(self):
        import subprocess
        import sys
        out = subprocess.run([sys.executable, os.path.join(ROOT, "bench", "results_page.py")],
                             capture_output=True, text=True, check=True).stdout
        self.assertEqual(out, self.page, "bench/results.md is stale: /usr/bin/python3 bench/results_page.py > bench/results.md")


class SelfCheck(unittest.TestCase):
    """The checks flag what they are meant to flag."""
    PAGE = ("## Validation ratios against published results\n\n| a | b | ratio | d | e |\n|---|---|---|---|---|\n"
            "| drag / paper | 178.36 | 1.081 +- 0.028 | x | y |\n\n## Speed-up\n\n| GW | 0.01 | imp | 2.27 | 1.41 |\n")

    def test_a_wrong_speed_up_is_flagged(self):
        text = "On GW at m = 0.01 the implicit scheme is 3.8 times faster than stock velocity-Verlet.\n"
        self.assertEqual(unheld_speed_claims(text, self.PAGE), [(1, "3.8 times")])

    def test_a_speed_up_of_the_page_passes_and_rounding_counts(self):
        text = "It runs 2.27x stock on 1 rank, 2.3 / 1.4 times stock on 1 / 2 ranks.\n"
        self.assertEqual(len(speed_claims(text)), 2)
        self.assertEqual(unheld_speed_claims(text, self.PAGE), [])
        self.assertEqual(unheld_speed_claims("It runs 2.4x stock.", self.PAGE), [(1, "2.4x")])

    def test_targets_and_other_quantities_are_not_claims(self):
        text = ("target: >= 2x fix shardlow; at least 1.3x stock. eta is 1.02 times stock's eta;"
                " a skin of four times the travel; 2.6 times smaller error than stock.\n")
        self.assertEqual(speed_claims(text), [])

    def test_a_wrong_readme_ratio_is_flagged(self):
        readme = ("Published results that we do not match\n\n| published result | paper | ours | ratio | cause |\n"
                  "|---|---|---|---|---|\n| drag | 178.36 | 192.8 | 1.08 +- 0.03 | walls |\n"
                  "| torque | 1.066 | 1.30 | 1.22 +- 0.03 | slip |\n")
        self.assertEqual(unheld_readme_ratios(readme, self.PAGE), [("torque", "1.22 +- 0.03")])

    def test_two_values_of_one_quantity_are_flagged(self):
        texts = [("a.md", "On GW the implicit step costs 3-4 stock steps."),
                 ("b.rst", "A step of scheme implicit costs 4-5 stock steps."),
                 ("c.md", "Every largest step re-run with four independent seeds.")]
        conflicts = conflicting_quantities(texts)
        self.assertEqual(list(conflicts), ["cost of a step of the implicit scheme, in stock steps"])
        self.assertEqual(conflicts["cost of a step of the implicit scheme, in stock steps"],
                         {"3-4": ["a.md"], "4-5": ["b.rst"]})


if __name__ == "__main__":
    unittest.main()
