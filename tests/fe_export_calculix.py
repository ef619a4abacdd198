#!/usr/bin/python3
"""The FE export in the solver: CalculiX (Debian's calculix-ccx) runs a small model with the card
`asperity contact --export calculix` writes, and its contact pressures are checked against
asperity's own law.

Two models, each an elastic block pressed by prescribed displacement onto a larger one, with
NODE TO SURFACE contact and *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR from the card:

A  (agreement) one slave element whose nodes' contact-spring cut-off (1e-3 sqrt(node area)) lies
   beyond the card's whole clearance range: at every increment and slave node, ccx's contact
   pressure (*CONTACT PRINT CSTR) at its overclosure (minus CDIS's normal clearance) is compared
   with the model's pressure at that overclosure (`asperity contact --separation`), within the
   card's interpolation tolerance plus ccx's 7 printed digits, over the card's pressure range;
   below the range, with the card's tangent row.
B  (cut-off) a 2x2 slave mesh of faces of edge a: its interior node (area a^2), edge nodes (a^2/2)
   and corner nodes (a^2/4) get a contact spring only once their clearance is below 1e-3 sqrt(area)
   (steps 2 % either side of each cut-off), and `--face-size a` warns that the card reaches beyond
   the interior node's cut-off 1e-3 a.

Usage: fe_export_calculix.py ASPERITY [--ccx ccx] [--keep DIR]. Fails (never skips) without ccx.
Prints the largest relative disagreement measured and the pressures it covers.
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

SURFACE = ["--dist", "weibull", "--shape", "2", "--sigma", "1e-6", "--radius", "1e-4", "--density", "1e10",
           "--area", "1e-4", "--modulus", "1.15e11"]
PRESSURE_RANGE = "1e4:5e7"    # Pa: 0.01 to 50 MPa (GW's sparse contacts: real area below 0.35 of nominal)
TOLERANCE = 1e-3              # the card's interpolation tolerance (the default)
DIGITS = 5e-7                 # ccx prints CSTR and CDIS with 7 digits: half a unit of the 7th, relative
AREA = 1e-4                   # m^2, --area
CUTOFF = 1e-3                 # ccx 2.20: a spring only where clearance < 1e-3 sqrt(slave node area)


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(command, **kwargs):
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kwargs)
    if result.returncode != 0:
        fail("%s exited with %d\n%s\n%s" % (" ".join(command), result.returncode, result.stdout[-3000:],
                                             result.stderr[-3000:]))
    return result


def parse_card(text):
    """The (pressure, overclosure) rows after *SURFACE BEHAVIOR, as ccx reads them (20 characters a field)."""
    rows, inside = [], False
    for line in text.splitlines():
        if line.startswith("**"):
            continue
        if line.startswith("*"):
            inside = line.upper().replace(" ", "") == "*SURFACEBEHAVIOR,PRESSURE-OVERCLOSURE=TABULAR"
            continue
        if inside and line.strip():
            fields = line.split(",")
            if len(fields) != 2 or max(len(f) for f in fields) > 20:
                fail("card row not two fields of at most 20 characters: %r" % line)
            rows.append((float(fields[0]), float(fields[1])))
    if len(rows) < 3:
        fail("the card has %d rows" % len(rows))
    return rows


def card_pressure(rows, overclosure):
    """Linear interpolation in the card, as ccx does: 0 before the first row, the last pressure after the last."""
    if overclosure <= rows[0][1]:
        return 0.0
    for (p0, h0), (p1, h1) in zip(rows, rows[1:]):
        if overclosure <= h1:
            return p0 + (p1 - p0) * (overclosure - h0) / (h1 - h0)
    return rows[-1][0]


class Law:
    """The model's nominal pressure [MPa] at an overclosure [mm] from the mean summit height, asked of asperity."""

    def __init__(self, asperity):
        self.asperity = asperity
        self.cache = {}
        # mean_separation at separation 0: the origin seen from the mean summit height
        self.origin_from_mean = -self.state(0.0)["mean_separation_m"]

    def state(self, separation):
        out = run([self.asperity, "contact"] + SURFACE + ["--separation", repr(separation)]).stdout.splitlines()
        return dict(zip(out[0].split(","), map(float, out[1].split(","))))

    def pressure(self, overclosure_mm):
        """(pressure [MPa], its slope dp/dh [MPa/mm]) at the overclosure."""
        if overclosure_mm not in self.cache:
            state = self.state(self.origin_from_mean - overclosure_mm * 1e-3)
            self.cache[overclosure_mm] = (state["nominal_pressure_Pa"] / 1e6,
                                          state["stiffness_N_per_m"] / AREA * 1e-9)
        return self.cache[overclosure_mm]


