"""The ellipse's axes over a 6 x 6 grid on a Dask cluster (docs/sweeps.md):

    PYTHONPATH=build/python python3 examples/python/sweep_ellipse.py [--scheduler tcp://HOST:8786]
        [--resolution N] [--image-size W H] [--values K] [--out DIR]

Prints the five deepest bowls and writes out/ellipse_axes/ (results.csv, contact_sheet.png,
scenes/NNNN/ with each run's files).
"""

import argparse
from pathlib import Path

import membra

here = Path(__file__).resolve().parent


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--scheduler", help="tcp://HOST:8786 of a running Dask scheduler")
    parser.add_argument("--resolution", type=int, default=21, help="particles per side (default 21)")
    parser.add_argument("--image-size", type=int, nargs=2, metavar=("W", "H"),
                        help="pixels of each scene's pictures (default the scene's, 1200 x 900)")
    parser.add_argument("--values", type=int, default=6, choices=range(1, 7), metavar="K",
                        help="the first K radii of each axis (default all 6)")
    parser.add_argument("--out", default="out/ellipse_axes")
    args = parser.parse_args()

    spec = membra.sweep_spec.load_sweep(here / "ellipse_axes.sweep.json")
    spec["set"]["sheet.resolution"] = [args.resolution, args.resolution]
    if args.image_size:
        spec["set"]["output.image_size"] = args.image_size
    for key in spec["grid"]:  # a K x K corner of the grid, for a quick look
        spec["grid"][key] = spec["grid"][key][:args.values]
    table = membra.sweep(spec, out=args.out, scheduler=args.scheduler)

    rx, ry = "radius_x", "radius_y"  # the columns' names: the sweep file's "labels"
    ok = table[table["error"] == ""]
    best = ok.sort_values("global_height", ascending=False).head(5)
    print("deepest bowls (radii in mm, heights in mm, total K in rad):")
    print(best[[rx, ry, "global_height", "total_K_global", "classification"]].to_string(index=False))
    print(f"{len(ok)} of {len(table)} converged runs; table in {args.out}/results.csv")


# The guard matters: Dask's local workers are new processes that import this file again.
if __name__ == "__main__":
    main()
