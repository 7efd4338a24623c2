#!/usr/bin/env python3
"""The most common naive collision engine, as a clash4d external subject.

It samples the time span at N + 1 evenly spaced instants (both ends
included) and, at each, tests every pair of convex pieces for static overlap
with the separating-axis test in floating point, counting a gap of at most
TOLERANCE as contact (closed semantics). The fuzzer finds what such engines
get wrong: objects that pass through each other between two samples
(tunnelling), touching counted as collision, and near misses inside the
tolerance.

    clash4d fuzz --seed 1 --cases 200 --out fz \
        --subject "sampling=python3 examples/subjects/sampling_subject.py"

Standard library only. Protocol: docs/subject-protocol.md.
Options: --samples N (default 20), --tolerance EPS (default 1e-9).
"""
import itertools
import json
import math
import sys
from fractions import Fraction


class Unsupported(Exception):
    pass


def number(x):
    """A scene number (JSON number or string, maybe "p/q") as the nearest double."""
    return float(Fraction(str(x)))


# ---------------------------------------------------------------- solids

def quaternion_matrix(w, x, y, z):
    n = w * w + x * x + y * y + z * z
    return [[(w*w + x*x - y*y - z*z) / n, 2 * (x*y - w*z) / n, 2 * (x*z + w*y) / n],
            [2 * (x*y + w*z) / n, (w*w - x*x + y*y - z*z) / n, 2 * (y*z - w*x) / n],
            [2 * (x*z - w*y) / n, 2 * (y*z + w*x) / n, (w*w - x*x - y*y + z*z) / n]]


def convex_vertices(planes):
    """Vertices of {p : a.p + d <= 0 for each plane}, by intersecting triples."""
    points = []
    for (a, b, c) in itertools.combinations(planes, 3):
        m = [a[:3], b[:3], c[:3]]
        det = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
               - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
               + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
        if abs(det) < 1e-12:
            continue
        rhs = [-a[3], -b[3], -c[3]]
        p = []
        for col in range(3):  # Cramer's rule
            mc = [row[:] for row in m]
            for r in range(3):
                mc[r][col] = rhs[r]
            p.append((mc[0][0] * (mc[1][1] * mc[2][2] - mc[1][2] * mc[2][1])
                      - mc[0][1] * (mc[1][0] * mc[2][2] - mc[1][2] * mc[2][0])
                      + mc[0][2] * (mc[1][0] * mc[2][1] - mc[1][1] * mc[2][0])) / det)
        if all(h[0] * p[0] + h[1] * p[1] + h[2] * p[2] + h[3] <= 1e-9 for h in planes):
            points.append(p)
    if len(points) < 4:
        raise Unsupported("a convex solid without four vertices")
    return points


