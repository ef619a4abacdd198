#!/usr/bin/python3
"""Runs two_blocks.inp in CalculiX with the cards asperity writes and checks ccx's contact pressure
against asperity's law at the same overclosure.

  gw     `asperity contact --export calculix --units mm` (the README's surface, 1 kPa to 100 MPa,
         the default datum zero-pressure): ccx's pressure at each slave node and increment
         against the law (a CSV card of the same law within 1e-6), where the card covers the law
         (from its lowest pressure on); fails beyond the card's stated tolerance plus ccx's 7 digits.
  exact  `asperity exact-contact --card` of the AFM map (tests/data), 13 pressures from 0.1 to
         100 MPa: ccx against the exact curve solved at 49 pressures over the same range; fails
         beyond EXACT_TOLERANCE (the card interpolates linearly between its 13 solved points).
  exact-refined  the same with --card-tolerance 0.01 (solves added where the curve bends) against
         the curve refined to --card-tolerance 0.001; fails beyond REFINED_TOLERANCE.
  datum  the gw card with --overclosure-datum mean-summit and the slave placed at the card's
         clearance (the first point): the faces (0.5 mm) give a contact-spring cut-off of 5e-4 mm at
         interior nodes, below the card's clearance, so nothing acts until the pressure jumps;
         prints the first pressure ccx reports (docs/usage.md quotes it); not a failure.

Also measures ccx's sign conventions: where a node carries pressure (CSTR, positive in
compression) its normal CDIS is negative (penetration) and equals minus the overclosure.

Usage: run_examples.py ASPERITY [--ccx ccx] [--data DIR] [--keep DIR]. Fails without ccx.
"""
import argparse
import bisect
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SURFACE = ["--dist", "weibull", "--shape", "2", "--rms", "5e-7", "--radius", "1e-4", "--density", "1e10",
           "--area", "1e-4", "--e1", "2.1e11", "--nu1", "0.3", "--e2", "2.1e11", "--nu2", "0.3"]
PRESSURE_RANGE = "1e3:1e8"  # Pa: the README's card
DIGITS = 5e-7               # ccx prints CSTR and CDIS with 7 digits: half a unit of the 7th, relative
EXACT_TOLERANCE = 0.08      # the 13-point exact card's linear interpolation against the 49-point curve (0.070 measured)
REFINED_TOLERANCE = 0.012   # --card-tolerance 0.01 against the curve refined to 1e-3
INCREMENTS = 40             # two_blocks.inp: 0.025 of the step each


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(command, **kwargs):
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kwargs)
    if result.returncode != 0:
        fail("%s exited with %d\n%s" % (" ".join(command), result.returncode, result.stderr[-3000:]))
    return result


def rows_of(text):
    """(pressure, overclosure) rows of a card (after *SURFACE BEHAVIOR) or of a CSV (after its header)."""
    rows, inside = [], False
    for line in text.splitlines():
        if line.startswith("**"):
            continue
        if line.startswith("*") or line.startswith("pressure_"):
            inside = True
            continue
        if inside and line.strip():
            p, h = line.split(",")
            rows.append((float(p), float(h)))
    return rows


def interpolate(rows, overclosure):
    """Linear interpolation, as ccx reads a card: 0 before the first row, the last pressure after the last."""
    hs = [h for _, h in rows]
    k = bisect.bisect_left(hs, overclosure)
    if k == 0:
        return 0.0 if overclosure < hs[0] else rows[0][0]
    if k == len(rows):
        return rows[-1][0]
    (p0, h0), (p1, h1) = rows[k - 1], rows[k]
    return p0 + (p1 - p0) * (overclosure - h0) / (h1 - h0)


def header_number(card, pattern):
    match = re.search(pattern, card)
    if not match:
        fail("the card's header has no %r" % pattern)
    return float(match.group(1))


def parse_dat(text):
    """{time: {"u": {node: uz}, "p": {node: pressure}, "c": {node: normal CDIS}}} from ccx's .dat."""
    results, current, table = {}, None, None
    for line in text.splitlines():
        header = re.search(r"(displacements|contact stress|relative contact displacement).*time\s+(\S+)", line)
        if header:
            current = results.setdefault(float(header.group(2)), {"u": {}, "p": {}, "c": {}})
            table = {"displacements": "u", "contact stress": "p", "relative contact displacement": "c"}[header.group(1)]
            continue
        fields = line.split()
        if current is not None and len(fields) == 4 and fields[0].isdigit():
            values = [float(v) for v in fields[1:]]
            current[table][int(fields[0])] = values[2] if table == "u" else values[0]
    if not results:
        fail("no results in ccx's .dat")
    return results


