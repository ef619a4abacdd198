#!/usr/bin/python3
"""The adhesive asperity laws (DMT, JKR, Maugis-Dugdale) on the two shared maps against the exact
adhesive contact of the same map (the Maugis-Dugdale cohesive zone on every pixel;
docs/exact-contact.md, "Adhesive contact"): refreshes the section between
<!-- adhesive-laws:begin --> and <!-- adhesive-laws:end --> and the figure
docs/exact-contact-adhesive-maps.svg.

    /usr/bin/python3 scripts/exact_contact_adhesive_report.py [BUILD_DIR]   (default build)

The material is chosen by the mesh criterion, not taken from a real pair: on each map the work of
adhesion makes Maugis' length a_s = (pi w R^2 / K)^(1/3) (K = 4 E*/3, R the measured summit radius)
A_S_PIXELS pixels (the larger pixel side) and the adhesive stress makes Maugis' parameter LAMBDA at
R, so that a summit's cohesive zone spans a few pixels (the sphere's test: 3.4 pixels at a_s 8
pixels, lambda 1, pull-off 11% high). The exact curve is solved periodic, by mean gap, loading
from the highest point down and unloading back up (asperity exact-contact --work-of-adhesion
--adhesive-stress --gap ...); each law through asperity surface MAP --law NAME (its curves on the
fit the verdict names, with the measured summit density and radius; the approach branch) at
compressive pressures of the exact loading curve, and its pull-off. Separations from the mean
summit height, as in the other tables.
"""
import json
import os
import math
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
BUILD = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build"
ASPERITY = (BUILD if BUILD.is_absolute() else ROOT / BUILD) / "asperity"
SHARED = ROOT.parent / "shared" / "surfaces"
MAPS = [("AFM, 256 x 256, 10 um", SHARED / "afm-zsensor-10um.txt"), ("X3P, 650 x 650", SHARED / "digitalsurf-650x650.x3p")]
# ASPERITY_ADHESIVE_MAPS=AFM: the maps whose name starts so (the X3P map's cycle costs minutes)
MAPS = [m for m in MAPS if any(m[0].startswith(k) for k in os.environ.get("ASPERITY_ADHESIVE_MAPS", "AFM,X3P").split(","))]
MODULUS = 1e6        # E* [Pa]: a soft solid (the criterion fixes w / E*, see above)
# Maugis' parameter at the measured summit radius (DMT side: a wide zone), and Maugis' length a_s in
# pixels (the zone c - a at the pull-off 3.3 a_s at lambda 0.1: 6.7 pixels); ASPERITY_ADHESIVE_LAMBDA
# and ASPERITY_ADHESIVE_AS_PIXELS set others
LAMBDA = float(os.environ.get("ASPERITY_ADHESIVE_LAMBDA", "0.1"))
A_S_PIXELS = float(os.environ.get("ASPERITY_ADHESIVE_AS_PIXELS", "2"))
STEPS = 24           # loading steps (and as many unloading)
FRACTIONS = [0.1, 0.3, 1.0]  # of the exact loading curve's largest pressure: the pressures compared


def run(args):
    return subprocess.run([str(ASPERITY)] + [str(a) for a in args], check=True, capture_output=True, text=True).stdout


def g(x, digits=3):
    return f"{x:.{digits}g}"


def surface(path, options, pressures):
    out = run(["surface", path, "--modulus", MODULUS, "--pressure", ",".join(g(p, 6) for p in pressures),
               "--bootstrap", "0", "--no-exact", "--no-persson", "--json"] + options)
    return json.loads(out)


def material(path):
    d = surface(path, [], [1.0])
    R = d["summits"]["radius_m"]
    pixel = max(d["surface"]["dx_m"], d["surface"].get("dy_m", d["surface"]["dx_m"]))
    K = 4 * MODULUS / 3
    a_s = A_S_PIXELS * pixel
    w = a_s ** 3 * K / (math.pi * R * R)
    sigma0 = LAMBDA / (2 * (R / (math.pi * w * K * K)) ** (1 / 3))
    return {"R": R, "pixel": pixel, "a_s": a_s, "w": w, "sigma0": sigma0, "h0": w / sigma0}


