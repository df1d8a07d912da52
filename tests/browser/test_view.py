"""`eulerdyn view` pages in a real browser: Debian's Chromium, headless, driven by Playwright.

Each page is opened from disk with every network request blocked; a test fails on any request other than the
page itself and the blob:/data: URLs the page makes, on any console error and on any uncaught exception. The
page's `window.eulerdyn.state()` is checked against the run's CSV at the row times, the drawing against a blank
canvas, and two times against each other.

Run by `.ci/browser-tests` (which builds the binary and makes the venv). Environment:
  EULERDYN_BIN                the eulerdyn binary (default: target/release/eulerdyn)
  CHROMIUM                    the browser (default: /usr/bin/chromium)
  EULERDYN_VIEW_SCREENSHOT    if set, the tilted disk's screenshot is written there (docs/tilted_disk_view.png)
  EULERDYN_VIEW_REPORT        if set, page sizes and open times are appended there (measurements, not checks)
  EULERDYN_VIEW_SCREENSHOT_DIR  if set, the rod pendulum's view at t = 0 is written there as rod_t0.png
"""

import csv
import json
import math
import os
import shutil
import subprocess
import time
from pathlib import Path

import pytest
from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[2]
BIN = Path(os.environ.get("EULERDYN_BIN", ROOT / "target" / "debug" / "eulerdyn"))
CHROMIUM = Path(os.environ.get("CHROMIUM", "/usr/bin/chromium"))
# WebGL without a GPU: Chromium's software renderer.
CHROMIUM_ARGS = ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist"]
VIEWPORT = {"width": 1200, "height": 800}
# The canvas's clear colour (view.css and scene.js): #f4f5f7.
BACKGROUND = (0xF4, 0xF5, 0xF7)


def eulerdyn(*args):
    """Runs the binary; returns the completed process (stdout, stderr as text)."""
    return subprocess.run([str(BIN), *map(str, args)], capture_output=True, text=True, check=False)


def read_csv(path):
    """The CSV's rows as dicts of floats (Python's float() is correctly rounded, as JSON.parse is)."""
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def report(line):
    """Appends a measurement to $EULERDYN_VIEW_REPORT (and prints it: pytest -s shows it)."""
    print(line)
    if os.environ.get("EULERDYN_VIEW_REPORT"):
        with open(os.environ["EULERDYN_VIEW_REPORT"], "a") as f:
            f.write(line + "\n")


@pytest.fixture(scope="session")
def work(tmp_path_factory):
    assert BIN.is_file(), f"{BIN} is missing: build it first (cargo build --release)"
    return tmp_path_factory.mktemp("view")


def make_page(work, scenario, name, *run_args):
    """Runs `scenario` and writes its page; returns (csv path, html path, view's stderr)."""
    csv_path = work / f"{name}.csv"
    html_path = work / f"{name}.html"
    run = eulerdyn("run", ROOT / "scenarios" / scenario, "-o", csv_path, *run_args)
    assert run.returncode == 0, run.stderr
    view = eulerdyn("view", csv_path, "-o", html_path)
    assert view.returncode == 0, view.stderr
    return csv_path, html_path, view.stderr


@pytest.fixture(scope="session")
def disk(work):
    return make_page(work, "tilted_disk.toml", "disk")


@pytest.fixture(scope="session")
def racket(work):
    return make_page(work, "tennis_racket.toml", "racket")


@pytest.fixture(scope="session")
def browser():
    assert CHROMIUM.is_file(), f"{CHROMIUM} is missing: install Debian's chromium (apt-get install -y chromium)"
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        yield b
        b.close()


