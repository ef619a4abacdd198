"""What every report script shares: matplotlib without a display, one look, and figures whose
bytes depend only on their data (no date in the SVG metadata, fixed SVG ids), so that running a
report twice on the same data leaves the tree clean.

Imported by the report scripts (scripts/ is on their path when run as scripts/NAME.py).
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

plt.rcParams.update({
    "svg.hashsalt": "asperity",  # clip-path and other ids from a fixed salt, not a random one
    "svg.fonttype": "path",      # text as paths: the same picture on every viewer
    "font.size": 10,
    "axes.titlesize": 11,
    "axes.labelsize": 10,
    "legend.fontsize": 8.5,
    "xtick.labelsize": 9,
    "ytick.labelsize": 9,
    "axes.grid": True,
    "grid.alpha": 0.3,
})


def save(figure, directory, name, dpi=120):
    """Writes NAME.svg and NAME.png into directory, reproducibly, and closes the figure."""
    figure.savefig(directory / f"{name}.svg", metadata={"Date": None})
    figure.savefig(directory / f"{name}.png", dpi=dpi)
    plt.close(figure)