def block_model(card, slave_elements, edge, gap, height, displacement, increments):
    """A slave block (slave_elements^2 C3D8, faces edge x edge, height `height`) `gap` above a master block
    twice as wide; its top moved down by `displacement` in `increments` equal increments (mm, MPa).
    Numbers with 12 digits: ccx reads 20 characters a field."""
    n = slave_elements
    width = n * edge
    lines = ["*HEADING", "asperity FE export check", "*NODE"]
    master = [(-width / 2, -width / 2), (1.5 * width, -width / 2), (1.5 * width, 1.5 * width), (-width / 2, 1.5 * width)]
    for k, (x, y) in enumerate(master):
        lines.append("%d, %.12g, %.12g, %.12g" % (k + 1, x, y, -height))
        lines.append("%d, %.12g, %.12g, %.12g" % (k + 5, x, y, 0.0))
    node = lambda i, j, layer: 1000 + layer * 100 + j * (n + 1) + i
    for layer, z in ((0, gap), (1, gap + height)):
        for j in range(n + 1):
            for i in range(n + 1):
                lines.append("%d, %.12g, %.12g, %.12g" % (node(i, j, layer), i * edge, j * edge, z))
    lines += ["*ELEMENT, TYPE=C3D8, ELSET=EMASTER", "1, 1, 2, 3, 4, 5, 6, 7, 8", "*ELEMENT, TYPE=C3D8, ELSET=ESLAVE"]
    e = 10
    for j in range(n):
        for i in range(n):
            corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            lines.append("%d, %s" % (e, ", ".join(str(node(a, b, layer)) for layer in (0, 1) for a, b in corners)))
            e += 1
    top = [node(i, j, 1) for j in range(n + 1) for i in range(n + 1)]
    bottom = [node(i, j, 0) for j in range(n + 1) for i in range(n + 1)]
    lines += ["*NSET, NSET=NFIXED", "1, 2, 3, 4", "*NSET, NSET=NTOP"] + [", ".join(map(str, top))]
    lines += ["*NSET, NSET=NCONTACT"] + [", ".join(map(str, bottom))]
    # stiff (1e7 MPa) so that the blocks' compression stays small beside the overclosures
    lines += ["*MATERIAL, NAME=STIFF", "*ELASTIC", "1e7, 0.3",
              "*SOLID SECTION, ELSET=EMASTER, MATERIAL=STIFF", "*SOLID SECTION, ELSET=ESLAVE, MATERIAL=STIFF",
              "*SURFACE, NAME=SMASTER", "EMASTER, S2", "*SURFACE, NAME=SSLAVE", "ESLAVE, S1",
              "*CONTACT PAIR, INTERACTION=ROUGH, TYPE=NODE TO SURFACE", "SSLAVE, SMASTER",
              "*SURFACE INTERACTION, NAME=ROUGH"]
    lines += [l for l in card.splitlines() if not l.startswith("**")]
    lines += ["*BOUNDARY", "NFIXED, 1, 3, 0", "NTOP, 1, 2, 0",
              "*STEP, INC=10000", "*STATIC", "%.12g, 1, 1e-8, %.12g" % (1.0 / increments, 1.0 / increments)]
    lines += [
              "*BOUNDARY", "NTOP, 3, 3, %.12g" % (-displacement),
              "*NODE PRINT, NSET=NCONTACT", "U", "*CONTACT PRINT", "CSTR, CDIS", "*END STEP"]
    return "\n".join(lines) + "\n", bottom