class Page:
    """An open page with its requests and console errors recorded; network requests are blocked."""

    def __init__(self, browser, html_path, fragment=""):
        self.url = html_path.resolve().as_uri()
        self.context = browser.new_context(viewport=VIEWPORT)
        self.page = self.context.new_page()
        self.requests = []
        self.errors = []
        self.page.on("request", lambda r: self.requests.append(r.url))
        self.page.on("console", lambda m: m.type == "error" and self.errors.append(f"console: {m.text}"))
        self.page.on("pageerror", lambda e: self.errors.append(f"pageerror: {e}"))
        self.context.route("**/*", self._route)
        started = time.monotonic()
        self.page.goto(self.url + fragment)
        self.wait_drawn()
        self.open_seconds = time.monotonic() - started

    def _route(self, route):
        if route.request.url == self.url:
            route.continue_()
        else:
            route.abort()

    def wait_drawn(self, timeout=60.0):
        """Waits for the first frame. (Polled from here: the page's CSP forbids the eval that
        wait_for_function would need.)"""
        end = time.monotonic() + timeout
        while not self.page.evaluate("!!(window.eulerdyn && window.eulerdyn.drawn)"):
            assert not self.errors, self.errors
            assert time.monotonic() < end, "the page never drew a frame"
            time.sleep(0.05)

    def js(self, expression, arg=None):
        return self.page.evaluate(expression, arg)

    def check_clean(self):
        """No request but the page and blob:/data: URLs; no console error or exception."""
        foreign = [u for u in self.requests if u != self.url and not u.startswith(("blob:", "data:"))]
        assert not foreign, f"the page made network requests: {foreign}"
        assert self.url in self.requests
        assert not self.errors, self.errors

    def canvas_pixels(self):
        """The canvas read back in the page: its size, how many pixels are not the background, and how many differ
        from the previous call's (all of them on the first call)."""
        return self.js("""(bg) => {
            const c = document.getElementById('scene');
            const copy = document.createElement('canvas');
            copy.width = c.width; copy.height = c.height;
            const ctx = copy.getContext('2d');
            ctx.drawImage(c, 0, 0);
            const px = ctx.getImageData(0, 0, c.width, c.height).data;
            const prev = window.__testPixels;
            let drawn = 0, changed = 0;
            for (let k = 0; k < px.length; k += 4) {
                if (Math.abs(px[k] - bg[0]) + Math.abs(px[k + 1] - bg[1]) + Math.abs(px[k + 2] - bg[2]) > 24) drawn++;
                if (!prev || prev[k] !== px[k] || prev[k + 1] !== px[k + 1] || prev[k + 2] !== px[k + 2]) changed++;
            }
            window.__testPixels = px;
            return { width: c.width, height: c.height, drawn: drawn, changed: changed };
        }""", list(BACKGROUND))

    def close(self):
        self.check_clean()
        self.context.close()


@pytest.fixture
def open_page(browser):
    pages = []

    def opener(html_path, fragment=""):
        p = Page(browser, html_path, fragment)
        pages.append(p)
        return p

    yield opener
    for p in pages:
        p.close()


def states_at(page, times):
    """state() after setTime(t) for each t, in one call."""
    return page.js("(ts) => ts.map((t) => { window.eulerdyn.setTime(t); return window.eulerdyn.state(); })", times)


def check_rows(page, rows):
    """state() at every row time equals the row's H_s and q: to 1e-9, and in fact bit for bit."""
    states = states_at(page, [r["t"] for r in rows])
    for row, s in zip(rows, states):
        expected_h = [row["H_s_x"], row["H_s_y"], row["H_s_z"]]
        expected_q = [row["q_w"], row["q_x"], row["q_y"], row["q_z"]]
        assert s["t"] == row["t"]
        for got, want in zip(s["H_s"] + s["q"], expected_h + expected_q):
            assert abs(got - want) <= 1e-9, (row["t"], s, row)
        assert s["H_s"] == expected_h and s["q"] == expected_q, (row["t"], s, row)
        assert s["omega_s"] == [row["omega_s_x"], row["omega_s_y"], row["omega_s_z"]]
        assert s["M_s"] == [row["M_s_x"], row["M_s_y"], row["M_s_z"]]


@pytest.mark.parametrize("fixture", ["disk", "racket"])
def test_the_page_opens_offline_and_matches_the_csv_at_every_row(fixture, request, open_page):
    csv_path, html_path, _ = request.getfixturevalue(fixture)
    rows = read_csv(csv_path)
    page = open_page(html_path)
    report(f"{fixture}: {len(rows)} rows, page {html_path.stat().st_size / 1e6:.2f} MB, "
           f"opened and drawn in {page.open_seconds:.2f} s")
    api = page.js("() => ({ n: window.eulerdyn.rows.length, t_end: window.eulerdyn.t_end, "
                  "keys: Object.keys(window.eulerdyn) })")
    assert api["n"] == len(rows)
    assert api["t_end"] == rows[-1]["t"]
    for key in ("rows", "t_end", "setTime", "state"):
        assert key in api["keys"]
    check_rows(page, rows)
    page.check_clean()


