#!/usr/bin/env python3
"""Loads an HTML report in headless Chromium and checks it.

Usage: check_report.py CATPLAN CHROMIUM WORKDIR -- REPORT_ARGS...

1. `CATPLAN report REPORT_ARGS... -o WORKDIR/report.html` writes the page (exit 0 or 1: valid or
   invalid transfer; anything else fails the test).
2. Self-tests prove the checks can fail: a page with a deliberate script error must be caught
   by the console check, and a blank page by the screenshot check.
3. The report is loaded in Chromium (headless, no sandbox, no GPU, no background networking, a
   fresh profile): the page must log nothing to the console (it has no scripts, so any console
   line - an uncaught error, a failed load - is a fault), and the screenshot Chromium takes must
   not be blank (at least 2% of its pixels not white, more than 16 distinct colours).

Chromium missing is a failure with a message, not a skip: `make test` installs it
(tools/install-deps.sh).
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib


def fail(message):
    print(f"check_report: FAIL: {message}")
    sys.exit(1)


def run_chromium(chromium, html, png):
    """Loads `html` and screenshots it to `png`; returns Chromium's stderr."""
    profile = tempfile.mkdtemp(prefix="catplan-chromium-")
    try:
        cmd = [chromium, "--headless", "--no-sandbox", "--disable-gpu",
               "--disable-background-networking", f"--user-data-dir={profile}",
               "--enable-logging=stderr", "--v=0", f"--screenshot={png}",
               "--window-size=1280,2000", "file://" + os.path.abspath(html)]
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=180)
        if p.returncode != 0:
            fail(f"chromium exited with {p.returncode}:\n{p.stderr}")
        return p.stderr
    finally:
        shutil.rmtree(profile, ignore_errors=True)


def console_errors(stderr):
    """Chromium logs each console message of the page as `...:CONSOLE(n)] "text", source: ...`
    (console.error and uncaught exceptions alike); the report has no scripts, so every such
    line is a fault."""
    return [line for line in stderr.splitlines() if ":CONSOLE" in line or "Uncaught" in line]


def png_pixels(path):
    """The (width, height, rows of RGB(A) bytes) of an 8-bit RGB or RGBA PNG, decoded with zlib."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail(f"{path} is not a PNG")
    pos, idat, width, height, channels = 8, b"", 0, 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            if depth != 8 or colour not in (2, 6):
                fail(f"unexpected PNG format (depth {depth}, colour type {colour})")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        line = raw[y * (stride + 1):(y + 1) * (stride + 1)]
        ftype, cur = line[0], bytearray(line[1:])
        for i in range(stride):
            a = cur[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if ftype == 1:
                cur[i] = (cur[i] + a) & 255
            elif ftype == 2:
                cur[i] = (cur[i] + b) & 255
            elif ftype == 3:
                cur[i] = (cur[i] + (a + b) // 2) & 255
            elif ftype == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                cur[i] = (cur[i] + pred) & 255
        rows.append(bytes(cur))
        prev = cur
    return width, height, channels, rows


def blankness(path):
    """(fraction of non-white pixels, number of distinct colours) of a screenshot."""
    width, height, channels, rows = png_pixels(path)
    colours, ink = set(), 0
    for row in rows:
        for x in range(0, width * channels, channels):
            px = row[x:x + 3]
            colours.add(px)
            if px != b"\xff\xff\xff":
                ink += 1
    return ink / float(width * height), len(colours)


def not_blank(path):
    ink, colours = blankness(path)
    return ink >= 0.02 and colours > 16, ink, colours


def main():
    if len(sys.argv) < 5 or "--" not in sys.argv:
        fail("usage: check_report.py CATPLAN CHROMIUM WORKDIR -- REPORT_ARGS...")
    sep = sys.argv.index("--")
    catplan, chromium, workdir = sys.argv[1:4]
    report_args = sys.argv[sep + 1:]
    if not chromium or not shutil.which(chromium):
        fail("chromium not found: install Debian's `chromium` (tools/install-deps.sh does)")
    os.makedirs(workdir, exist_ok=True)

    # 1. The report.
    html = os.path.join(workdir, "report.html")
    p = subprocess.run([catplan, "report", *report_args, "-o", html], capture_output=True,
                       text=True, timeout=600)
    # A sanitizer build exits 1 after a report too: its message must not pass for "invalid".
    if p.returncode not in (0, 1) or not os.path.exists(html) or "Sanitizer" in p.stderr:
        fail(f"catplan report exited with {p.returncode}:\n{p.stdout}{p.stderr}")
    print(f"catplan report: exit {p.returncode}: {p.stdout.strip()}")

    # 2. The checks can fail.
    bad = os.path.join(workdir, "selftest_error.html")
    with open(bad, "w") as f:
        f.write("<!DOCTYPE html><html><body><p>x</p>"
                "<script>console.error('deliberate'); notDefined();</script></body></html>")
    if not console_errors(run_chromium(chromium, bad, os.path.join(workdir, "selftest.png"))):
        fail("the console check does not see a deliberate script error")
    blank = os.path.join(workdir, "selftest_blank.html")
    with open(blank, "w") as f:
        f.write("<!DOCTYPE html><html><body></body></html>")
    blank_png = os.path.join(workdir, "selftest_blank.png")
    run_chromium(chromium, blank, blank_png)
    if not_blank(blank_png)[0]:
        fail("the screenshot check does not see a blank page")
    print("self-tests: a script error and a blank page are caught")

    # 3. The report in Chromium.
    png = os.path.join(workdir, "report.png")
    errors = console_errors(run_chromium(chromium, html, png))
    if errors:
        fail("console messages while loading the report:\n" + "\n".join(errors))
    if not os.path.exists(png):
        fail("chromium wrote no screenshot")
    ok, ink, colours = not_blank(png)
    if not ok:
        fail(f"the screenshot looks blank: {ink:.1%} non-white pixels, {colours} colours")
    print(f"report loads with no console messages; screenshot {png}: {ink:.1%} non-white "
          f"pixels, {colours} colours")


if __name__ == "__main__":
    main()