def run_ccx(ccx, directory, name, deck):
    with open(os.path.join(directory, name + ".inp"), "w") as f:
        f.write(deck)
    result = subprocess.run([ccx, "-i", name], cwd=directory, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    if result.returncode != 0 or "*ERROR" in result.stdout:
        fail("ccx failed on %s (exit %d):\n%s" % (name, result.returncode, result.stdout[-4000:]))
    with open(os.path.join(directory, name + ".dat")) as f:
        return parse_dat(f.read())


def parse_dat(text):
    """{time: {"u": {node: uz}, "p": {node: pressure}, "c": {node: normal clearance}}} from ccx's .dat."""
    results, current, table = {}, None, None
    for line in text.splitlines():
        header = re.search(r"(displacements|contact stress|relative contact displacement).*time\s+(\S+)", line)
        if header:
            time = float(header.group(2))
            current = results.setdefault(time, {"u": {}, "p": {}, "c": {}})
            table = {"displacements": "u", "contact stress": "p", "relative contact displacement": "c"}[header.group(1)]
            continue
        fields = line.split()
        if current is not None and len(fields) == 4 and fields[0].isdigit():
            values = [float(v) for v in fields[1:]]
            current[table][int(fields[0])] = values[2] if table == "u" else values[0]
    if not results:
        fail("no results in ccx's .dat")
    return results


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("asperity")
    parser.add_argument("--ccx", default="ccx")
    parser.add_argument("--keep", help="write the models and results here (default: a temporary directory)")
    args = parser.parse_args()
    ccx = shutil.which(args.ccx)
    if ccx is None:
        fail("CalculiX (%s) is not installed: scripts/setup.sh installs Debian's calculix-ccx" % args.ccx)

    # the mean-summit datum: a card with a clearance, for the cut-off (model B); the default datum
    # (zero-pressure) has none: examples/calculix/run_examples.py runs it
    export = [args.asperity, "contact"] + SURFACE + ["--export", "calculix", "--units", "mm",
                                                    "--pressure-range", PRESSURE_RANGE,
                                                    "--overclosure-datum", "mean-summit"]
    card = run(export).stdout
    rows = parse_card(card)
    reach = -rows[0][1]                      # mm: the card's largest clearance
    p_min, h_min = rows[1]                   # the range's lowest pressure and its overclosure
    law = Law(args.asperity)

    directory = args.keep or tempfile.mkdtemp(prefix="asperity-ccx-")
    os.makedirs(directory, exist_ok=True)
    try:
        # A: one slave element; corner nodes of area edge^2/4: cut-off 1e-3 edge/2, 1.5 times the card's reach.
        edge = 1.5 * reach / (CUTOFF / 2)
        overclosure_end = rows[-1][1] - 0.01 * (rows[-1][1] - h_min)  # just short of the last row
        deck, contact_nodes = block_model(card, 1, edge, reach, 1.0, reach + overclosure_end, 40)
        results = run_ccx(ccx, directory, "agreement", deck)
        worst, worst_at, below, covered = 0.0, None, 0, []
        for time, r in sorted(results.items()):
            for node, pressure in r["p"].items():
                overclosure = -r["c"][node]
                if overclosure < h_min:
                    expected = card_pressure(rows, overclosure)   # the card's tangent row below the range
                    slope = (rows[1][0] - rows[0][0]) / (rows[1][1] - rows[0][1])
                    if abs(pressure - expected) > DIGITS * (2 * pressure + abs(overclosure) * slope):
                        fail("below the range at overclosure %g mm ccx gives %g MPa, the card %g" %
                             (overclosure, pressure, expected))
                    below += 1
                    continue
                exact, slope = law.pressure(overclosure)
                # what ccx's 7 printed digits of pressure and of clearance leave uncertain
                printed = DIGITS * (1 + abs(overclosure) * slope / exact)
                error = abs(pressure - exact) / exact
                covered.append(pressure)
                if error > TOLERANCE + printed:
                    fail("ccx's contact pressure differs from the law by %.3g (allowed %.3g) at overclosure %g mm: "
                         "ccx %g MPa, law %g" % (error, TOLERANCE + printed, overclosure, pressure, exact))
                if error > worst:
                    worst, worst_at = error, (overclosure, pressure, exact, printed)
        if len(covered) < 40 or min(covered) > 2 * p_min or max(covered) < 0.5 * rows[-1][0]:
            fail("model A covered too little of the range: %d points, %g to %g MPa" %
                 (len(covered), min(covered or [0]), max(covered or [0])))
        print("A: %d contact pressures from %.3g to %.3g MPa (overclosures from %.4g to %.4g mm): largest relative "
              "difference from asperity's law %.2e (at %.4g mm, where %.1e is allowed: the card's tolerance %g and "
              "%.1e for ccx's 7 printed digits); %d below the range, on the card's tangent row" %
              (len(covered), min(covered), max(covered), h_min, overclosure_end, worst, worst_at[0],
               TOLERANCE + worst_at[3], TOLERANCE, worst_at[3], below))

        # B: 2x2 slave faces of edge a; the interior node's cut-off 1e-3 a at half the card's reach.
        a = 0.5 * reach / CUTOFF
        cutoffs = {"interior": CUTOFF * a, "edge": CUTOFF * a / math.sqrt(2), "corner": CUTOFF * a / 2}
        # clearances 2 % either side of each cut-off, from far to near
        clearances = sorted([f * c for c in cutoffs.values() for f in (1.02, 0.98)], reverse=True)
        start = 1.05 * cutoffs["interior"]
        steps = [start - c for c in clearances]
        # one model per clearance (a step each would carry forces over): the slave's top moved by `step`
        node_kind = {}
        for j in range(3):
            for i in range(3):
                border = (i in (0, 2)) + (j in (0, 2))
                node_kind[1000 + j * 3 + i] = ["interior", "edge", "corner"][border]
        for clearance, step in zip(clearances, steps):
            deck, _ = block_model(card, 2, a, start, 1.0, step, 1)
            r = run_ccx(ccx, directory, "cutoff", deck)[1.0]
            sprung = set(r["p"])
            expected = {n for n, kind in node_kind.items() if clearance < cutoffs[kind]}
            if sprung != expected:
                fail("at clearance %g mm (cut-offs %s) ccx made springs at %s, expected %s" %
                     (clearance, cutoffs, sorted(sprung), sorted(expected)))
        print("B: faces of %.4g mm: contact springs appear at clearance 0.98 x 1e-3 sqrt(A) and not at 1.02 x, for "
              "the interior (A = a^2, cut-off %.4g mm), edge (a^2/2) and corner (a^2/4) nodes" %
              (a, cutoffs["interior"]))
        # --face-size in the card's units (mm here)
        warned = run(export + ["--face-size", repr(a)]).stderr
        if not re.search(r"warning: the card reaches a clearance of .* within a clearance of 1e-3 sqrt\(A\)[^=]*= %s mm"
                         % re.escape("%.6g" % cutoffs["interior"]), warned):
            fail("--face-size %g (mm) gave no cut-off warning naming %.6g mm:\n%s" % (a, cutoffs["interior"], warned))
        quiet = run(export + ["--face-size", repr(2.2 * reach / CUTOFF)]).stderr
        if "clearance" in quiet:
            fail("a face size whose cut-off covers the card warned:\n" + quiet)
    finally:
        if not args.keep:
            shutil.rmtree(directory, ignore_errors=True)


if __name__ == "__main__":
    main()