@pytest.mark.parametrize("fixture", ["disk", "racket"])
def test_between_rows_the_state_is_interpolated(fixture, request, open_page):
    csv_path, html_path, _ = request.getfixturevalue(fixture)
    rows = read_csv(csv_path)
    page = open_page(html_path)
    a, b = rows[10], rows[11]
    mid = states_at(page, [(a["t"] + b["t"]) / 2])[0]
    for axis in "xyz":
        want = (a[f"H_s_{axis}"] + b[f"H_s_{axis}"]) / 2
        assert abs(mid["H_s"]["xyz".index(axis)] - want) <= 1e-12 * max(1.0, abs(want))
    q = mid["q"]
    assert abs(math.fsum(x * x for x in q) - 1) < 1e-12
    qa = [a[f"q_{c}"] for c in "wxyz"]
    qb = [b[f"q_{c}"] for c in "wxyz"]
    # The slerp midpoint is equally far from both ends (angles between unit quaternions, up to sign).
    da = abs(sum(x * y for x, y in zip(q, qa)))
    db = abs(sum(x * y for x, y in zip(q, qb)))
    assert abs(da - db) < 1e-9 and da < 1.0
    # Outside the run, the first and last rows.
    first, last = states_at(page, [-5.0, rows[-1]["t"] + 5.0])
    assert first["q"] == [rows[0][f"q_{c}"] for c in "wxyz"]
    assert last["t"] == rows[-1]["t"]


