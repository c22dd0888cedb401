"""A sweep's report.html: one sortable table of its scenes (click a column's heading), each row
with its parameters, its form and a thumbnail of its curvature picture that links to the scene's
own report.html. Plain HTML and a few lines of script, so it opens from file:// anywhere."""

import html
import math
import os
from pathlib import Path

_SCRIPT = """
document.querySelectorAll('th').forEach(function (th, col) {
  th.addEventListener('click', function () {
    const body = th.closest('table').tBodies[0];
    const rows = Array.from(body.rows);
    const up = th.dataset.order !== 'up';
    document.querySelectorAll('th').forEach(function (h) { delete h.dataset.order; });
    th.dataset.order = up ? 'up' : 'down';
    rows.sort(function (a, b) {
      const x = a.cells[col].dataset.value, y = b.cells[col].dataset.value;
      const nx = parseFloat(x), ny = parseFloat(y);
      const c = (isNaN(nx) || isNaN(ny)) ? x.localeCompare(y) : nx - ny;
      return up ? c : -c;
    });
    rows.forEach(function (r) { body.appendChild(r); });
  });
});
"""

_STYLE = """
body { font-family: "DejaVu Sans", system-ui, sans-serif; margin: 1.5em; color: #1a1a1a; }
table { border-collapse: collapse; } th { cursor: pointer; background: #f2f2f2; user-select: none; }
th, td { padding: 0.3em 0.6em; border-bottom: 1px solid #ddd; text-align: left; }
th[data-order=up]::after { content: " \\25B2"; } th[data-order=down]::after { content: " \\25BC"; }
td img { height: 90px; display: block; } .failed { color: #a00; } .note { color: #666; }
"""

_UNITS = {"height": "mm", "global_height": "mm", "total_K": "rad", "total_K_global": "rad",
          "quadric_k1": "1/m", "quadric_k2": "1/m", "design_error": "%", "wall_seconds": "s"}


def _cell(value):
    """(text shown, value sorted by) of one table cell."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "", ""
    if isinstance(value, float):
        return f"{value:.4g}", repr(value)
    return str(value), str(value)


def write_sweep_page(table, params, out, title):
    """Writes out/report.html for the sweep's `table` (a DataFrame as membra.sweep returns);
    `params` are the varied parameters' columns."""
    out = Path(out)
    columns = ["id"] + list(params) + ["classification", "quadric", "height", "global_height",
                                       "total_K", "total_K_global", "quadric_k1", "quadric_k2",
                                       "design_error", "converged", "stable", "self_intersection",
                                       "wall_seconds"]
    columns = [c for c in columns if c in table.columns and table[c].notna().any()]
    failed = int((table["error"].fillna("") != "").sum())
    lines = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
             f"<title>{html.escape(title)} — membra sweep</title><style>{_STYLE}</style></head>",
             f"<body><h1>{html.escape(title)}</h1>",
             f'<p class="note">{len(table)} scenes, {failed} failed. Click a heading to sort; a '
             'picture opens the scene\'s own page. Every number is also in '
             '<a href="results.csv">results.csv</a>; all pictures in '
             '<a href="contact_sheet.png">contact_sheet.png</a> (one colour range and scale), each '
             'parameter against the form in <a href="parameters.png">parameters.png</a>, the '
             'short column names\' paths in <a href="parameters.json">parameters.json</a>.</p>',
             "<table><thead><tr><th>form</th>"]
    for c in columns:
        unit = _UNITS.get(c)
        lines.append(f"<th>{html.escape(c)}{f' ({unit})' if unit else ''}</th>")
    lines.append("<th>error</th></tr></thead><tbody>")
    for _, row in table.iterrows():
        folder = Path(row["out"]) if isinstance(row.get("out"), str) and row["out"] else None
        rel = os.path.relpath(folder, out) if folder else None
        picture = ""
        if folder and (folder / "curvature.png").exists():
            target = f"{rel}/report.html" if (folder / "report.html").exists() else f"{rel}/curvature.png"
            picture = f'<a href="{html.escape(target)}"><img src="{html.escape(rel)}/curvature.png" alt=""></a>'
        cells = [f'<td data-value="{row["id"]}">{picture}</td>']
        for c in columns:
            shown, key = _cell(row[c])
            cells.append(f'<td data-value="{html.escape(key)}">{html.escape(shown)}</td>')
        error = str(row.get("error") or "")
        cells.append(f'<td class="failed" data-value="{html.escape(error)}">{html.escape(error)}</td>')
        lines.append("<tr>" + "".join(cells) + "</tr>")
    lines.append(f"</tbody></table><script>{_SCRIPT}</script></body></html>")
    (out / "report.html").write_text("\n".join(lines) + "\n", encoding="utf-8")
