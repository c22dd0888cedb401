"""report.html in a real browser: Debian's Chromium, headless, loads a run's page from file://,
waits for the 3-D view (three.js + the inlined final.glb), and is checked for errors and for a
form drawn in colour. The screenshot is kept as build/Testing/report_page.png to look at."""
import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import matplotlib.image

MEMBRA = os.environ["MEMBRA_CLI"]
SOURCE = Path(__file__).resolve().parents[2]
SHOT_DIR = Path(os.environ.get("MEMBRA_TEST_OUTPUT", tempfile.gettempdir()))
CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
# As root in a container: no sandbox; software WebGL; nothing that reaches for the network.
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
         "--enable-unsafe-swiftshader", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--window-size=1300,1000", "--enable-logging=stderr", "--v=0"]
# Chromium's virtual time does not wait for the page's own asynchronous work (parsing the GLB,
# compiling shaders in software): on a loaded machine a 20 s budget can end before the first
# frame. A page that is not ready is loaded again with a longer budget; one that never gets
# ready within the last still fails.
BUDGETS_MS = (20000, 60000, 120000)


def chromium(page, profile, *extra, budget=BUDGETS_MS[0]):
    cmd = [CHROMIUM, *FLAGS, f"--virtual-time-budget={budget}", f"--user-data-dir={profile}",
           *extra, page.as_uri()]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=240)


def ready_dom(page, profile):
    """The page's DOM once its 3-D view has marked itself ready (or the last attempt's)."""
    for budget in BUDGETS_MS:
        dom = chromium(page, profile, "--dump-dom", budget=budget)
        if dom.returncode == 0 and 'data-view="ready"' in dom.stdout:
            break
    return dom


def coloured_share(shot, rect):
    img = matplotlib.image.imread(shot)[..., :3]
    x, y, w, h = (int(round(v)) for v in rect)
    view = img[y + 2:y + h - 2, x + 2:x + w - 2]
    assert view.size > 0
    saturation = view.max(axis=2) - view.min(axis=2)
    return img, view, saturation > 0.35


def drawn_screenshot(page, profile, shot, rect):
    """A screenshot with the form drawn (or the last attempt's), as for ready_dom."""
    for budget in BUDGETS_MS:
        res = chromium(page, profile, f"--screenshot={shot}", budget=budget)
        if res.returncode == 0 and shot.exists() and coloured_share(shot, rect)[2].mean() > 0.03:
            break
    return res


def run_scene(out):
    subprocess.run([MEMBRA, "run", str(SOURCE / "examples/synclastic_ellipse.json"),
                    "--set", "sheet.resolution=[13,13]", "--set", "simulation.solver=newton",
                    "--out", str(out), "-q"], check=True, timeout=300)


def console_errors(stderr):
    return [line for line in stderr.splitlines()
            if "CONSOLE" in line and re.search(r"Uncaught|Error|error", line)
            and "GL Driver Message" not in line]


def test_report_page_shows_the_form_in_colour(tmp_path):
    out = tmp_path / "run"
    run_scene(out)
    assert not (out / "report_files").exists()
    # One file: the page alone, away from the run's other files, still shows everything.
    alone = tmp_path / "alone"
    alone.mkdir()
    page = alone / "report.html"
    shutil.copy(out / "report.html", page)

    dom = ready_dom(page, tmp_path / "profile1")
    assert dom.returncode == 0, dom.stderr[-2000:]
    body = re.search(r"<body[^>]*>", dom.stdout).group(0)
    assert 'data-view="ready"' in body, body + dom.stderr[-3000:]
    assert "data-errors" not in body, dom.stdout[-3000:]
    assert console_errors(dom.stderr) == []
    rect = [float(v) for v in re.search(r'data-view-rect="([^"]+)"', body).group(1).split(",")]

    shot = tmp_path / "page.png"
    res = drawn_screenshot(page, tmp_path / "profile2", shot, rect)
    assert res.returncode == 0 and shot.exists(), res.stderr[-2000:]
    assert console_errors(res.stderr) == []
    SHOT_DIR.mkdir(parents=True, exist_ok=True)
    shutil.copy(shot, SHOT_DIR / "report_page.png")

    # The form in the map's colours: strongly saturated pixels (the background is white, the
    # shading grey), covering a real share of the view, and more than one hue.
    img, view, coloured = coloured_share(shot, rect)
    assert coloured.mean() > 0.03, f"only {coloured.mean():.4f} of the view is coloured"
    hues = view[coloured].argmax(axis=1)
    assert len(set(hues.tolist())) >= 2, "one hue only"
    # The page around the view is mostly white: the view, not the whole page, holds the colour.
    assert (img[:40].min(axis=2) > 0.9).mean() > 0.9


def test_page_without_three_js_says_why(tmp_path):
    out = tmp_path / "run"
    env = dict(os.environ, MEMBRA_THREE_JS=str(tmp_path / "nowhere"))
    subprocess.run([MEMBRA, "run", str(SOURCE / "examples/exp1_basic.json"),
                    "--set", "sheet.resolution=[9,9]", "--out", str(out), "-q"],
                   check=True, timeout=300, env=env)
    html = (out / "report.html").read_text()
    assert "No 3-D view: three.js was not found" in html
    assert not (out / "report_files").exists()
