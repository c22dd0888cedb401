"""A result's inline 3-D view for Jupyter (Result._repr_html_): the released form on a canvas,
drag to turn, coloured by Gaussian curvature, with its key numbers. Self-contained (no
three.js, no network): the page draws the triangles back to front with plain canvas calls."""

import html
import json
import uuid

import numpy as np

# ColorBrewer's RdBu, readable with every common colour-vision deficiency: blue where the form
# is saddle-like (K < 0), white where flat, red where dome-like (K > 0), as membra's pictures.
_DIVERGING = np.array([
    [5, 48, 97], [33, 102, 172], [67, 147, 195], [146, 197, 222], [209, 229, 240],
    [247, 247, 247], [253, 219, 199], [244, 165, 130], [214, 96, 77], [178, 24, 43],
    [103, 0, 31]], dtype=float)


def diverging_colours(values, limit):
    """RGB rows (0..255) for values on [-limit, limit] (saturating beyond)."""
    t = np.clip((np.asarray(values, dtype=float) / limit + 1.0) * 0.5, 0.0, 1.0)
    x = t * (len(_DIVERGING) - 1)
    i = np.minimum(x.astype(int), len(_DIVERGING) - 2)
    f = (x - i)[:, None]
    return (_DIVERGING[i] * (1 - f) + _DIVERGING[i + 1] * f).round().astype(int)


_SCRIPT = """
(function() {
  const d = %(data)s, c = document.getElementById(%(id)s), g = c.getContext("2d");
  let yaw = -0.6, pitch = 0.9, drag = null;
  function draw() {
    const cy = Math.cos(yaw), sy = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
    const P = [];
    for (let i = 0; i < d.x.length; i += 3) {  // turn about z, then tilt towards the viewer
      const x = d.x[i] * cy - d.x[i + 1] * sy, y = d.x[i] * sy + d.x[i + 1] * cy, z = d.x[i + 2];
      P.push([x, y * cp - z * sp, y * sp + z * cp]);
    }
    const order = [];
    for (let t = 0; t < d.t.length; t += 3) {
      const a = P[d.t[t]], b = P[d.t[t + 1]], e = P[d.t[t + 2]];
      order.push([a[1] + b[1] + e[1], t]);
    }
    order.sort((p, q) => q[0] - p[0]);  // far (large depth) first
    g.fillStyle = "#fff"; g.fillRect(0, 0, c.width, c.height);
    const s = 0.45 * Math.min(c.width, c.height) / d.r, ox = c.width / 2, oy = c.height / 2;
    for (const [, t] of order) {
      const a = P[d.t[t]], b = P[d.t[t + 1]], e = P[d.t[t + 2]];
      const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]], v = [e[0] - a[0], e[1] - a[1], e[2] - a[2]];
      const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
      const len = Math.hypot(n[0], n[1], n[2]) || 1;
      const light = 0.35 + 0.65 * Math.abs((0.3 * n[0] - 0.8 * n[1] + 0.5 * n[2]) / len);
      const k = t, col = [d.c[k], d.c[k + 1], d.c[k + 2]].map(q => Math.round(q * light));
      g.fillStyle = g.strokeStyle = "rgb(" + col.join(",") + ")";
      g.beginPath();
      g.moveTo(ox + s * a[0], oy - s * a[2]); g.lineTo(ox + s * b[0], oy - s * b[2]);
      g.lineTo(ox + s * e[0], oy - s * e[2]); g.closePath(); g.fill(); g.stroke();
    }
  }
  c.onmousedown = ev => { drag = [ev.clientX, ev.clientY]; };
  window.addEventListener("mouseup", () => { drag = null; });
  c.onmousemove = ev => {
    if (!drag) return;
    yaw += (ev.clientX - drag[0]) * 0.01;
    pitch = Math.max(-1.6, Math.min(1.6, pitch + (ev.clientY - drag[1]) * 0.01));
    drag = [ev.clientX, ev.clientY]; draw();
  };
  draw();
})();
"""


def result_html(positions, triangles, curvature, title, facts, size=(480, 360)):
    """The view as an HTML fragment: positions (n, 3) mm, triangles (m, 3), curvature (n,)
    1/m^2, facts: (label, text) rows shown beside it."""
    x = np.asarray(positions, dtype=float)
    x = x - 0.5 * (x.min(axis=0) + x.max(axis=0))
    tri = np.asarray(triangles, dtype=np.int64)
    k = np.asarray(curvature, dtype=float)[tri].mean(axis=1)
    limit = float(np.percentile(np.abs(k), 95)) if len(k) else 0.0
    limit = limit if limit > 0 else 1.0
    colours = diverging_colours(k, limit)
    data = {"x": np.round(x, 2).ravel().tolist(), "t": tri.ravel().tolist(),
            "c": colours.ravel().tolist(), "r": float(np.linalg.norm(x, axis=1).max() or 1.0)}
    canvas_id = "membra-" + uuid.uuid4().hex[:12]
    rows = "".join(f"<tr><td style='padding-right:1em;color:#555;white-space:nowrap;vertical-align:top'>{html.escape(a)}</td>"
                   f"<td>{html.escape(b)}</td></tr>" for a, b in facts)
    legend = (f"colour: Gaussian curvature, blue {-limit:.3g} .. white 0 .. red "
              f"{limit:.3g} 1/m² (95 % of |K|); drag to turn")
    return (f"<div style='display:flex;gap:1em;align-items:flex-start;font:13px sans-serif'>"
            f"<div><canvas id='{canvas_id}' width='{size[0]}' height='{size[1]}' "
            f"style='border:1px solid #ddd;cursor:grab'></canvas>"
            f"<div style='color:#555;font-size:11px'>{html.escape(legend)}</div></div>"
            f"<div style='max-width:28em'><b>{html.escape(title)}</b><table>{rows}</table></div></div>"
            f"<script>{_SCRIPT % {'data': json.dumps(data), 'id': json.dumps(canvas_id)}}</script>")
