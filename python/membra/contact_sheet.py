"""A sweep's contact sheet: every job's curvature picture in one image, labelled with its
parameters and its form, in the sweep's order."""

import math
from pathlib import Path


def _label(row, params):
    parts = [f"{p.split('.')[-2] + '.' + p.split('.')[-1] if p.count('.') else p}={row[p]}"
             for p in params]
    if row.get("error"):
        parts.append("FAILED")
    elif row.get("height") == row.get("height"):  # not NaN
        parts.append(f"h {row['height']:.1f} mm, K {row['total_K_global']:.2f}")
    return "\n".join(parts)


def write_contact_sheet(table, jobs, file, title):
    """Writes `file` (PNG): a grid of the jobs' curvature.png (a grey square where a job has
    none), each titled with its varied parameters, height and global total curvature."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.image as mpimg
    import matplotlib.pyplot as plt

    params = [c for c in table.columns if any(c in j["params"] for j in jobs)]
    n = len(table)
    cols = min(6, max(1, n))
    rows = math.ceil(n / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(2.6 * cols, 2.9 * rows), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for ax, (_, row) in zip(axes.flat, table.iterrows()):
        out = row.get("out")  # NaN for a job whose workers died with it
        picture = Path(out) / "curvature.png" if isinstance(out, str) and out else None
        if picture is not None and picture.is_file():
            ax.imshow(mpimg.imread(picture))
        else:
            ax.imshow([[0.85]], cmap="gray", vmin=0, vmax=1)
        ax.set_title(_label(row, params), fontsize=7)
    fig.suptitle(f"{title}: curvature of each released form", fontsize=10)
    fig.tight_layout()
    fig.savefig(file, dpi=90)
    plt.close(fig)
