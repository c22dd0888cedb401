"""A sweep's pictures: the contact sheet, every job's released form drawn side by side on one
colour range, one scale and one pose, labelled with its parameters' short names and its form;
and parameters.png, each swept parameter against the form's measures (docs/sweeps.md)."""

import math
from pathlib import Path


def _label(row, params):
    parts = [f"{p}={row[p]}" for p in params]
    if row.get("error"):
        parts.append("FAILED")
    elif row.get("height") == row.get("height"):  # not NaN
        parts.append(f"h {row['height']:.1f} mm, K {row['total_K_global']:.2f}")
    return "\n".join(parts)


def _form(row):
    """A job's form.npz as (positions, triangles, curvature), or None."""
    import numpy as np

    out = row.get("out")  # NaN for a job whose workers died with it
    file = Path(out) / "form.npz" if isinstance(out, str) and out else None
    if file is None or not file.is_file():
        return None
    with np.load(file) as f:
        x, tri, k = f["positions"], f["triangles"], f["gaussian_curvature"]
    # Centred and on z = 0 as the reading pose leaves a form; a form still held by pins or
    # gravity (not posed) is shifted so that it shares the sheet's box.
    lo, hi = x.min(axis=0), x.max(axis=0)
    return x - [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]], tri, k


def write_contact_sheet(table, params, file, title):
    """Writes `file` (PNG): a grid of the jobs' forms in the reading pose, seen from the same
    3/4 view, on one box (the largest form's) and one curvature range (95 % of |K| over all
    jobs), a grey square where a job has no form, each titled with its parameters, height and
    global total curvature; one colour bar for all."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    forms = [_form(row) for _, row in table.iterrows()]
    drawn = [f for f in forms if f is not None]
    ks = np.concatenate([f[2] for f in drawn]) if drawn else np.zeros(1)
    limit = float(np.percentile(np.abs(ks[ks != 0]), 95)) if np.any(ks != 0) else 1.0
    half = max((np.ptp(f[0], axis=0).max() for f in drawn), default=1.0) / 2
    top = max((f[0][:, 2].max() for f in drawn), default=1.0)
    n = len(table)
    cols = min(6, max(1, n))
    rows = math.ceil(n / cols)
    fig = plt.figure(figsize=(2.6 * cols + 0.8, 2.9 * rows))
    surf = None
    for i, ((_, row), form) in enumerate(zip(table.iterrows(), forms)):
        if form is None:
            ax = fig.add_subplot(rows, cols, i + 1)
            ax.imshow([[0.85]], cmap="gray", vmin=0, vmax=1)
            ax.axis("off")
        else:
            ax = fig.add_subplot(rows, cols, i + 1, projection="3d")
            x, tri, k = form
            surf = ax.plot_trisurf(x[:, 0], x[:, 1], x[:, 2], triangles=tri, cmap="RdBu_r",
                                   vmin=-limit, vmax=limit, linewidth=0, antialiased=False)
            surf.set_array(k[tri].mean(axis=1))
            ax.set(xlim=(-half, half), ylim=(-half, half), zlim=(0, max(top, 1e-9)))
            # zoom: a 3-D axes leaves wide margins around its box; the forms fill the tile.
            ax.set_box_aspect((1, 1, max(top, 1e-9) / (2 * half)), zoom=1.6)
            ax.view_init(elev=35, azim=-60)  # membra's pictures' camera
            ax.set_axis_off()
        ax.set_title(_label(row, params), fontsize=7)
    fig.suptitle(f"{title}: each released form on one scale (box {2 * half:.0f} mm wide) and one "
                 f"colour range", fontsize=10)
    fig.subplots_adjust(left=0.01, right=0.9, bottom=0.01, top=0.88, wspace=0.0, hspace=0.25)
    if surf is not None:
        bar = fig.colorbar(surf, ax=fig.axes, shrink=0.5, fraction=0.02)
        bar.set_label("Gaussian curvature, 1/m² (95 % of |K| in range)", fontsize=8)
    fig.savefig(file, dpi=90)
    plt.close(fig)


def write_parameter_plot(table, params, file, title):
    """Writes `file` (PNG): for each numeric swept parameter, the form's height and global total
    curvature against it, one line per combination of the other parameters."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import pandas as pd

    numeric = [p for p in params if pd.to_numeric(table[p], errors="coerce").notna().all()]
    measures = [("height", "height, mm"), ("total_K_global", "global total K, rad")]
    if not numeric:
        return
    fig, axes = plt.subplots(len(measures), len(numeric), squeeze=False,
                             figsize=(4.2 * len(numeric), 3.0 * len(measures)))
    ok = table[table["error"].fillna("") == ""].copy()
    keys = {q: ok[q].map(str) for q in params}  # lists (a resolution) cannot be group keys
    for c, p in enumerate(numeric):
        others = [q for q in params if q != p]
        groups = ok.groupby([keys[q] for q in others], dropna=False) if others else [((), ok)]
        for r, (measure, label) in enumerate(measures):
            ax = axes[r][c]
            for key, group in groups:
                g = group.sort_values(p)
                key = key if isinstance(key, tuple) else (key,)
                name = ", ".join(f"{q}={v}" for q, v in zip(others, key))
                ax.plot(g[p], g[measure], "o-", ms=3, lw=1, label=name or None)
            ax.set_xlabel(p, fontsize=8)
            ax.set_ylabel(label, fontsize=8)
            ax.tick_params(labelsize=7)
            ax.grid(alpha=0.3)
        if others and 1 < len(groups) <= 8:
            axes[0][c].legend(fontsize=6)
    fig.suptitle(f"{title}: the form against each swept parameter", fontsize=10)
    fig.tight_layout()
    fig.savefig(file, dpi=90)
    plt.close(fig)
