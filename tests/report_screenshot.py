#!/usr/bin/env python3
"""The report's 3D view, seen by a browser: writes the report of a colliding
scene, screenshots index.html?shot=1 (the first 3D view moved to the top) in
headless chromium (WebGL by SwiftShader, no GPU) and checks, with the
standard library only, that the view is drawn and shows each object's colour.

usage: report_screenshot.py CLASH4D SCENE WORKDIR [--keep PNG]
Exit 77 (ctest SKIP_RETURN_CODE) when chromium is not installed."""

import colorsys
import json
import os
import shutil
import struct
import subprocess
import sys
import zlib

SKIP = 77


def read_png(path):
    """(width, height, rows of (r, g, b)) of an 8-bit RGB or RGBA PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(path + ": not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError("unsupported PNG: depth %d, colour type %d, interlace %d" % (depth, colour, interlace))
    channels = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        unfilter(kind, line, previous, channels)
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def unfilter(kind, line, previous, bpp):
    for i in range(len(line)):
        a = line[i - bpp] if i >= bpp else 0
        b = previous[i]
        c = previous[i - bpp] if i >= bpp else 0
        if kind == 1:
            line[i] = (line[i] + a) & 255
        elif kind == 2:
            line[i] = (line[i] + b) & 255
        elif kind == 3:
            line[i] = (line[i] + (a + b) // 2) & 255
        elif kind == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255


def hue(rgb):
    h, _, s = colorsys.rgb_to_hls(*(v / 255 for v in rgb))
    return h * 360, s


def browse(browser, url, *args):
    # SwiftShader gives headless chromium WebGL without a GPU.
    return subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
                           "--enable-unsafe-swiftshader", "--hide-scrollbars", *args, url],
                          check=True, timeout=60, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL).stdout.decode()


def check_gap(clash4d, browser, work, fixtures):
    """Where exact says no collision, the view's gap line: blocks a [0, 1]^3
    and b [-3, -2] x [2, 3] x [0, 1] at t = 0 (the exact t* is none, so the
    view starts at tL = 0) are sqrt(2^2 + 1^2) = 2.236 apart."""
    out = os.path.join(work, "gap")
    subprocess.run([clash4d, "report", os.path.join(fixtures, "clear_miss_parallel.json"), "--out", out],
                   check=True, timeout=60, stdout=subprocess.DEVNULL)
    dom = browse(browser, "file://" + os.path.abspath(os.path.join(out, "index.html")), "--dump-dom")
    want = "the closest objects, a and b, are \u2248 2.24 apart"
    print("gap line:", "found" if want in dom else "missing")
    return want in dom


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    clash4d, scene, work = sys.argv[1:4]
    keep = sys.argv[5] if len(sys.argv) > 5 and sys.argv[4] == "--keep" else None
    browser = shutil.which("chromium") or shutil.which("chromium-browser")
    if not browser:
        print("SKIP: chromium is not installed")
        return SKIP
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    out = os.path.join(work, "report")
    subprocess.run([clash4d, "report", scene, "--out", out], check=True, timeout=60)
    if not os.path.exists(os.path.join(out, "three.min.js")):
        print("FAIL: three.min.js was not copied into the report")
        return 1
    png = os.path.join(work, "shot.png")
    browse(browser, "file://" + os.path.abspath(os.path.join(out, "index.html")) + "?shot=1",
           "--screenshot=" + png, "--window-size=1200,900")
    if keep:
        shutil.copyfile(png, keep)
    width, height, rows = read_png(png)
    # The view is first on the page: its 560 x 420 canvas in the top-left
    # 600 x 460 (the page's margins), looked at inside that.
    region = [rows[y][x] for y in range(40, min(height, 420)) for x in range(30, min(width, 560))]
    drawn = sum(1 for p in region if max(abs(v - 255) for v in p) > 24)
    print("non-white pixels in the 3D view: %d of %d" % (drawn, len(region)))
    if drawn < len(region) // 50:
        print("FAIL: the 3D view is blank")
        return 1
    with open(os.path.join(out, "report.json")) as f:
        json.load(f)
    colours = {"a": "#4e79a7", "b": "#f28e2b"}   # the first two objects' colours (compare/Scene_view.cpp)
    for name, colour in colours.items():
        want, _ = hue(tuple(int(colour[i:i + 2], 16) for i in (1, 3, 5)))
        # Lighting scales the colour and transparency mixes in white: the hue stays.
        seen = sum(1 for p in region if hue(p)[1] > 0.2 and min(abs(hue(p)[0] - want), 360 - abs(hue(p)[0] - want)) < 8)
        print("object %s (%s, hue %.0f): %d pixels" % (name, colour, want, seen))
        if seen < 300:
            print("FAIL: object %s is not drawn in its colour" % name)
            return 1
    if not check_gap(clash4d, browser, work, os.path.dirname(os.path.abspath(scene))):
        print("FAIL: no gap line for two blocks that never meet")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
