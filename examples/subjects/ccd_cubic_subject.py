#!/usr/bin/env python3
"""The textbook float CCD test, as a clash4d external subject: the cubic.

Most float CCD code (Provot 1997; Bridson, Fedkiw and Anderson 2002) does
this: the four moving points are coplanar exactly when a cubic in t
vanishes; its roots in [0, 1] are found in doubles (here: [0, 1] cut at the
roots of its derivative into monotone pieces, each piece with a sign change
bisected), and at each root, in time order, an inside test with a tolerance
decides contact (barycentric coordinates for vertex-face, the closest points'
parameters for edge-edge). The first root that passes is the answer.

It is meant to be typical, so it is wrong where such code is wrong: a root
at t = 1 or t = 0 that rounding moves off the interval, a vertex grazing an
edge, primitives sliding in one plane (the cubic is zero throughout: only
t = 0 and t = 1 are tried), parallel edges (no crossing point), degenerate
triangles, and near misses inside the tolerance.

    clash4d fuzz --ccd --seed 1 --cases 400 --out fz \\
        --subject "cubic=python3 examples/subjects/ccd_cubic_subject.py"

Standard library only. Protocol: docs/subject-protocol.md (CCD requests).
"""
import json
import math
import sys
from fractions import Fraction

TOLERANCE = 1e-9


def number(x):
    """A request's number (JSON number or string, maybe "p/q") as the nearest double."""
    return float(Fraction(str(x)))


# ---------------------------------------------------------------- polynomials in t

def poly_add(a, b):
    n = max(len(a), len(b))
    return [(a[i] if i < len(a) else 0.0) + (b[i] if i < len(b) else 0.0) for i in range(n)]


def poly_sub(a, b):
    return poly_add(a, [-x for x in b])


def poly_mul(a, b):
    out = [0.0] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def moving(p0, p1):
    """A vertex's coordinates as polynomials in t: p0 + t (p1 - p0)."""
    return [[p0[k], p1[k] - p0[k]] for k in range(3)]


def vec_sub(u, v):
    return [poly_sub(u[k], v[k]) for k in range(3)]


def vec_cross(u, v):
    return [poly_sub(poly_mul(u[(k + 1) % 3], v[(k + 2) % 3]), poly_mul(u[(k + 2) % 3], v[(k + 1) % 3]))
            for k in range(3)]


def vec_dot(u, v):
    return poly_add(poly_add(poly_mul(u[0], v[0]), poly_mul(u[1], v[1])), poly_mul(u[2], v[2]))


def coplanarity_cubic(kind, x):
    """The coefficients (constant first) of the cubic that is zero when the four points are coplanar."""
    if kind == "vertex-face":  # p = x0, triangle x1 x2 x3: ((b - a) x (c - a)) . (p - a)
        return vec_dot(vec_cross(vec_sub(x[2], x[1]), vec_sub(x[3], x[1])), vec_sub(x[0], x[1]))
    return vec_dot(vec_cross(vec_sub(x[1], x[0]), vec_sub(x[3], x[2])), vec_sub(x[2], x[0]))


def quadratic_roots(a, b, c):
    if a == 0:
        return [] if b == 0 else [-c / b]
    disc = b * b - 4 * a * c
    if disc < 0:
        return []
    s = math.sqrt(disc)
    return sorted([(-b - s) / (2 * a), (-b + s) / (2 * a)])


def bisect(f, lo, hi):
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if f(lo) * f(mid) <= 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def roots_in_unit_interval(c):
    """The cubic's roots in [0, 1], ascending."""
    def f(t):
        return ((c[3] * t + c[2]) * t + c[1]) * t + c[0]
    cuts = [0.0] + [r for r in quadratic_roots(3 * c[3], 2 * c[2], c[1]) if 0 < r < 1] + [1.0]
    roots = []
    for lo, hi in zip(cuts, cuts[1:]):
        if f(lo) == 0:
            roots.append(lo)
        elif f(lo) * f(hi) < 0:
            roots.append(bisect(f, lo, hi))
    if f(1.0) == 0:
        roots.append(1.0)
    return roots


# ---------------------------------------------------------------- inside tests

def sub(p, q):
    return [p[0] - q[0], p[1] - q[1], p[2] - q[2]]


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def in_triangle(p, a, b, c):
    """Barycentric coordinates of p, within the tolerance of the triangle."""
    v0, v1, v2 = sub(b, a), sub(c, a), sub(p, a)
    d00, d01, d11, d20, d21 = dot(v0, v0), dot(v0, v1), dot(v1, v1), dot(v2, v0), dot(v2, v1)
    denom = d00 * d11 - d01 * d01
    if denom == 0:  # a degenerate triangle: no contact
        return False
    v = (d11 * d20 - d01 * d21) / denom
    w = (d00 * d21 - d01 * d20) / denom
    return v >= -TOLERANCE and w >= -TOLERANCE and v + w <= 1 + TOLERANCE


def segments_cross(p1, q1, p2, q2):
    """The parameters of the lines' closest points, within the tolerance of both segments."""
    d1, d2, r = sub(q1, p1), sub(q2, p2), sub(p1, p2)
    a, b, c, e, f = dot(d1, d1), dot(d1, d2), dot(d1, r), dot(d2, d2), dot(d2, r)
    denom = a * e - b * b
    if denom == 0:  # parallel edges: no crossing point
        return False
    s = (b * f - c * e) / denom
    u = (a * f - b * c) / denom
    return -TOLERANCE <= s <= 1 + TOLERANCE and -TOLERANCE <= u <= 1 + TOLERANCE


def first_contact(query):
    """The first root of the cubic at which the primitives touch, or None."""
    kind = query["type"]
    t0 = [[number(v) for v in p] for p in query["t0"]]
    t1 = [[number(v) for v in p] for p in query["t1"]]
    cubic = coplanarity_cubic(kind, [moving(t0[i], t1[i]) for i in range(4)])
    for t in roots_in_unit_interval(cubic):
        x = [[t0[i][k] + t * (t1[i][k] - t0[i][k]) for k in range(3)] for i in range(4)]
        inside = in_triangle(*x) if kind == "vertex-face" else segments_cross(*x)
        if inside:
            return t
    return None


def answer(request):
    out = {"id": request["id"]}
    if "ccd" not in request:
        out["unsupported"] = "the cubic subject answers CCD queries only"
        return out
    t = first_contact(request["ccd"])
    out["collide"] = t is not None
    if t is not None:
        out["t"] = t
    return out


def main():
    print(json.dumps({"subject": "cubic", "semantics": "closed", "tolerance": TOLERANCE}), flush=True)
    for line in sys.stdin:
        print(json.dumps(answer(json.loads(line))), flush=True)


if __name__ == "__main__":
    main()
