#!/usr/bin/python3
"""One home per number: the speed-ups and validation ratios that README.md, doc/*.rst and the
bench/ and validation/ READMEs state must be numbers of the generated page bench/results.md
(bench/results_page.py), and one quantity must not be stated with two values. Runs without
LAMMPS: it reads text only.

What counts as a speed claim (SPEED): a number, or two joined by '-' or '/' (a range, or 1 rank /
2 ranks), directly followed by 'x' or 'times', with a word of speed or cost ('speed', 'faster',
'slower', 'throughput', 'cost', 'stock', 'shardlow', 'per time unit') within the 70 characters
before or the 50 after, and not about another quantity ('eta', 'viscosity', 'error', 'drag',
'torque', 'step', 'skin', 'thermal', 'smaller', 'larger' within the 35 characters after). Targets
('>= 2x', 'at least 1.3x') are not claims.

A claim must name its quantity, and holds only against the page's entries for that quantity
(claim_quantity, page_entries):
- pair throughput ('throughput' or 'atom-steps' next to it): the "ratio to stock dpd + nve" cells
  of the throughput table for the style the claim's paragraph names last before it (dpd/gen or
  dpd/fpm, with s = 2, 1/2 or 0.4244 and the integrator, `fix etd` or `scheme implicit`, where
  named; fix nve otherwise) and the ranks where named ('1 rank', '2 ranks', '1 / 2 ranks', '1 and 2 ranks');
- the cost of a step ('stock step' after it): the "step / stock step" cells;
- the speed-up at equal accuracy over fix shardlow ('shardlow' after it) or over stock
  velocity-Verlet (otherwise): the "speed-up over stock" / "over shardlow" cells;
  for these two, of the rows of the fluid (GW, P, HS, S2), mass (m = ...), integrator
  (implicit, diagonal, shardlow, stock) and ranks that the claim's sentence names.
A claim holds when each of its numbers, rounded to the decimals it is written with, equals one of
those cells rounded the same way. A claim whose quantity is not recognised, or whose style is not
named, fails: write the quantity out or link to the page instead.

Validation ratios: the ratio column of README.md's table "Published results that we do not
match" must hold, row by row, the ratios of the page's "Validation ratios" rows for that result
(README_RATIO_ROWS maps each README row to its page rows; a README row with a ratio but no entry
there fails), in order, value and error each rounded to the decimals written (a row with no
generated ratio leaves the column empty and points to its study).

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


# README's published-results rows (by how the row starts) -> the page's validation rows (by how
# they start), in the order the README cell lists the ratios
README_RATIO_ROWS = {
    "56-particle sphere, free flow": ["56-particle sphere, free flow"],
    "the same, C_D at Re about 6": ["the same sphere, C_D at Re about 6"],
    "dpd/fpm two spheres": ["dpd/fpm two spheres at l = 1,", "dpd/fpm two spheres at l = 1.5,",
                            "dpd/fpm two spheres at l = 2,"],
    "dpd/fpm spun sphere": ["dpd/fpm spun sphere"],
    "one-particle colloid in Couette flow": ["one-particle colloid in Couette flow"],
}
FLUIDS = re.compile(r"\b(GW|HS|S2|P)\b")
INTEGRATORS = (("implicit", "imp"), ("diagonal", "diag"), ("shardlow", "shardlow"), ("stock", "stock"))


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
    return [(line, claim, numbers) for line, claim, numbers, _ in _speed_matches(text)]


def _speed_matches(text):
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
        claims.append((text.count("\n", 0, match.start()) + 1, match.group(0), numbers, match))
    return claims


def page_tables(page):
    """(heading, header cells, rows of cells) of each markdown table of the page."""
    tables, heading, lines = [], "", page.splitlines()
    for i, line in enumerate(lines):
        if line.startswith("#"):
            heading = line
        elif (line.startswith("|") and i + 1 < len(lines) and re.match(r"^\|[-| ]+\|$", lines[i + 1])
              and (i == 0 or not lines[i - 1].startswith("|"))):
            header = [c.strip() for c in line.strip().strip("|").split("|")]
            rows = []
            for row in lines[i + 2:]:
                if not row.startswith("|"):
                    break
                rows.append([c.strip() for c in row.strip().strip("|").split("|")])
            tables.append((heading, header, rows))
    return tables


def page_entries(page):
    """{quantity: [(labels, value)]}: the cells of the page that a speed claim can be checked
    against, each with what identifies its row."""
    entries = {"throughput": [], "step cost": [], "speed-up over stock": [], "speed-up over shardlow": []}
    for heading, header, rows in page_tables(page):
        ranks = re.search(r"(\d+) rank", heading)
        columns = {"ratio to stock dpd + nve": "throughput", "step / stock step": "step cost",
                   "speed-up over stock": "speed-up over stock", "over shardlow": "speed-up over shardlow"}
        for column, quantity in columns.items():
            if column not in header:
                continue
            index = header.index(column)
            for row in rows:
                if len(row) != len(header):
                    continue
                if quantity == "throughput":
                    labels = {"style": row[0], "ranks": row[1]}
                else:
                    labels = {"fluid": row[0], "m": row[1], "integrator": row[2],
                              "ranks": ranks.group(1) if ranks else "1"}
                entries[quantity].append((labels, row[index]))
    return entries


def _paragraph_before(text, start):
    """The text from the start of the paragraph (or table row) holding `start` up to it."""
    line_start = text.rfind("\n", 0, start) + 1
    if text.startswith("|", line_start):
        return text[line_start:start]
    blank = text.rfind("\n\n", 0, start)
    return text[blank + 2 if blank >= 0 else 0:start]


def _ranks(context):
    found = re.search(r"((?:\d\s*(?:/|,|and|or)\s*)*\d)\s+ranks?\b", context)
    return set(re.findall(r"\d", found.group(1))) if found else None


def throughput_style(paragraph, after):
    """The throughput table's style label the claim is about, or None when no style is named."""
    styles = list(re.finditer(r"dpd/(gen|fpm)", paragraph))
    if not styles:
        return None
    style = "dpd/" + styles[-1].group(1)
    context = paragraph[styles[-1].start():] + after
    exponent = re.search(r"\bs\s*=\s*(0\.4244|1/2|2)\b", context)
    exponent = exponent.group(1) if exponent else ("1/2" if style == "dpd/fpm" else "2")
    if re.search(r"scheme implicit", context):
        integrator = "etd scheme implicit"
    elif re.search(r"fix etd|\+ etd\b", context):
        integrator = "etd"
    else:
        integrator = "nve/sphere" if style == "dpd/fpm" else "nve"
    return f"{style} s={exponent} + {integrator}"


