"""The stencil as a fabricator's tools read it: pattern.dxf through ezdxf, pattern.svg as XML,
each against the ellipse example's exact resin area (docs/outputs.md, "The stencil")."""

import math
import subprocess
import xml.etree.ElementTree as ET

import ezdxf
from ezdxf import path as dxf_path

# The example's resin: an ellipse of radii 120 x 80 mm and 24 squares of 15 mm, none overlapping.
RESIN_MM2 = math.pi * 120 * 80 + 24 * 15 * 15


def shoelace(points):
    return 0.5 * sum(x0 * y1 - x1 * y0
                     for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1]))


def run_ellipse(cli, root, out):
    run = subprocess.run([cli, "run", str(root / "examples" / "synclastic_ellipse.json"),
                          "--set", "sheet.resolution=[9,9]", "-o", str(out)],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    return out


def test_the_dxf_holds_the_ellipse_and_squares_at_true_scale(cli, root, tmp_path):
    out = run_ellipse(cli, root, tmp_path / "run")
    doc = ezdxf.readfile(out / "pattern.dxf")
    resin = [e for e in doc.modelspace() if e.dxf.layer == "RESIN"]
    ellipses = [e for e in resin if e.dxftype() == "ELLIPSE"]
    squares = [e for e in resin if e.dxftype() == "LWPOLYLINE"]
    assert len(ellipses) == 1 and len(squares) == 24
    e = ellipses[0]
    assert math.isclose(e.dxf.major_axis.magnitude, 120, rel_tol=1e-9)
    assert math.isclose(e.dxf.ratio, 80 / 120, rel_tol=1e-9)
    assert all(len(s.get_points()) == 4 and s.closed for s in squares)
    area = sum(abs(shoelace([(v.x, v.y) for v in dxf_path.make_path(x).flattening(0.001)]))
               for x in resin)
    assert math.isclose(area, RESIN_MM2, rel_tol=1e-3)
    frame = [e for e in doc.modelspace() if e.dxf.layer == "FRAME"]
    assert len(frame) == 1 and doc.header["$INSUNITS"] == 4  # millimetres


def test_the_svg_holds_one_ellipse_and_four_point_squares(cli, root, tmp_path):
    out = run_ellipse(cli, root, tmp_path / "run")
    ns = {"svg": "http://www.w3.org/2000/svg"}
    svg = ET.parse(out / "pattern.svg").getroot()
    assert svg.get("width") == "300.0000mm"
    resin = svg.find("svg:g[@id='resin']", ns)
    ellipses = resin.findall("svg:ellipse", ns)
    polygons = resin.findall("svg:polygon", ns)
    assert len(ellipses) == 1 and len(polygons) == 24
    area = math.pi * float(ellipses[0].get("rx")) * float(ellipses[0].get("ry"))
    for p in polygons:
        corners = [tuple(map(float, xy.split(","))) for xy in p.get("points").split()]
        assert len(corners) == 4
        area += abs(shoelace(corners))
    assert math.isclose(area, RESIN_MM2, rel_tol=1e-9)