def run_deck(ccx, directory, name, card, displacement, slave_gap=0.0):
    """two_blocks.inp with `card`, the top moved down by `displacement` mm; the slave `slave_gap` mm up."""
    case = os.path.join(directory, name)
    os.makedirs(case, exist_ok=True)
    deck = open(os.path.join(HERE, "two_blocks.inp")).read()
    if slave_gap:
        lines, inside = [], False
        for line in deck.splitlines():
            if line.startswith("*"):
                inside = line.upper().startswith("*NODE, NSET=NSLAVE")
            elif inside:
                fields = [f.strip() for f in line.split(",")]
                line = "%s, %s, %s, %.12g" % (fields[0], fields[1], fields[2], float(fields[3]) + slave_gap)
            lines.append(line)
        deck = "\n".join(lines) + "\n"
    with open(os.path.join(case, "two_blocks.inp"), "w") as f:
        f.write(deck)
    with open(os.path.join(case, "card.inp"), "w") as f:
        f.write(card)
    with open(os.path.join(case, "load.inp"), "w") as f:
        f.write("NTOP, 3, 3, %.12g\n" % -displacement)
    result = subprocess.run([ccx, "-i", "two_blocks"], cwd=case, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    if result.returncode != 0 or "*ERROR" in result.stdout:
        fail("ccx failed on %s (exit %d):\n%s" % (name, result.returncode, result.stdout[-4000:]))
    with open(os.path.join(case, "two_blocks.dat")) as f:
        return parse_dat(f.read())


def compare(name, results, card_rows, law_rows, tolerance, from_overclosure):
    """ccx's pressures against the law from `from_overclosure` on; checks the signs; returns the worst."""
    worst, worst_at, checked, below, signs = 0.0, None, [], 0, 0
    for time, r in sorted(results.items()):
        for node, pressure in r["p"].items():
            cdis = r["c"][node]
            if pressure > 0:
                signs += 1
                if not cdis < 0:
                    fail("%s: node %d carries %g MPa at CDIS %g: penetration should be a negative CDIS" %
                         (name, node, pressure, cdis))
            overclosure = -cdis
            if overclosure < from_overclosure:
                expected = interpolate(card_rows, overclosure)  # the card's own row, below the law's range
                if abs(pressure - expected) > 1e-5 * max(pressure, card_rows[1][0]):
                    fail("%s: at overclosure %g mm ccx gives %g MPa, the card %g" % (name, overclosure, pressure,
                                                                                   expected))
                below += 1
                continue
            exact = interpolate(law_rows, overclosure)
            k = bisect.bisect_left([h for _, h in law_rows], overclosure)
            k = min(max(k, 1), len(law_rows) - 1)
            slope = (law_rows[k][0] - law_rows[k - 1][0]) / (law_rows[k][1] - law_rows[k - 1][1])
            allowed = tolerance + DIGITS * (1 + abs(overclosure) * slope / exact)
            error = abs(pressure - exact) / exact
            checked.append(pressure)
            if error > allowed:
                fail("%s: ccx's contact pressure differs from the law by %.3g (allowed %.3g) at overclosure %g mm: "
                     "ccx %g MPa, law %g" % (name, error, allowed, overclosure, pressure, exact))
            if error > worst:
                worst, worst_at = error, (overclosure, pressure, exact)
    if len(checked) < 40:
        fail("%s: only %d pressures checked" % (name, len(checked)))
    print("%s: %d contact pressures from %.4g to %.4g MPa checked against asperity's law: largest relative "
          "difference %.3g (at overclosure %.6g mm: ccx %.6g MPa, law %.6g; allowed %.3g); %d below the law's range "
          "on the card's first row; %d pressures, each at a negative CDIS" %
          (name, len(checked), min(checked), max(checked), worst, worst_at[0], worst_at[1], worst_at[2], tolerance,
           below, signs))
    return worst


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("asperity")
    parser.add_argument("--ccx", default="ccx")
    parser.add_argument("--data", default=os.path.join(HERE, "..", "..", "tests", "data", "surfaces"))
    parser.add_argument("--keep", help="write the models and results here (default: a temporary directory)")
    args = parser.parse_args()
    ccx = shutil.which(args.ccx)
    if ccx is None:
        fail("CalculiX (%s) is not installed: scripts/setup.sh installs Debian's calculix-ccx" % args.ccx)
    directory = args.keep or tempfile.mkdtemp(prefix="asperity-calculix-")
    os.makedirs(directory, exist_ok=True)
    try:
        # gw: the README's card, as written (units mm), and the law as a CSV within 1e-6
        export = [args.asperity, "contact"] + SURFACE + ["--export", "calculix", "--units", "mm",
                                                        "--pressure-range", PRESSURE_RANGE]
        card = run(export).stdout
        rows = rows_of(card)
        tolerance = header_number(card, r"linear interpolation between the points is within ([0-9.e-]+)")
        law = rows_of(run([args.asperity, "contact"] + SURFACE + [
            "--export", "csv", "--units", "mm", "--pressure-range", PRESSURE_RANGE, "--export-tolerance", "1e-6",
            "--max-points", "100000"]).stdout)
        if rows[0] != (0.0, 0.0):
            fail("the default card does not start at zero pressure and overclosure: %r" % (rows[0],))
        gw = run_deck(ccx, directory, "gw", card, 0.995 * rows[-1][1])
        compare("gw", gw, rows, law, tolerance + 1e-6, rows[1][1])
        gw_first = max(gw[min(gw)]["p"].values() or [0.0])

        # exact: 13 solved points on the card, the curve at 49 as the law
        afm = os.path.join(args.data, "afm-zsensor-10um.txt")
        exact = [args.asperity, "exact-contact", afm, "--modulus", "1e11", "--quiet", "--units", "mm"]
        card_path, law_path = os.path.join(directory, "exact13.inp"), os.path.join(directory, "exact49.csv")
        run(exact + ["--sweep", "pressure:1e5:1e8:13", "--card", card_path, "--overwrite"])
        run(exact + ["--sweep", "pressure:1e5:1e8:49", "--card", law_path, "--card-format", "csv", "--overwrite"])
        card = open(card_path).read()
        rows, law = rows_of(card), rows_of(open(law_path).read())
        results = run_deck(ccx, directory, "exact", card, 0.995 * rows[-1][1])
        compare("exact", results, rows, law, EXACT_TOLERANCE, rows[1][1])

        # exact-refined: the same 13 pressures with --card-tolerance 0.01 (solves added where the curve
        # bends), against the curve refined to 1e-3 (its own midpoint solves within 1e-3)
        law_path = os.path.join(directory, "exact-fine.csv")
        run(exact + ["--sweep", "pressure:1e5:1e8:13", "--card", card_path, "--overwrite", "--card-tolerance",
                     "0.01"])
        run(exact + ["--sweep", "pressure:1e5:1e8:13", "--card", law_path, "--card-format", "csv", "--overwrite",
                     "--card-tolerance", "0.001", "--max-points", "2000"])
        card = open(card_path).read()
        rows, law = rows_of(card), rows_of(open(law_path).read())
        results = run_deck(ccx, directory, "exact-refined", card, 0.995 * rows[-1][1])
        print("exact-refined: the card has %d rows" % len(rows))
        compare("exact-refined", results, rows, law, REFINED_TOLERANCE, rows[1][1])

        # datum: the mean-summit card, the slave placed at its clearance (its first point)
        card = run(export + ["--overclosure-datum", "mean-summit"]).stdout
        rows = rows_of(card)
        clearance = -rows[0][1]
        # to 1 um past the mean summit height (the card's last row is short of it)
        results = run_deck(ccx, directory, "datum", card, clearance + max(rows[-1][1], 0.0) + 1e-3,
                           slave_gap=clearance)
        first = None
        for time, r in sorted(results.items()):
            if any(p > 0 for p in r["p"].values()):
                if not [n for n in r["p"] if r["p"][n] > 0]:
                    continue
                first = (time, max(r["p"].values()), min(-r["c"][n] for n in r["p"]))
                break
        if first is None:
            fail("datum: no contact pressure at all")
        print("datum: the mean-summit card (clearance %.6g mm) with the slave at that clearance, faces of 0.5 mm "
              "(cut-off 5e-4 mm at interior nodes): no contact pressure before time %.4g of the step, then %.4g MPa "
              "at once (overclosure %.6g mm); with the default zero-pressure datum the first increment (time %.4g) "
              "carries %.4g MPa at most" % (clearance, first[0], first[1], first[2], min(gw), gw_first))
    finally:
        if not args.keep:
            shutil.rmtree(directory, ignore_errors=True)


if __name__ == "__main__":
    main()
