#!/usr/bin/python3
"""The elastic-plastic asperity laws (CEB, ZMC, KE, JG) on the two shared maps against the exact
elastic-perfectly-plastic contact of the same map at the same hardness (docs/exact-contact.md,
"Elastic-perfectly-plastic"): refreshes the section between <!-- plastic-laws:begin --> and
<!-- plastic-laws:end -->.

    /usr/bin/python3 scripts/exact_contact_plastic_report.py [BUILD_DIR]   (default build)

Each law comes from `asperity surface MAP --law NAME` (its curves on the fit the verdict names, at
the pressures of interest), the exact curve from `asperity exact-contact MAP --hardness H` (periodic
and padded). The same hardness: CEB and ZMC take H; KE and JG the yield strength Y = H / 2.8
(Kogut-Etsion's H = 2.8 Y). Separations from the mean summit height, as in the elastic tables.
"""
import json
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
BUILD = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build"
ASPERITY = (BUILD if BUILD.is_absolute() else ROOT / BUILD) / "asperity"
SHARED = ROOT.parent / "shared" / "surfaces"
MAPS = [("AFM, 256 x 256, 10 um", SHARED / "afm-zsensor-10um.txt"), ("X3P, 650 x 650", SHARED / "digitalsurf-650x650.x3p")]
MODULUS = 1e11
HARDNESS = 4e9
PRESSURES = [1e6, 1e7, 1e8]
LAWS = [
    ("CEB", ["--law", "chang-etsion-bogy", "--hardness", str(HARDNESS), "--law-poisson", "0.3"]),
    ("ZMC", ["--law", "zhao-maietta-chang", "--hardness", str(HARDNESS)]),
    ("KE", ["--law", "kogut-etsion", "--yield-strength", str(HARDNESS / 2.8), "--law-poisson", "0.3"]),
    ("JG", ["--law", "jackson-green", "--yield-strength", str(HARDNESS / 2.8), "--law-poisson", "0.3"]),
]


def run(args):
    return subprocess.run([str(ASPERITY)] + [str(a) for a in args], check=True, capture_output=True, text=True).stdout


def g(x, digits=3):
    return f"{x:.{digits}g}"


def exact_steps(path, boundary):
    out = run(["exact-contact", path, "--modulus", MODULUS, "--hardness", HARDNESS, "--boundary", boundary,
               "--pressure", ",".join(str(p) for p in PRESSURES), "--json"])
    return {s["pressure_Pa"]: s for s in json.loads(out)["steps"]}


def law_states(path, options):
    out = run(["surface", path, "--modulus", MODULUS, "--pressure", ",".join(str(p) for p in PRESSURES),
               "--bootstrap", "0", "--no-exact", "--no-persson", "--json"] + options)
    law = json.loads(out)["contact"]["law"]
    states = {row["pressure_Pa"]: row["law"] for row in law["at_pressures"]}
    return law, states


def main():
    lines = [f"E* {g(MODULUS)} Pa, H {g(HARDNESS)} Pa (KE, JG: Y = H / 2.8 = {g(HARDNESS / 2.8)} Pa, nu 0.3); "
             f"command: `/usr/bin/python3 scripts/exact_contact_plastic_report.py`", ""]
    header = ["map", "pressure [Pa]", "model", "separation from mean summit [nm] (model - exact periodic / padded)",
              "area fraction (model / exact periodic / padded)", "plastic share of the area",
              "stiffness per area [N/m^3] (model / exact periodic / padded)"]
    rows = []
    for name, path in MAPS:
        periodic, padded = exact_steps(path, "periodic"), exact_steps(path, "padded")
        laws = [(label, *law_states(path, options)) for label, options in LAWS]
        for p in PRESSURES:
            a, b = periodic[p], padded[p]
            rows.append([name, g(p), "exact periodic / padded",
                         f"{a['separation_from_mean_summit_m'] * 1e9:.1f} / {b['separation_from_mean_summit_m'] * 1e9:.1f}",
                         f"{g(a['area_fraction'])} / {g(b['area_fraction'])}",
                         f"{a['plastic_area_fraction'] / a['area_fraction']:.2f} / {b['plastic_area_fraction'] / b['area_fraction']:.2f}",
                         f"{g(a['stiffness_per_area_N_per_m3'])} / {g(b['stiffness_per_area_N_per_m3'])}"])
            for label, law, states in laws:
                s = states.get(p)
                if s is None or not law.get("served"):
                    rows.append([name, g(p), label, "not served (below)", "", "", ""])
                    continue
                sep = s["mean_separation_m"]
                rows.append([name, g(p), label,
                             f"{sep * 1e9:.1f} ({(sep - a['separation_from_mean_summit_m']) * 1e9:+.1f} / "
                             f"{(sep - b['separation_from_mean_summit_m']) * 1e9:+.1f})",
                             f"{g(s['area_fraction'])} ({s['area_fraction'] / a['area_fraction']:.2f} / "
                             f"{s['area_fraction'] / b['area_fraction']:.2f})", "",
                             f"{g(s['stiffness_per_area_N_per_m3'])} ({s['stiffness_per_area_N_per_m3'] / a['stiffness_per_area_N_per_m3']:.2f} / "
                             f"{s['stiffness_per_area_N_per_m3'] / b['stiffness_per_area_N_per_m3']:.2f})"])
        for label, law, _ in laws:
            if not law.get("served"):
                lines.append(f"- {name}, {label}: not served: {law.get('note', '')}")
            psi = law["plasticity"]
            lines.append(f"- {name}, {label} ({law['law']}, fit {law['model']}): psi {g(psi['psi'])}, "
                         f"GW's psi {g(psi['psi_gw'])}" if psi.get("psi_gw") is not None else
                         f"- {name}, {label} ({law['law']}, fit {law['model']}): psi {g(psi['psi'])}")
    lines += ["", "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    body = "\n".join(lines)
    page = ROOT / "docs" / "exact-contact.md"
    text = page.read_text()
    key = "plastic-laws"
    if f"<!-- {key}:begin -->" not in text:
        sys.exit(f"docs/exact-contact.md has no <!-- {key}:begin --> marker")
    text = re.sub(rf"<!-- {key}:begin -->.*?<!-- {key}:end -->",
                  lambda _: f"<!-- {key}:begin -->\n{body}\n<!-- {key}:end -->", text, flags=re.S)
    page.write_text(text)
    print(body)


if __name__ == "__main__":
    main()