def exact_cycle(path, m):
    first = json.loads(run(["exact-contact", path, "--modulus", MODULUS, "--gap", "1e-3", "--json", "--no-stiffness"]))
    top, rms = first["map"]["max_height_m"], first["map"]["rms_height_m"]
    low = 0.2 * rms  # deep enough for the net pressure to turn compressive
    down = [top - (top - low) * k / (STEPS - 1) for k in range(STEPS)]
    up = [low + (top + m["h0"] - low) * k / (STEPS - 1) for k in range(1, STEPS)]
    out = json.loads(run(["exact-contact", path, "--modulus", MODULUS, "--work-of-adhesion", g(m["w"], 8),
                          "--adhesive-stress", g(m["sigma0"], 8), "--no-stiffness", "--json", "--quiet",
                          "--gap", ",".join(g(x, 10) for x in down + up)]))
    steps = out["steps"]
    return steps[:STEPS], steps[STEPS:], first["map"]


def on_loading(loading, pressure):
    """The exact loading curve at a compressive pressure: separation and area, interpolated (the
    last crossing of the pressure, where the curve rises into compression)."""
    for a, b in zip(loading, loading[1:]):
        if a["pressure_Pa"] <= pressure <= b["pressure_Pa"]:
            t = (pressure - a["pressure_Pa"]) / (b["pressure_Pa"] - a["pressure_Pa"])
            return {k: a[k] + t * (b[k] - a[k]) for k in ("separation_from_mean_summit_m", "area_fraction")}
    return None


def figure(results):
    import matplotlib
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "asperity"
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(results), figsize=(5.5 * len(results), 4.2), squeeze=False)
    axes = axes[0]
    for ax, (name, loading, unloading, laws, m) in zip(axes, results):
        for steps, label, style in ((loading, "exact, loading", "o-"), (unloading, "exact, unloading", "s--")):
            ax.plot([s["separation_from_mean_summit_m"] * 1e9 for s in steps], [s["pressure_Pa"] for s in steps], style,
                    ms=3, label=label)
        for label, law in laws:
            pts = [(row["law"]["mean_separation_m"] * 1e9, row["pressure_Pa"]) for row in law["at_pressures"] if row.get("law")]
            adh = law.get("adhesion") or {}
            po, ps = adh.get("pull_off_pressure_Pa"), adh.get("pull_off_mean_separation_m")
            if po is not None and ps is not None and math.isfinite(float(po)):
                pts.append((float(ps) * 1e9, float(po)))
            pts.sort()
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "x:", label=f"{label} (pull-off, pressures)")
        ax.axhline(0, color="0.6", lw=0.5)
        ax.set_title(f"{name}\nw {g(m['w'])} J/m², σ0 {g(m['sigma0'])} Pa, h0 {g(m['h0'] * 1e9)} nm", fontsize=9)
        ax.set_xlabel("separation from the mean summit height [nm]")
        ax.set_ylabel("nominal pressure [Pa] (tension < 0)")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(ROOT / "docs" / "exact-contact-adhesive-maps.svg", metadata={"Date": None})