@pytest.mark.parametrize("fixture", ["disk", "racket"])
def test_the_drawing_is_not_blank_and_moves_with_time(fixture, request, open_page):
    csv_path, html_path, _ = request.getfixturevalue(fixture)
    rows = read_csv(csv_path)
    page = open_page(html_path)
    t1, t2 = rows[0]["t"], rows[len(rows) * 2 // 5]["t"]
    page.js("(t) => window.eulerdyn.setTime(t)", t1)
    first = page.canvas_pixels()
    shot1 = page.page.screenshot()
    page.js("(t) => window.eulerdyn.setTime(t)", t2)
    second = page.canvas_pixels()
    shot2 = page.page.screenshot()
    width, height = first["width"], first["height"]
    assert width > 0 and height > 0
    # A blank canvas has no pixel but the background; the body, axes and arrows cover some thousands.
    assert first["drawn"] > 2000, f"only {first['drawn']} drawn pixels of {width * height}"
    assert second["drawn"] > 2000, f"only {second['drawn']} drawn pixels of {width * height}"
    assert second["changed"] > 500, f"the drawing did not change between two times: {second}"
    assert shot1 != shot2
    if fixture == "disk" and os.environ.get("EULERDYN_VIEW_SCREENSHOT"):
        page.js("(t) => window.eulerdyn.setTime(t)", 0.3)
        page.page.screenshot(path=os.environ["EULERDYN_VIEW_SCREENSHOT"])


def test_controls_play_and_the_slider_move_the_time(disk, open_page):
    _, html_path, _ = disk
    page = open_page(html_path)
    page.js("() => window.eulerdyn.setTime(0)")
    page.page.click("#play")
    page.page.wait_for_timeout(400)
    t = page.js("() => window.eulerdyn.state().t")
    assert 0 < t <= 1.0, t
    page.page.click("#play")  # pause
    # The slider's middle: t = 0.5 of 1.0.
    page.js("() => { const s = document.getElementById('time'); s.value = '50000'; "
            "s.dispatchEvent(new Event('input')); }")
    assert abs(page.js("() => window.eulerdyn.state().t") - 0.5) < 1e-9
    readout = page.page.inner_text("#readout")
    assert "t = 0.5000" in readout and "H_s" in readout and "kg*m^2/s" in readout
    assert page.js("() => document.getElementById('polhode-toggle').hidden"), "a fixed-axis run has no polhode"


def test_a_free_run_shows_the_polhode_and_a_fixed_axis_run_its_axis(racket, disk, open_page):
    page = open_page(racket[1])
    assert page.js("() => !document.getElementById('polhode-frame').hidden")
    assert page.js("() => window.eulerdyn.geometry.motion") == "free"
    page = open_page(disk[1])
    geometry = page.js("() => window.eulerdyn.geometry")
    assert geometry["motion"] == "fixed_axis" and geometry["body"]["kind"] == "thin_disk"
    assert geometry["body"]["radius"] == 0.3
    assert len(geometry["axis_b"]) == 3


def test_bearing_forces_are_drawn_where_the_run_has_them(work, open_page):
    csv_path, html_path, _ = make_page(work, "rotor_bearings.toml", "rotor", "--t-end", "0.5")
    page = open_page(html_path)
    vectors = page.js("() => window.eulerdyn.vectors")
    assert "R_A_s" in vectors and "R_B_s" in vectors
    rows = read_csv(csv_path)
    s = states_at(page, [rows[3]["t"]])[0]
    assert s["R_A_s"] == [rows[3]["R_A_s_x"], rows[3]["R_A_s_y"], rows[3]["R_A_s_z"]]
    assert "R_A" in page.page.inner_text("#legend")


def test_in_orbit_nadir_and_the_field_are_drawn_as_directions(work, open_page):
    # Nadir from the orbital elements: -r_hat = -R_z(raan) R_x(i) (cos u, sin u, 0), u = n t (the scenario's orbit:
    # 500 km, i = 97.4 deg, raan = 0, u0 = 0; n = sqrt(mu / r^3)); the field's direction q B_b / |B_b| from the CSV.
    csv_path, html_path, _ = make_page(work, "cubesat_b_dot.toml", "cubesat", "--t-end", "600")
    page = open_page(html_path)
    vectors = page.js("() => window.eulerdyn.vectors")
    assert "nadir_s" in vectors and "field_s" in vectors, vectors
    rows = read_csv(csv_path)
    r = 6378.137e3 + 500e3
    n = math.sqrt(3.986004418e14 / r**3)
    inc = math.radians(97.4)
    picked = [rows[k] for k in (0, 7, 30, len(rows) - 1)]
    for row, s in zip(picked, states_at(page, [row["t"] for row in picked])):
        u = n * row["t"]
        nadir = [-math.cos(u), -math.sin(u) * math.cos(inc), -math.sin(u) * math.sin(inc)]
        # The page evaluates the same closed form from the sidecar's orbit: agreement to rounding, 1e-12.
        assert max(abs(a - b) for a, b in zip(s["nadir_s"], nadir)) < 1e-12, (row["t"], s["nadir_s"], nadir)
        q = [row["q_w"], row["q_x"], row["q_y"], row["q_z"]]
        b = [row["B_b_x"], row["B_b_y"], row["B_b_z"]]
        b_s = rotate(q, [x / math.hypot(*b) for x in b])
        assert max(abs(a - c) for a, c in zip(s["field_s"], b_s)) < 1e-12, (row["t"], s["field_s"], b_s)
    legend = page.page.inner_text("#legend")
    assert "nadir" in legend and "magnetic field" in legend


def rotate(q, v):
    """v turned by the unit quaternion q = (w, x, y, z): the rotation matrix of Shuster (1993), eq. 161, applied."""
    w, x, y, z = q
    m = [
        [w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z],
    ]
    return [sum(m[i][k] * v[k] for k in range(3)) for i in range(3)]


def test_without_the_sidecar_the_page_draws_the_csv_and_says_what_is_missing(disk, work, open_page):
    csv_path = work / "lonely.csv"
    shutil.copy(disk[0], csv_path)
    html_path = work / "lonely.html"
    view = eulerdyn("view", csv_path, "-o", html_path)
    assert view.returncode == 0, view.stderr
    assert "no sidecar" in view.stderr and "lonely.csv.meta.json" in view.stderr
    page = open_page(html_path)
    notes = page.page.inner_text("#notes")
    assert "no sidecar" in notes and "unit cube" in notes
    check_rows(page, read_csv(csv_path)[:20])


def synthetic_disk_rows(template, n, every):
    """n rows of the tilted disk turning at 10 rad/s about space z, from the first row of a real run: q, ω_s, H_s
    and M_s turn about z; the body-axes columns are constant."""
    head = list(template.keys())
    omega = 10.0
    q0 = [template[f"q_{c}"] for c in "wxyz"]
    h0 = [template["H_s_x"], template["H_s_y"], template["H_s_z"]]
    lines = [",".join(head)]
    for k in range(n):
        t = k * every
        th = omega * t
        c, s = math.cos(th), math.sin(th)
        cz, sz = math.cos(th / 2), math.sin(th / 2)
        # q = (cos θ/2, 0, 0, sin θ/2) ⊗ q0
        w0, x0, y0, z0 = q0
        q = [cz * w0 - sz * z0, cz * x0 - sz * y0, cz * y0 + sz * x0, cz * z0 + sz * w0]
        h = [c * h0[0] - s * h0[1], s * h0[0] + c * h0[1], h0[2]]
        m = [-omega * h[1], omega * h[0], 0.0]
        row = dict(template)
        row.update(t=t, q_w=q[0], q_x=q[1], q_y=q[2], q_z=q[3], omega_s_x=0.0, omega_s_y=0.0, omega_s_z=omega,
                   H_s_x=h[0], H_s_y=h[1], H_s_z=h[2], M_s_x=m[0], M_s_y=m[1], M_s_z=m[2])
        lines.append(",".join(repr(row[k2]) for k2 in head))
    return "\n".join(lines) + "\n"


def test_a_run_of_a_million_rows_is_decimated_by_the_stated_rule(disk, work, open_page):
    n = 1_000_001
    template = read_csv(disk[0])[0]
    csv_path = work / "million.csv"
    csv_path.write_text(synthetic_disk_rows(template, n, 0.01))
    shutil.copy(str(disk[0]) + ".meta.json", str(csv_path) + ".meta.json")
    html_path = work / "million.html"
    started = time.monotonic()
    view = eulerdyn("view", csv_path, "-o", html_path)
    view_seconds = time.monotonic() - started
    assert view.returncode == 0, view.stderr
    page = open_page(html_path)
    report(f"million: {n} rows, csv {csv_path.stat().st_size / 1e6:.0f} MB, view {view_seconds:.1f} s, "
           f"page {html_path.stat().st_size / 1e6:.2f} MB, opened and drawn in {page.open_seconds:.2f} s")
    api = page.js("() => ({ n: window.eulerdyn.rows.length, stride: window.eulerdyn.stride, "
                  "in_run: window.eulerdyn.rows_in_run, note: window.eulerdyn.rows_note })")
    # ceil(1000001 / 64) > 10000 >= ceil(1000001 / 128): every 128th row, plus the last.
    assert api["stride"] == 128 and api["in_run"] == n
    assert api["n"] == len(range(0, n, 128)) + 1
    assert "every 128th row" in api["note"]
    assert "every 128th row" in page.page.inner_text("#notes")
    rows = read_csv_rows_at(csv_path, [0, 128, 256 * 1000, 128 * 7812, n - 1])
    check_rows(page, rows)
    assert page.js("() => window.eulerdyn.t_end") == rows[-1]["t"]


def read_csv_rows_at(path, indices):
    """The data rows at `indices` (0-based) of a CSV, as dicts of floats."""
    wanted = set(indices)
    out = {}
    with open(path, newline="") as f:
        for k, row in enumerate(csv.DictReader(f)):
            if k in wanted:
                out[k] = {key: float(v) for key, v in row.items()}
    return [out[k] for k in indices]


def test_the_page_embeds_everything_and_names_its_three_js(disk):
    html = disk[1].read_text()
    assert "Content-Security-Policy" in html and "default-src 'none'" in html
    for tag in ("<link", "src=\"http", "src='http", "@import", "url(http"):
        assert tag not in html, tag
    assert json.loads(html.split('id="eulerdyn-data">', 1)[1].split("</script>", 1)[0])["columns"][0] == "t"


@pytest.fixture(scope="session")
def rod(work):
    return make_page(work, "rod_pendulum.toml", "rod")


def visible_pixels(page, part):
    """How many canvas pixels change when `part` ('body', 'axes', 'vectors') is hidden: what of it shows."""
    page.canvas_pixels()
    page.js("(p) => window.eulerdyn.show(p, false)", part)
    changed = page.canvas_pixels()["changed"]
    page.js("(p) => window.eulerdyn.show(p, true)", part)
    page.canvas_pixels()
    return changed


def test_a_thin_rod_shows_at_t0_and_no_arrow_or_axis_lies_over_it(rod, open_page):
    _, html_path, _ = rod
    page = open_page(html_path)
    page.js("() => window.eulerdyn.setTime(0)")
    geometry = page.js("() => window.eulerdyn.geometry.body")
    assert geometry["kind"] == "thin_rod" and geometry["min_drawn_thickness"] == 0.05
    assert "at least 0.050 m thick" in page.page.inner_text("#legend")
    with_all = visible_pixels(page, "body")
    page.js("() => { window.eulerdyn.show('vectors', false); window.eulerdyn.show('axes', false); }")
    alone = visible_pixels(page, "body")
    page.js("() => { window.eulerdyn.show('vectors', true); window.eulerdyn.show('axes', true); }")
    if os.environ.get("EULERDYN_VIEW_SCREENSHOT_DIR"):
        page.page.screenshot(path=os.path.join(os.environ["EULERDYN_VIEW_SCREENSHOT_DIR"], "rod_t0.png"))
    report(f"rod at t = 0: {alone} pixels of the body alone, {with_all} with the axes and the vectors drawn")
    # The 1 m rod, 5 cm thick, seen from the first view at 1200 x 800 (with -g up): a solid, not a line (about
    # 1470 pixels; drawn 3.3 cm thick and seen along its length, as before, it covered about 750).
    assert alone > 1200, f"the rod covers only {alone} pixels"
    # The vectors start beside the body and the axes are thin lines: together they hide at most 10 % of it.
    assert with_all >= 0.9 * alone, f"{alone} pixels of the rod alone, {with_all} with the vectors and axes"
    origin = page.js("() => window.eulerdyn.vector_origin")
    assert math.hypot(*origin) > 1.0, f"the vectors start at {origin}, inside the rod's reach of 1 m"


def test_the_page_opens_at_the_time_in_its_fragment_and_keeps_it_in_step(rod, open_page):
    csv_path, html_path, _ = rod
    rows = read_csv(csv_path)
    page = open_page(html_path, "#t=0.44")
    s = page.js("() => window.eulerdyn.state()")
    row = next(r for r in rows if r["t"] == 0.44)
    assert s["t"] == 0.44 and s["H_s"] == [row["H_s_x"], row["H_s_y"], row["H_s_z"]], s
    assert "t = 0.4400" in page.page.inner_text("#readout")
    # Scrubbing to the middle writes the fragment (after a short pause), so that the address reopens there.
    page.js("() => { const s = document.getElementById('time'); s.value = '50000'; "
            "s.dispatchEvent(new Event('input')); }")
    end = time.monotonic() + 10
    while page.js("() => location.hash") != "#t=2.5":
        assert time.monotonic() < end, page.js("() => location.hash")
        time.sleep(0.05)
    # Editing the fragment moves the time.
    page.js("() => { location.hash = '#t=1.25'; }")
    end = time.monotonic() + 10
    while page.js("() => window.eulerdyn.state().t") != 1.25:
        assert time.monotonic() < end, page.js("() => window.eulerdyn.state().t")
        time.sleep(0.05)


def test_the_default_speed_plays_about_one_turn_per_second(work, disk, open_page):
    # A steel disk at 3000 rpm for 0.1 s: five turns, which 1x would play in 0.1 s.
    scene = work / "fast_disk.toml"
    scene.write_text('''name = "fast-disk"
[body]
mass = 4.9
shape = { type = "disk", radius = 0.1, thickness = 0.02 }
[motion]
type = "fixed_axis"
axis = [0.0, 0.0, 1.0]
rate = 314.1592653589793
[solver]
t_end = 0.1
[output]
every = 0.0002
''')
    csv_path = work / "fast_disk.csv"
    html_path = work / "fast_disk.html"
    assert eulerdyn("run", scene, "-o", csv_path).returncode == 0
    assert eulerdyn("view", csv_path, "-o", html_path).returncode == 0
    page = open_page(html_path)
    api = page.js("() => ({ speed: window.eulerdyn.clock.speed, rate: window.eulerdyn.typical_rate, "
                  "default: window.eulerdyn.default_speed })")
    # The rule: 2 pi / median |omega| = 0.02 s per second, already on the 1-2-5 ladder.
    assert abs(api["rate"] - 314.1592653589793) < 1e-9
    assert api["speed"] == api["default"] == 0.02
    turns_per_second = api["speed"] * api["rate"] / (2 * math.pi)
    assert 0.6 < turns_per_second < 1.6
    assert page.js("() => document.getElementById('speed').value") == "0.02"
    said = page.page.inner_text("#speed-rule")
    assert "0.02×" in said and "1 turn/s" in said and "314.2" in said, said
    # The tilted disk at 10 rad/s: 2 pi / 10 = 0.628, nearest on the ladder 0.5.
    page = open_page(disk[1])
    assert page.js("() => window.eulerdyn.clock.speed") == 0.5


#: A compound pendulum with theta's downward crossings of 0 and omega_b_z's minima as events (rows every 0.05 s).
PENDULUM_WITH_EVENTS = ROOT / "tests" / "data" / "pendulum_events.toml"


def read_events(csv_path):
    """The run's events file: (event, t, value, direction) with t and value as floats."""
    with open(f"{csv_path}.events.csv", newline="") as f:
        return [(r["event"], float(r["t"]), float(r["value"]), r["direction"]) for r in csv.DictReader(f)]


def test_the_events_are_listed_and_a_click_shows_each_ones_time(work, disk, open_page):
    csv_path, html_path = work / "pendulum_events.csv", work / "pendulum_events.html"
    assert eulerdyn("run", PENDULUM_WITH_EVENTS, "-o", csv_path).returncode == 0
    assert eulerdyn("view", csv_path, "-o", html_path).returncode == 0
    located = read_events(csv_path)
    assert len(located) == 4 and {e[0] for e in located} == {"down", "fast"}, located
    page = open_page(html_path)
    assert page.js("() => !document.getElementById('events').hidden")
    buttons = page.page.query_selector_all("#events button.event")
    assert len(buttons) == len(located)
    assert page.js("() => window.eulerdyn.events.length") == len(located)
    listed = page.page.inner_text("#events")
    assert f"Events ({len(located)})" in listed and "theta" in listed and "omega_b_z" in listed, listed
    for k, (name, t, value, _) in enumerate(located):
        assert buttons[k].inner_text() == name
        buttons[k].click()
        state = page.js("() => window.eulerdyn.state()")
        # The time shown is the event's (between two rows: the state interpolated there), and the list marks it.
        assert state["t"] == t, (name, state["t"], t)
        assert abs(t / 0.05 - round(t / 0.05)) > 1e-6, "located between the rows"
        assert page.js("(k) => document.querySelectorAll('#events tr')[k].classList.contains('current')", k)
        assert f"t = {t:.4g}" in page.page.inner_text("#clock")
        # The watched quantity at that time, to the interpolation between rows 0.05 s apart.
        if name == "fast":
            omega_b = state["omega_b"]
            assert abs(omega_b[2] - value) < 1e-2 * abs(value), (omega_b, value)
    # A run without events lists none.
    page = open_page(disk[1])
    assert page.js("() => document.getElementById('events').hidden")
    assert page.js("() => window.eulerdyn.events.length") == 0


def scene_objects(page, names):
    """For each three.js object name (a wheel's, a moving mass's), whether an object of that name is in the page's
    scene graph (its parents reach a Scene) and visible."""
    return page.js("""(names) => names.map((n) => {
        const r = window.eulerdyn.rotors.find((w) => 'rotor ' + w.name === n || 'rotor momentum ' + w.name === n);
        let o = r ? (r.wheel.name === n ? r.wheel : r.arrow) : window.eulerdyn.moving_balls.find((b) => b.name === n);
        if (!o) return false;
        const visible = o.visible;
        while (o.parent) o = o.parent;
        return o.type === 'Scene' && visible;
    })""", names)


def test_the_wheels_are_drawn_with_their_axes_and_momenta(work, rod, open_page):
    csv_path, html_path, _ = make_page(work, "satellite_wheels.toml", "wheels")
    rows = read_csv(csv_path)
    page = open_page(html_path)
    names = ["wheel_x", "wheel_y", "wheel_z"]
    assert page.js("() => window.eulerdyn.rotor_names") == names
    # At t = 0 the wheels are at rest: their discs and axes are drawn, their momentum arrows (h = 0) hidden.
    page.js("() => window.eulerdyn.setTime(0)")
    assert scene_objects(page, [f"rotor {n}" for n in names] + [f"rotor momentum {n}" for n in names]) == [True] * 3 + [
        False
    ] * 3
    assert "wheels wheel_x, wheel_y, wheel_z" in page.page.inner_text("#legend")
    # At a row's time: each wheel's h is the CSV's, and its arrow points along R(q) a sign(h) in space, its length
    # |h| at H's scale (the largest |h| over the run drawn as long as the largest |H| would be).
    row = rows[len(rows) // 2]
    page.js("(t) => window.eulerdyn.setTime(t)", row["t"])
    assert all(scene_objects(page, [f"rotor momentum {n}" for n in names]))
    drawn = page.js("""() => window.eulerdyn.rotors.map((w) => {
        w.arrow.updateWorldMatrix(true, false);
        const e = w.arrow.matrixWorld.elements;  // the arrow's local y is its direction
        const n = Math.hypot(e[4], e[5], e[6]);
        return { dir: [e[4] / n, e[5] / n, e[6] / n], length: w.arrow.line.scale.y + w.arrow.cone.scale.y };
    })""")
    state = page.js("() => window.eulerdyn.state()")
    q = [row[f"q_{c}"] for c in "wxyz"]
    for k, name in enumerate(names):
        h = row[f"{name}_h"]
        assert state["rotor_h"][k] == h
        axis_b = [1.0 if i == k else 0.0 for i in range(3)]
        want = [math.copysign(1.0, h) * c for c in rotate(q, axis_b)]
        assert max(abs(a - b) for a, b in zip(drawn[k]["dir"], want)) < 1e-6, (name, drawn[k], want)
    longest = max(abs(r[f"{n}_h"]) for r in rows for n in names)
    lengths = [d["length"] for d in drawn]
    for k, name in enumerate(names):
        assert abs(lengths[k] / lengths[0] - abs(row[f"{name}_h"] / row["wheel_x_h"])) < 1e-6
    assert longest > 0
    # The wheels show: hiding them changes the drawing.
    assert visible_pixels(page, "rotors") > 50
    # A run without rotors has none.
    page = open_page(rod[1])
    assert page.js("() => window.eulerdyn.rotor_names") == []
    assert page.js("() => window.eulerdyn.rotors.length") == 0
    assert "wheels" not in page.page.inner_text("#legend")


def rotate(q, v):
    """v turned by the unit quaternion q = (w, x, y, z): q v q*, body to space."""
    w, x, y, z = q
    return [
        (1 - 2 * (y * y + z * z)) * v[0] + 2 * (x * y - w * z) * v[1] + 2 * (x * z + w * y) * v[2],
        2 * (x * y + w * z) * v[0] + (1 - 2 * (x * x + z * z)) * v[1] + 2 * (y * z - w * x) * v[2],
        2 * (x * z - w * y) * v[0] + 2 * (y * z + w * x) * v[1] + (1 - 2 * (x * x + y * y)) * v[2],
    ]


def test_a_carriers_axis_and_bearings_turn_with_it(work, open_page):
    # scenarios/turbine_yawing_aircraft.toml: the axis (body z) is fixed in a yawing carrier, so the dashed axis line,
    # the bearings and their force arrows are drawn along R(q(t)) a_b, not where they were at t = 0.
    csv_path, html_path, _ = make_page(work, "turbine_yawing_aircraft.toml", "turbine")
    rows = read_csv(csv_path)
    page = open_page(html_path)
    row = rows[200]  # t = 1 s: the aircraft has yawed by 0.22 rad
    page.js("(t) => window.eulerdyn.setTime(t)", row["t"])
    drawn = page.js("""() => {
        const g = window.eulerdyn.axis_group;
        g.updateWorldMatrix(true, true);
        const line = g.children[0].geometry.attributes.position;
        const a = [line.getX(1), line.getY(1), line.getZ(1)];
        const n = Math.hypot(...a);
        const q = g.quaternion;
        const turn = (v) => {  // v turned by the group's quaternion
            const [x, y, z] = v, [qx, qy, qz, qw] = [q.x, q.y, q.z, q.w];
            const ix = qw * x + qy * z - qz * y, iy = qw * y + qz * x - qx * z, iz = qw * z + qx * y - qy * x,
                iw = -qx * x - qy * y - qz * z;
            return [ix * qw + iw * -qx + iy * -qz - iz * -qy, iy * qw + iw * -qy + iz * -qx - ix * -qz,
                iz * qw + iw * -qz + ix * -qy - iy * -qx];
        };
        return turn(a.map((c) => c / n));
    }""")
    q = [row[f"q_{c}"] for c in "wxyz"]
    want = rotate(q, [0.0, 0.0, 1.0])
    assert max(abs(a - b) for a, b in zip(drawn, want)) < 1e-6, (drawn, want)
    assert abs(want[1]) > 0.2, "the axis has turned away from space x"


def test_moving_masses_are_drawn_where_their_columns_put_them(work, rod, open_page):
    csv_path, html_path, _ = make_page(work, "deploying_booms.toml", "booms")
    rows = read_csv(csv_path)
    page = open_page(html_path)
    names = ["tip_a", "tip_b"]
    assert page.js("() => window.eulerdyn.moving_names") == names
    reference_o = page.js("() => window.eulerdyn.geometry.reference_o")
    # At a row's time each ball sits at its columns' position (from the reference origin) shifted to O, in the body
    # group: before the deployment, half-way and deployed.
    for row in (rows[0], rows[100], rows[-1]):
        page.js("(t) => window.eulerdyn.setTime(t)", row["t"])
        drawn = page.js("() => window.eulerdyn.moving_balls.map((b) => [b.position.x, b.position.y, b.position.z])")
        for k, name in enumerate(names):
            want = [row[f"{name}_{c}"] + reference_o[i] for i, c in enumerate("xyz")]
            assert max(abs(a - b) for a, b in zip(drawn[k], want)) < 1e-12, (row["t"], name, drawn[k], want)
    assert abs(rows[-1]["tip_a_x"] - 2.0) < 1e-15 and abs(rows[0]["tip_a_x"] - 0.3) < 1e-15
    assert scene_objects(page, [f"moving mass {n}" for n in names]) == [True, True]
    # A run without moving masses has none.
    page = open_page(rod[1])
    assert page.js("() => window.eulerdyn.moving_names") == []