def claim_quantity(text, match):
    """(quantity, {label: allowed values}) of the speed claim `match`, or None if unrecognised."""
    before = text[max(0, match.start() - 70):match.start()]
    after = text[match.end():match.end() + 50]
    paragraph = _paragraph_before(text, match.start())
    sentence = re.split(r"(?<=[.;])\s", paragraph)[-1] + text[match.end():match.end() + 80].split(". ")[0]
    ranks = _ranks(sentence)
    if re.search(r"throughput|atom-steps", before + after, re.I):
        style = throughput_style(paragraph, after)
        if style is None:
            return None
        labels = {"style": {style}}
        if ranks:
            labels["ranks"] = ranks
        return "throughput", labels
    if re.search(r"stock steps?\b", after[:20], re.I):
        quantity = "step cost"
    elif re.search(r"shardlow", after, re.I):
        quantity = "speed-up over shardlow"
    elif re.search(r"stock|velocity-verlet|faster|speed-up|per time unit", before + after, re.I):
        quantity = "speed-up over stock"
    else:
        return None
    labels = {}
    fluid = FLUIDS.search(sentence)
    if fluid:
        labels["fluid"] = {fluid.group(1)}
    mass = re.search(r"\bm\s*=\s*(\d+(?:\.\d+)?)", sentence)
    if mass:
        labels["m"] = {mass.group(1)}
    for word, short in INTEGRATORS:
        if re.search(word, before + text[match.end():match.end() + 30].split(" than ")[0], re.I) and short != "stock":
            labels["integrator"] = {short}
            break
    if ranks:
        labels["ranks"] = ranks
    if "fluid" not in labels and "m" not in labels:
        return None
    return quantity, labels


def _integrator_matches(name, allowed):
    short = {"stock + nve": "stock", "etd (diagonal)": "diag", "etd implicit": "imp",
             "etd implicit, v": "impv", "shardlow": "shardlow"}
    name = name.rstrip("*")
    return name in allowed or any(name.startswith(k) and v in allowed for k, v in short.items())


