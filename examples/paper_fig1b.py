#!/usr/bin/python3
"""The paper's Fig. 1b from Python: load against separation on the tail side, Weibull shapes, the
Gaussian and Persson's law (docs/paper.md: P/P0^g = sqrt(2 pi) X_3/2 / c_a^(3/2) against
t = (s - mu_a)/c_a). usage: paper_fig1b.py [OUT.png]"""
import sys

import matplotlib
import numpy as np

import asperity

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

table = asperity.Table.open_default()
t = np.linspace(-1.0, 4.5, 500)   # separation from the mean summit height, in rms units
for a in (1, 2, 3, 5):
    mean, rms = asperity.weibull_mean(a), asperity.weibull_rms(a)
    load = table.curve("weibull", "tail", a).value(3, mean + rms * t)   # X_3/2, one array call
    plt.semilogy(t, np.sqrt(2 * np.pi) * load / rms ** 1.5, label=f"Weibull a = {a}")
gaussian = np.sqrt(2 * np.pi) * table.curve("gaussian", "tail").value(3, t)
plt.semilogy(t, gaussian, "k--", label="Gaussian")
for beta, style in ((0.5, ":"), (1.0, "-.")):   # through the Gaussian at t = 0: only the slope means anything
    plt.semilogy(t, gaussian[np.abs(t).argmin()] * np.exp(-t / beta), style, color="gray", label=f"Persson, beta = {beta}")
plt.ylim(1e-8, 10)
plt.xlabel("separation from the mean summit height  t = (s - mu_a) / c_a  [rms units]")
plt.ylabel("load  P / P0^g = sqrt(2 pi) X_3/2 / c_a^3/2")
plt.title("Fig. 1b  load-separation, tail side")
plt.legend(fontsize=8)
plt.savefig(sys.argv[1] if len(sys.argv) > 1 else "paper_fig1b.png", dpi=110)