def main():
    maps = os.environ.get("ASPERITY_ADHESIVE_MAPS")
    lines = [f"E* {g(MODULUS)} Pa; on each map w and sigma0 from a_s = {g(A_S_PIXELS)} pixels and lambda = {g(LAMBDA)} at the "
             f"measured summit radius; command: `" + (f"ASPERITY_ADHESIVE_MAPS={maps} " if maps else "") +
             "/usr/bin/python3 scripts/exact_contact_adhesive_report.py`", ""]
    header = ["map", "model", "pull-off [Pa] (model / exact loading, unloading)",
              "at p [Pa]", "separation from mean summit [nm] (model - exact loading)", "area fraction (model / exact loading)"]
    rows, results = [], []
    for name, path in MAPS:
        m = material(path)
        loading, unloading, info = exact_cycle(path, m)
        top = max(s["pressure_Pa"] for s in loading)
        # compressive pressures of the exact loading curve (none where adhesion holds the map in tension)
        pressures = [f * top for f in FRACTIONS] if top > 0 else []
        asked = pressures or [1.0]  # the laws' pull-off needs a call
        least_loading = min(s["pressure_Pa"] for s in loading)
        least_unloading = min(s["pressure_Pa"] for s in unloading)
        lines.append(f"- {name}: summit radius R {g(m['R'])} m, pixel {g(m['pixel'])} m: w {g(m['w'])} J/m^2, sigma0 "
                     f"{g(m['sigma0'])} Pa, range h0 {g(m['h0'])} m ({g(m['h0'] / info['rms_height_m'])} rms heights); "
                     f"exact: pull-off {g(least_loading)} Pa on loading, {g(least_unloading)} Pa on unloading, "
                     f"largest loading pressure {g(top)} Pa, area fraction there {g(loading[-1]['area_fraction'])}")
        rows.append([name, "exact (periodic)", f"{g(least_loading)}, {g(least_unloading)}", "", "", ""])
        exact_at = {p: on_loading(loading, p) for p in pressures}
        laws = []
        for label, options in (("DMT", ["--law", "dmt", "--work-of-adhesion", g(m["w"], 8)]),
                               ("JKR", ["--law", "jkr", "--work-of-adhesion", g(m["w"], 8)]),
                               ("MD", ["--law", "maugis-dugdale", "--work-of-adhesion", g(m["w"], 8),
                                       "--maugis-parameter", g(LAMBDA)])):
            try:
                law = surface(path, options, asked)["contact"]["law"]
            except subprocess.CalledProcessError as error:
                lines.append(f"- {name}, {label}: failed: {error.stderr.strip()[:300]}")
                continue
            laws.append((label, law))
            adh = law.get("adhesion") or {}
            po = adh.get("pull_off_pressure_Pa")
            po_text = (f"{g(float(po))} ({g(float(po) / least_loading)}, {g(float(po) / least_unloading)})"
                       if po is not None and math.isfinite(float(po)) else "not in range")
            lines.append(f"- {name}, {label} ({law['law']}, fit {law['model']}): adhesion parameter sigma_s/delta_c "
                         f"{g(float(adh.get('adhesion_parameter', float('nan'))))}" + ("" if law.get("served") else
                                                                                      f"; not served: {law.get('note', '')}"))
            states = {round(row["pressure_Pa"], 6): row.get("law") for row in law.get("at_pressures", [])}
            if not pressures:
                rows.append([name, label, po_text, "", "", ""])
            for p in pressures:
                s, e = states.get(round(float(g(p, 6)), 6)), exact_at[p]
                if s is None or e is None:
                    rows.append([name, label, po_text if p == pressures[0] else "", g(p), "not served", ""])
                    continue
                sep = s["mean_separation_m"]
                rows.append([name, label, po_text if p == pressures[0] else "", g(p),
                             f"{sep * 1e9:.1f} ({(sep - e['separation_from_mean_summit_m']) * 1e9:+.1f})",
                             f"{g(s['area_fraction'])} ({s['area_fraction'] / e['area_fraction']:.2f})"])
        results.append((name, loading, unloading, laws, m))
    lines += ["", "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    body = "\n".join(lines)
    figure(results)
    page = ROOT / "docs" / "exact-contact.md"
    text = page.read_text()
    key = "adhesive-laws"
    if f"<!-- {key}:begin -->" not in text:
        sys.exit(f"docs/exact-contact.md has no <!-- {key}:begin --> marker")
    text = re.sub(rf"<!-- {key}:begin -->.*?<!-- {key}:end -->",
                  lambda _: f"<!-- {key}:begin -->\n{body}\n<!-- {key}:end -->", text, flags=re.S)
    page.write_text(text)
    print(body)


if __name__ == "__main__":
    main()