def claim_values(entries, quantity, labels):
    """The page's cells for `quantity` whose row matches `labels`."""
    values = []
    for row, value in entries[quantity]:
        ok = True
        for key, allowed in labels.items():
            cell = row.get(key, "")
            if key == "style":
                ok &= cell.split(" (")[0] in allowed
            elif key == "integrator":
                ok &= _integrator_matches(cell, allowed)
            else:
                ok &= cell in allowed
        if ok:
            values.append(value)
    return values


def unheld_speed_claims(text, page):
    """(line, claim) of the speed claims whose quantity is not recognised or whose numbers are not
    the page's cells for that quantity."""
    entries = page_entries(page)
    bad = []
    for line, claim, values, match in _speed_matches(text):
        identified = claim_quantity(text, match)
        if identified is None:
            bad.append((line, claim))
            continue
        numbers = [n for v in claim_values(entries, *identified) for n in page_numbers(v)]
        if not numbers or not all(held(v, numbers) for v in values):
            bad.append((line, claim))
    return bad


def page_ratios(page):
    """(published result, ratio) of the page's validation table."""
    section = page.split("## Validation ratios", 1)[1].split("\n## ", 1)[0]
    ratios = []
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 5 and re.match(NUM, cells[2]):
            ratios.append((cells[0], cells[2]))
    return ratios


def ratio_held(stated, generated):
    """Whether a stated ratio ('1.08 +- 0.03' or '1.038') is the generated one ('1.081 +- 0.028'),
    value and error each rounded to the decimals stated."""
    stated, generated = page_numbers(stated), page_numbers(generated)
    return 0 < len(stated) <= len(generated) and all(held(s, [g]) for s, g in zip(stated, generated))


