"""A notebook's worth of membra (docs/python.md): run a scene, plot its curvature, change the
pattern, run again, compare. Run it as a script, or open notebook.ipynb (the same cells, made
from this file by scripts/notebook-from-script) in Jupyter:

    PYTHONPATH=build/python python3 examples/python/notebook.py [--resolution N] [--out DIR]
"""

# %% 0. Settings. A script takes them from its command line; in Jupyter, edit them here (the
# test suite sets them through the environment). Jupyter runs a notebook in its own folder.
import argparse
import os
import sys
from pathlib import Path

import matplotlib
import numpy as np

import membra

in_jupyter = "ipykernel" in sys.modules
here = Path(__file__).resolve().parent if "__file__" in globals() else Path.cwd()
resolution = int(os.environ.get("MEMBRA_NOTEBOOK_RESOLUTION", 31))
out = Path(os.environ.get("MEMBRA_NOTEBOOK_OUT", "out/notebook"))
if not in_jupyter:
    matplotlib.use("Agg")  # no window: the figure is saved
    parser = argparse.ArgumentParser()
    parser.add_argument("--resolution", type=int, default=resolution)
    parser.add_argument("--out", default=str(out))
    args = parser.parse_args()
    resolution, out = args.resolution, Path(args.out)
import matplotlib.pyplot as plt  # noqa: E402

# %% 1. The paper's headline example: an elliptical pattern that releases into a bowl.
scene = membra.Scene(here.parent / "synclastic_ellipse.json",
                     set={"sheet.resolution": [resolution] * 2, "simulation.solver": "newton"})
bowl = membra.run(scene, out=out / "bowl")
print(bowl, "global form:", bowl.report["curvature"]["global"]["classification"])

# %% 2. Its curvature, plotted on the released form (mm and 1/m², as in the outputs).
def plot(ax, result, title, lim):
    x, y, z = result.positions.T
    k = result.gaussian_curvature
    surf = ax.plot_trisurf(x, y, z, triangles=result.triangles, cmap="RdBu_r",
                           vmin=-lim, vmax=lim, linewidth=0)
    surf.set_array(k[result.triangles].mean(axis=1))
    ax.set_title(title, fontsize=9)
    ax.set_box_aspect((np.ptp(x), np.ptp(y), max(np.ptp(z), 1.0)))
    return surf


# %% 3. Change the pattern: the filled ellipse's vertical radius from 80 to 50 mm.
narrow = membra.run(scene.with_set({"protocol.1.pattern.union.0.ellipse.radii.1": 50}),
                     out=out / "narrow")
print(narrow)

fig = plt.figure(figsize=(10, 4.5))
# One colour range for both, so that the colour bar reads for each: 95 % of |K| in range.
lim = max(np.percentile(np.abs(r.gaussian_curvature), 95) for r in (bowl, narrow)) or 1.0
for i, (result, title) in enumerate([(bowl, "ellipse 120 x 80 mm"), (narrow, "ellipse 120 x 50 mm")]):
    ax = fig.add_subplot(1, 2, i + 1, projection="3d")
    surf = plot(ax, result, f"{title}: height {result.report['shape']['height']:.1f} mm", lim)
fig.colorbar(surf, ax=fig.axes, shrink=0.6, label="Gaussian curvature, 1/m²")
fig.savefig(out / "compare.png", dpi=100)
print(f"heights: {bowl.report['shape']['height']:.1f} mm and {narrow.report['shape']['height']:.1f} mm;"
      f" figure in {out / 'compare.png'}")

# %% 4. The process step by step, as in the lab: stretch, impregnate, release.
m = membra.Membrane(scene)
m.run_protocol()
same = np.allclose(m.result().positions, bowl.positions)  # both in the reading pose
print("step by step gives the same form as membra.run:", same)

# %% 5. In Jupyter, a result shows itself: the form in 3-D (drag to turn) and its numbers.
bowl