def pieces(solid):
    """The solid as a list of convex pieces, each a list of vertices."""
    if "block" in solid:
        lo = [number(v) for v in solid["block"]["min"]]
        hi = [number(v) for v in solid["block"]["max"]]
        return [[[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]]
    if "hull" in solid:
        return [[[number(v) for v in p] for p in solid["hull"]]]
    if "prism" in solid:
        z0, z1 = (number(v) for v in solid["prism"]["z"])
        return [[[number(x), number(y), z] for (x, y) in solid["prism"]["base"] for z in (z0, z1)]]
    if "convex" in solid:
        return [convex_vertices([[number(v) for v in h] for h in solid["convex"]])]
    if "union" in solid:
        return [p for child in solid["union"] for p in pieces(child)]
    if "translate" in solid:
        d = [number(v) for v in solid["translate"]]
        return [[[p[i] + d[i] for i in range(3)] for p in piece] for piece in pieces(solid["solid"])]
    if "rotate" in solid:
        m = quaternion_matrix(*(number(v) for v in solid["rotate"]))
        return [[[sum(m[i][k] * p[k] for k in range(3)) for i in range(3)] for p in piece]
                for piece in pieces(solid["solid"])]
    raise Unsupported("not a union of convex pieces: " + next(iter(solid)))


# ---------------------------------------------------------------- motions

def motion(text):
    """(times, velocities) of a ROBMOD motion string."""
    if isinstance(text, dict):  # {"poses": [...]}: this sampler follows translations only
        raise Unsupported("pose motions (rotation) are not sampled by this subject")
    tokens = (text or "rest").split()
    times, velocities, i = [], [], 0
    while True:
        if tokens[i] == "rest":
            velocities.append([0.0, 0.0, 0.0])
            i += 1
        else:  # vel x y z
            velocities.append([number(v) for v in tokens[i + 1:i + 4]])
            i += 4
        if i >= len(tokens):
            return times, velocities
        times.append(number(tokens[i + 1]))  # until T
        i += 2


def displacement(m, t):
    """D(t), continuous and piecewise linear with D(0) = 0."""
    times, velocities = m
    d = [0.0, 0.0, 0.0]
    for k, v in enumerate(velocities):
        lo = times[k - 1] if k > 0 else -math.inf
        hi = times[k] if k < len(times) else math.inf
        span = min(max(t, lo), hi) - min(max(0.0, lo), hi)
        d = [d[i] + v[i] * span for i in range(3)]
    return d


# ---------------------------------------------------------------- overlap

def axes(a, b):
    """Candidate separating axes: normals of all vertex triples' planes and
    cross products of all vertex-pair directions (a superset of the face
    normals and edge-edge axes, so the test stays exact in exact arithmetic)."""
    out = []
    def add(n):
        length = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
        if length > 1e-12:
            out.append([n[0] / length, n[1] / length, n[2] / length])
    def cross(u, v):
        return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    def sub(p, q):
        return [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
    for piece in (a, b):
        for p, q, r in itertools.combinations(piece, 3):
            add(cross(sub(q, p), sub(r, p)))
    edges_a = [sub(q, p) for p, q in itertools.combinations(a, 2)]
    edges_b = [sub(q, p) for p, q in itertools.combinations(b, 2)]
    for u in edges_a:
        for v in edges_b:
            add(cross(u, v))
    return out


def overlap(a, b, tolerance):
    """Static overlap of two convex pieces (closed: a gap up to tolerance is contact)."""
    for n in axes(a, b):
        pa = [n[0] * p[0] + n[1] * p[1] + n[2] * p[2] for p in a]
        pb = [n[0] * p[0] + n[1] * p[1] + n[2] * p[2] for p in b]
        if max(pa) < min(pb) - tolerance or max(pb) < min(pa) - tolerance:
            return False
    return True


def moved(piece, d):
    return [[p[0] + d[0], p[1] + d[1], p[2] + d[2]] for p in piece]


def first_collision(scene, samples, tolerance):
    """The first sampled instant at which two objects overlap, or None."""
    t_lo, t_hi = (number(v) for v in scene["time"])
    objects = [(o["name"], pieces(o["shape"]), motion(o.get("motion"))) for o in scene["objects"]]
    ignored = {frozenset(p) for p in scene.get("ignore", [])}
    for k in range(samples + 1):
        t = t_lo + (t_hi - t_lo) * k / samples
        placed = [(name, [moved(p, displacement(m, t)) for p in ps]) for name, ps, m in objects]
        for (na, pa), (nb, pb) in itertools.combinations(placed, 2):
            if frozenset((na, nb)) in ignored:
                continue
            if any(overlap(x, y, tolerance) for x in pa for y in pb):
                return t
    return None


def answer(request, samples, tolerance):
    out = {"id": request["id"]}
    try:
        t = first_collision(request["scene"], samples, tolerance)
    except Unsupported as why:
        out["unsupported"] = str(why)
        return out
    out["collide"] = t is not None
    if t is not None:
        out["t"] = repr(t)  # the shortest decimal of the double
    return out


def main():
    args = sys.argv[1:]
    samples = int(args[args.index("--samples") + 1]) if "--samples" in args else 20
    tolerance = float(args[args.index("--tolerance") + 1]) if "--tolerance" in args else 1e-9
    print(json.dumps({"subject": "sampling-sat", "semantics": "closed", "tolerance": tolerance}), flush=True)
    for line in sys.stdin:
        print(json.dumps(answer(json.loads(line), samples, tolerance)), flush=True)


if __name__ == "__main__":
    main()