def unheld_readme_ratios(readme, page):
    """(row, ratio cell) of README's published-results table whose ratios are not the page's ratios
    of the same results (README_RATIO_ROWS)."""
    section = readme.split("Published results that we do not match", 1)[1].split("\n## ", 1)[0]
    generated = page_ratios(page)
    bad = []
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 5 or cells[0] in ("published result",) or set(cells[0]) <= set("-"):
            continue
        if not page_numbers(cells[3]):
            continue
        keys = [k for k in README_RATIO_ROWS if cells[0].startswith(k)]
        stated = [r.strip() for r in cells[3].split(",")]
        if len(keys) != 1:
            bad.append((cells[0][:50], cells[3]))
            continue
        wanted = []
        for prefix in README_RATIO_ROWS[keys[0]]:
            wanted += [ratio for name, ratio in generated if name.startswith(prefix)][:1]
        if len(wanted) != len(stated) or not all(ratio_held(s, g) for s, g in zip(stated, wanted)):
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
        self.assertGreaterEqual(len(page_ratios(self.page)), 7)
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
            "| one-particle colloid in Couette flow, drag | 178.36 | 1.081 +- 0.028 | x | y |\n"
            "| dpd/fpm two spheres at l = 1, torque | 1.066 | 1.22 +- 0.03 | x | y |\n"
            "| dpd/fpm two spheres at l = 1.5, torque | 0.974 | 0.76 +- 0.05 | x | y |\n"
            "| dpd/fpm two spheres at l = 2, torque | 0.969 | 0.89 +- 0.12 | x | y |\n\n"
            "## Speed-up\n\n### Largest step, 1 rank(s)\n\n"
            "| fluid | m | integrator | largest dt | speed-up over stock | over shardlow |\n|---|---|---|---|---|---|\n"
            "| GW | 0.01 | etd implicit | 0.005* | 2.27 | 1.41 |\n| P | 0.01 | etd implicit | 0.005 | 3.81 | |\n\n"
            "### Largest step, 2 rank(s)\n\n"
            "| fluid | m | integrator | largest dt | speed-up over stock | over shardlow |\n|---|---|---|---|---|---|\n"
            "| GW | 0.01 | etd implicit | 0.005* | 1.41 | 0.93 |\n\n"
            "## Pair-style throughput\n\n| style | ranks | atom-steps/s | ratio to stock dpd + nve |\n|---|---|---|---|\n"
            "| dpd/gen s=2 + nve | 1 | 3.0e+06 | 1.373 |\n| dpd/gen s=1/2 + nve | 1 | 3.1e+06 | 1.413 |\n"
            "| dpd/gen s=2 + nve | 2 | 5.8e+06 | 1.308 |\n")

    def test_a_wrong_speed_up_is_flagged(self):
        text = "On GW at m = 0.01 the implicit scheme is 3.8 times faster than stock velocity-Verlet.\n"
        self.assertEqual(unheld_speed_claims(text, self.PAGE), [(1, "3.8 times")])

    def test_a_speed_up_of_the_page_passes_and_rounding_counts(self):
        text = ("On GW at m = 0.01 the implicit scheme runs 2.27x stock on 1 rank; "
                "on GW at m = 0.01 it is 2.3 / 1.4 times faster than stock on 1 / 2 ranks.\n"
                "dpd/gen has 1.31-1.37x the throughput of stock dpd at s = 2 on 1 and 2 ranks.\n")
        self.assertEqual(len(speed_claims(text)), 3)
        self.assertEqual(unheld_speed_claims(text, self.PAGE), [])
        self.assertEqual(unheld_speed_claims("On GW at m = 0.01 it runs 2.4x stock.", self.PAGE), [(1, "2.4x")])

    def test_a_number_of_another_quantity_is_flagged(self):
        # each number is on the page, but in another row or column than the one the text names
        wrong = ["dpd/gen has 1.41x the throughput of stock dpd at s = 2.\n",             # s = 1/2's
                 "dpd/gen has 1.37x the throughput of stock dpd at s = 2 on 2 ranks.\n",  # 1 rank's
                 "On P at m = 0.01 the implicit scheme is 2.27 times faster than stock.\n",  # GW's
                 "On GW at m = 0.01 the implicit scheme is 1.41 times faster than stock on 1 rank.\n",
                 "On GW at m = 0.01 the implicit scheme is 2.27 times faster than fix shardlow.\n"]
        for text in wrong:
            self.assertEqual(len(unheld_speed_claims(text, self.PAGE)), 1, text)
        right = ["dpd/gen has 1.37x the throughput of stock dpd at s = 2 on 1 rank.\n",
                 "On P at m = 0.01 the implicit scheme is 3.81 times faster than stock.\n",
                 "On GW at m = 0.01 the implicit scheme is 1.41 times faster than fix shardlow on 1 rank.\n"]
        for text in right:
            self.assertEqual(unheld_speed_claims(text, self.PAGE), [], text)

    def test_a_claim_that_names_no_quantity_is_flagged(self):
        # 1.373 is on the page, but the text says neither which style nor which fluid and mass
        for text in ("The new loop has 1.373x the throughput of the old one.\n",
                     "The colloid's cost is 1.373 times the sphere's in these runs.\n"):
            self.assertEqual(len(unheld_speed_claims(text, self.PAGE)), 1, text)

    def test_targets_and_other_quantities_are_not_claims(self):
        text = ("target: >= 2x fix shardlow; at least 1.3x stock. eta is 1.02 times stock's eta;"
                " a skin of four times the travel; 2.6 times smaller error than stock.\n")
        self.assertEqual(speed_claims(text), [])

    def test_a_wrong_readme_ratio_is_flagged(self):
        head = ("Published results that we do not match\n\n| published result | paper | ours | ratio | cause |\n"
                "|---|---|---|---|---|\n")
        right = head + ("| one-particle colloid in Couette flow, drag | 178.36 | 192.8 | 1.08 +- 0.03 | viscosity |\n"
                        "| dpd/fpm two spheres, torque | 1.066, 0.974, 0.969 | 1.30 | 1.22 +- 0.03, 0.76 +- 0.05, 0.89 | reach |\n"
                        "| compliant channel | yes | the same | | spread |\n")
        self.assertEqual(unheld_readme_ratios(right, self.PAGE), [])
        wrong = head + ("| one-particle colloid in Couette flow, drag | 178.36 | 192.8 | 1.08 +- 0.05 | viscosity |\n"
                        "| dpd/fpm two spheres, torque | 1.066, 0.974, 0.969 | 1.30 | 1.22 +- 0.03, 0.89, 0.76 | reach |\n"
                        "| dpd/fpm spun sphere | 1.3 % | 1.038 | 1.038 | rotation |\n")
        # a wrong error; the right ratios in the wrong rows; a row the page has no ratio for
        self.assertEqual([row for row, _ in unheld_readme_ratios(wrong, self.PAGE)],
                         ["one-particle colloid in Couette flow, drag", "dpd/fpm two spheres, torque",
                          "dpd/fpm spun sphere"])
        # one ratio of the page stated for another result: held by the page, not by its row
        swapped = head + "| one-particle colloid in Couette flow, drag | 178.36 | 192.8 | 1.22 +- 0.03 | x |\n"
        self.assertEqual(len(unheld_readme_ratios(swapped, self.PAGE)), 1)

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
