#!/usr/bin/env python3
"""A second, independent checker of clash4d certificates, standard library only.

    python3 clash4d_verify.py SCENE.json CERT.json

Written from docs/certificate-format.md ("the doc", section numbers below as
"s2.1" and so on) and ../shared/spec/scene-format.md alone; it shares no code
with clash4d (not even the scene reader). Exits as `clash4d verify`: 0 and the
proved claim (s5), 1 and the first reason the certificate fails with its JSON
path, 2 when the scene or the certificate cannot be read, 3 beyond a limit
(nesting, memory), 4 on a flaw of this checker (never a traceback).
"""
import bisect
import itertools
import json
import math
import re
import sys
import threading
from fractions import Fraction

PROG = "clash4d_verify.py"
STEP_LIMIT = 10_000_000      # s4: steps of term enumeration in one certificate
MAX_SPLIT_DEPTH = 2000       # s4: splits nested deeper are refused
SEMANTICS = ("regularised", "closed")
MAX_EXPONENT = 1000          # the scene reader's limit on a decimal exponent
MAX_NUMBER_CHARS = 1000      # and on the characters of one number
MAX_NESTING = 5000           # s6: JSON nested deeper is refused (exit 3)

# s1: integers of any length, as the C++ checker (GMP) reads them; Python
# 3.11 refuses to convert more than 4,300 digits by default.
if hasattr(sys, "set_int_max_str_digits"):
    sys.set_int_max_str_digits(0)


class Unreadable(Exception):
    """Exit 2: the scene or the certificate cannot be read (or interpreted)."""

    def __init__(self, where, reason):
        super().__init__(f"{where}: {reason}")


class Limit(Exception):
    """Exit 3: beyond a limit of s6."""

    def __init__(self, where, reason):
        super().__init__(f"{where}: {reason}")


class Failed(Exception):
    """Exit 1: the certificate does not prove its claim."""

    def __init__(self, path, reason):
        super().__init__(f"{path}: {reason}")


def line_column(data, i):
    line, start = data.count(b"\n", 0, i) + 1, data.rfind(b"\n", 0, i) + 1
    return f"line {line}, column {i - start + 1}"


MAX_SCENE_BYTES = 64 << 20          # the scene reader's limit (docs/scene-format.md): unreadable beyond
MAX_CERTIFICATE_BYTES = 256 << 20   # clash4d verify's default --certificate-max-mb: exit 3 beyond


def read_text(filename, max_bytes, over):
    """s1's text rules: UTF-8, one leading byte-order mark skipped, no NUL byte; at most
    max_bytes, read no further (`over` is raised beyond)."""
    try:
        with open(filename, "rb") as f:
            data = f.read(max_bytes + 1)
    except OSError as e:
        raise Unreadable(filename, f"cannot read: {e}")
    if len(data) > max_bytes:
        raise over(filename, f"file larger than the limit of {max_bytes >> 20} MiB")
    nul = data.find(b"\0")
    if nul >= 0:
        raise Unreadable(f"{filename}: {line_column(data, nul)}", "a NUL byte (section 1)")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise Unreadable(f"{filename}: {line_column(data, e.start)}", "not UTF-8 text")
    return text[1:] if text.startswith("\ufeff") else text


def load_json(filename, max_bytes, over, **options):
    text = read_text(filename, max_bytes, over)
    try:
        return json.loads(text, **options)
    except RecursionError:
        raise Limit(filename, f"nesting deeper than the limit of {MAX_NESTING} levels")
    except ValueError as e:   # json's own errors (after the value: JSON whitespace only) and the hooks'
        where = f"{filename}: line {e.lineno}, column {e.colno}" if hasattr(e, "lineno") else filename
        raise Unreadable(where, f"not JSON: {getattr(e, 'msg', e)}")


class JsonNumber:
    """A JSON number token, kept as text: a certificate has none (s1)."""

    def __init__(self, text):
        self.text = text


class Duplicate(dict):
    """An object in which a key appears twice (s1: unreadable)."""

    key = None


def certificate_object(pairs):
    d = dict(pairs)
    if len(d) != len(pairs):
        seen = set()
        d = Duplicate(pairs)
        d.key = next(k for k, _ in pairs if k in seen or seen.add(k))
    return d


SURROGATE = re.compile("[\ud800-\udfff]")    # an escaped lone surrogate: not Unicode text


def load_certificate(filename):
    """The certificate's JSON by s1's rules, each failure at its JSON path."""
    doc = load_json(filename, MAX_CERTIFICATE_BYTES, Limit, parse_int=JsonNumber, parse_float=JsonNumber,
                    parse_constant=JsonNumber, object_pairs_hook=certificate_object)
    keys = [None]                  # per open level: the key or index being read
    stack = [iter(((None, doc),))]

    def fail(kind, reason, key=None):
        parts = [k for k in keys[1:]] + ([key] if key is not None else [])
        path = "".join(f"[{k}]" if isinstance(k, int) else f".{k}" for k in parts).lstrip(".")
        if len(path) > 200:                        # deep nesting: its ends say where
            path = path[:100] + " ... " + path[-80:]
        raise kind(f"{filename}: {path or '(top level)'}", reason)
    while stack:                   # in document order, iteratively; paths built only to report
        for key, v in stack[-1]:
            keys[-1] = key
            t = type(v)
            if t is str:
                if SURROGATE.search(v):
                    fail(Unreadable, "a lone surrogate escape is not Unicode text")
            elif t is JsonNumber:
                fail(Unreadable, "expected a number as a string, not a JSON number (section 1)")
            elif t is dict or t is Duplicate or t is list:
                if len(stack) > MAX_NESTING:
                    fail(Limit, f"nesting deeper than the limit of {MAX_NESTING} levels")
                if t is Duplicate:
                    fail(Unreadable, f"the key '{v.key}' appears twice in one object", v.key)
                if t is not list and any(SURROGATE.search(k) for k in v):
                    fail(Unreadable, "a lone surrogate escape is not Unicode text")
                stack.append(iter(v.items() if t is not list else enumerate(v)))
                keys.append(None)
                break
        else:
            stack.pop()
            keys.pop()
    return doc


# ---------------------------------------------------------------- numbers

# Digits are ASCII 0-9 only (s1): \d would take any Unicode digit.
SCENE_NUMBER = re.compile(r"[-+]?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][-+]?[0-9]+)?|[-+]?[0-9]+/[0-9]+")
CERT_NUMBER = re.compile(r"-?[0-9]+(/[0-9]+)?")         # s1: "-12" or "p/q"


def scene_number_from_text(text):
    """A number of the scene format, exactly, from its text (decimal, exponent, p/q)."""
    if len(text) > MAX_NUMBER_CHARS:
        raise ValueError(f"number longer than the limit of {MAX_NUMBER_CHARS} characters: {text[:40]!r}...")
    m = SCENE_NUMBER.fullmatch(text)
    if not m:
        raise ValueError(f"not a number: {text!r}")
    if m.group(3) and abs(int(m.group(3)[1:])) > MAX_EXPONENT:
        raise ValueError(f"exponent beyond the limit of +-{MAX_EXPONENT}: {text!r}")
    if "/" in text and int(text.split("/")[1]) == 0:
        raise ValueError(f"zero denominator: {text!r}")
    return Fraction(text)


def primitive(v):
    """The coprime integer form k v (k > 0) of a rational vector (s2.2)."""
    if all(type(x) is int for x in v):            # the common case: no Fraction at all
        g = math.gcd(*v)
        return tuple(x // g for x in v) if g else None
    den = 1
    for x in v:
        den = den * Fraction(x).denominator // math.gcd(den, Fraction(x).denominator)
    ints = [int(Fraction(x) * den) for x in v]
    g = 0
    for x in ints:
        g = math.gcd(g, x)
    if g == 0:
        return None
    return tuple(x // g for x in ints)


def negate(k):
    return tuple(-x for x in k)


def value(k, p):
    """A literal [a, b, c, e_t, e] at a space-time point (x, y, z, t)."""
    return k[0] * p[0] + k[1] * p[1] + k[2] * p[2] + k[3] * p[3] + k[4]


def sign(x):
    return (x > 0) - (x < 0)


def fmt_point(p):
    return "(" + ", ".join(str(x) for x in p) + ")"


# ------------------------------------------------------------------ scene
# Formulas are tuples: ("atom", (a, b, c, d)) in a solid's coordinates,
# ("lit", key) once extruded (key the coprime 5-tuple), ("and", [..]), ("or", [..]).

def f_not(node):
    """Negation pushed to the atoms (s2.1)."""
    tag, arg = node
    if tag == "atom":
        return ("atom", tuple(-x for x in arg))
    return ("or" if tag == "and" else "and", [f_not(c) for c in arg])


def f_map(node, fn):
    tag, arg = node
    if tag == "atom":
        return ("atom", fn(arg))
    return (tag, [f_map(c, fn) for c in arg])


def conj(atoms):
    return ("and", [("atom", a) for a in atoms])


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


class Flat(ValueError):
    """The hull's points lie in one plane."""


def supporting(P, n, p):
    """The plane through p with normal n, coprime, with every point on its <= 0 side; and its points."""
    e = -dot(n, p)
    side, on = 0, []
    for i, s in enumerate(P):
        v = dot(n, s) + e
        if v == 0:
            on.append(i)
        elif side == 0:
            side = 1 if v > 0 else -1
        elif (v > 0) != (side > 0):
            raise AssertionError("hull wrapping: a plane that does not support the points")
    g = math.gcd(math.gcd(n[0], n[1]), math.gcd(n[2], e)) * (-1 if side > 0 else 1)
    return (n[0] // g, n[1] // g, n[2] // g, e // g), on


def pivot(P, h, p, e, w):
    """Gift wrapping about the line through P[p] along e, in the supporting plane h (the
    plane's other points on the side of w): the plane through the line and the point of
    largest angle from w towards the inside supports every point."""
    n = h[:3]
    best, ba, bb = None, 0, 0
    for i, s in enumerate(P):
        d = sub(s, P[p])
        a, b = dot(w, d), -dot(n, d)
        if b != 0 and (best is None or ba * b - bb * a > 0):
            best, ba, bb = i, a, b
    if best is None:
        raise Flat("the points lie in one plane")
    return supporting(P, cross(e, sub(P[best], P[p])), P[p])


def facet_polygon(P, h, on):
    """The corners of a facet in order (monotone chain, dropping the normal's first non-zero axis)."""
    drop = 0 if h[0] else 1 if h[1] else 2
    u, v = (1, 2) if drop == 0 else (0, 2) if drop == 1 else (0, 1)
    pts = sorted(on, key=lambda i: (P[i][u], P[i][v]))

    def turn(o, a, b):
        return ((P[a][u] - P[o][u]) * (P[b][v] - P[o][v]) - (P[a][v] - P[o][v]) * (P[b][u] - P[o][u]))
    chain = []
    for i in pts:                                              # lower chain
        while len(chain) >= 2 and turn(chain[-2], chain[-1], i) <= 0:
            chain.pop()
        chain.append(i)
    lower = len(chain) + 1
    for i in reversed(pts[:-1]):                               # upper chain
        while len(chain) >= lower and turn(chain[-2], chain[-1], i) <= 0:
            chain.pop()
        chain.append(i)
    return chain[:-1]


def first_facet(P):
    """The plane x = min x supports the lowest point p; wrap about the z line through p, and,
    if the plane found holds only points on one line, about that line (as the C++ checker)."""
    p = min(range(len(P)), key=lambda i: P[i])
    h, on = pivot(P, supporting(P, (-1, 0, 0), P[p])[0], p, (0, 0, 1), (0, 1, 0))
    q = next((i for i in on if P[i] != P[p]), None)
    e = sub(P[q], P[p])
    if any(cross(e, sub(P[i], P[p])) != (0, 0, 0) for i in on):
        return h, on
    return pivot(P, h, p, e, cross(h[:3], e))


def hull_atoms(points):
    """Every plane through three points with all points on its <= 0 side (s2.1), each once, in
    increasing coprime form: the hull's facets, by gift wrapping from facet to facet across each
    facet polygon's edges, O(n) per edge (at most O(n^2) in all), on the points scaled to integers."""
    L = math.lcm(*(x.denominator for p in points for x in p))
    P = [tuple(int(x * L) for x in p) for p in points]
    h, on = first_facet(P)
    seen, todo = {h}, [(h, on)]
    while todo:
        h, on = todo.pop()
        poly = facet_polygon(P, h, on)
        if len(poly) < 3:
            raise AssertionError("hull wrapping: a facet with fewer than three corners")
        for i, p in enumerate(poly):
            q, r = poly[(i + 1) % len(poly)], poly[(i + 2) % len(poly)]
            e = sub(P[q], P[p])
            w = cross(h[:3], e)
            if dot(w, sub(P[r], P[p])) < 0:                     # towards the facet
                w = (-w[0], -w[1], -w[2])
            g, g_on = pivot(P, h, p, e, w)
            if g not in seen:
                seen.add(g)
                todo.append((g, g_on))
    return [(a, b, c, Fraction(e, L)) for a, b, c, e in sorted(seen)]


def rotation(q):
    """The rational rotation matrix of a quaternion (scene-format.md, Solids)."""
    w, x, y, z = q
    n = w * w + x * x + y * y + z * z
    return [[(w*w + x*x - y*y - z*z) / n, 2 * (x*y - w*z) / n, 2 * (x*z + w*y) / n],
            [2 * (x*y + w*z) / n, (w*w - x*x + y*y - z*z) / n, 2 * (y*z - w*x) / n],
            [2 * (x*z - w*y) / n, 2 * (y*z + w*x) / n, (w*w - x*x - y*y + z*z) / n]]


class Motion:
    """D(t) = v_k t + o_k on segment k, between the listed times (scene-format.md, Motion)."""

    def __init__(self, times, vels):
        self.times, self.vels = times, vels
        k0 = sum(1 for T in times if T < 0)        # the segment whose closure holds t = 0
        offs = [None] * len(vels)
        offs[k0] = (Fraction(0),) * 3               # D(0) = 0
        for k in range(k0 + 1, len(vels)):          # continuity at times[k - 1]
            T = times[k - 1]
            offs[k] = tuple(offs[k - 1][i] + (vels[k - 1][i] - vels[k][i]) * T for i in range(3))
        for k in range(k0 - 1, -1, -1):             # continuity at times[k]
            T = times[k]
            offs[k] = tuple(offs[k + 1][i] + (vels[k + 1][i] - vels[k][i]) * T for i in range(3))
        self.offs = offs
        # A velocity change is every time the motion lists (s3), even between equal velocities.
        self.changes = list(times)

    # The times increase strictly: binary searches, so a motion of many
    # segments costs a logarithm per piece, not a scan.
    def segment(self, t):
        return bisect.bisect_left(self.times, t)

    def is_change(self, t):
        i = bisect.bisect_left(self.times, t)
        return i < len(self.times) and self.times[i] == t

    def change_between(self, lo, hi):
        """The first velocity change strictly between lo < hi, or None."""
        i = bisect.bisect_right(self.times, lo)
        return self.times[i] if i < len(self.times) and self.times[i] < hi else None


class Object:
    def __init__(self, name, formula, motion):
        self.name, self.formula, self.motion = name, formula, motion
        self.cache = {}

    def formula_at(self, t):
        """The object's formula over literals on the motion segment holding t (s2.2)."""
        k = self.motion.segment(t)
        if k not in self.cache:
            v, o = self.motion.vels[k], self.motion.offs[k]

            def extrude(node):
                tag, arg = node
                if tag == "atom":
                    n, d = arg[:3], arg[3]
                    nv = sum(n[i] * v[i] for i in range(3))
                    no = sum(n[i] * o[i] for i in range(3))
                    return ("lit", primitive((*n, -nv, d - no)))
                kids = []
                for c in map(extrude, arg):          # flatten AND of AND, OR of OR
                    kids.extend(c[1] if c[0] == tag else [c])
                return kids[0] if len(kids) == 1 else (tag, kids)
            self.cache[k] = extrude(self.formula)
        return self.cache[k]


def literals_of(node, out):
    if node[0] == "lit":
        out.add(node[1])
    else:
        for c in node[1]:
            literals_of(c, out)
    return out


def strictly_true(node, p):
    tag, arg = node
    if tag == "lit":
        return value(arg, p) < 0
    if tag == "and":
        return all(strictly_true(c, p) for c in arg)
    return any(strictly_true(c, p) for c in arg)


def check_keys(obj, path, required, optional, bad, unknown):
    """The keys of a JSON object: not an object or a missing key goes to
    bad (exit 2), a key outside required and optional to unknown (the
    scene's reader: exit 2; the certificate's: exit 1, section 3)."""
    if not isinstance(obj, dict):
        bad(path, "expected an object")
    for k in sorted(required - obj.keys()):
        bad(path, f"missing key \"{k}\"")
    for k in sorted(obj.keys() - required - optional):
        unknown(k)
    return obj


class SceneReader:
    """Reads what it needs of a scene; what it cannot interpret is exit 2."""

    def __init__(self, filename):
        self.file = filename
        doc = load_json(filename, MAX_SCENE_BYTES, Unreadable, parse_float=scene_number_from_text, parse_int=scene_number_from_text,
                        parse_constant=self.constant, object_pairs_hook=self.unique_keys)
        self.keys(doc, "", {"format", "time", "objects"}, {"name", "ignore", "meta"})
        if not isinstance(doc.get("name", ""), str):
            self.bad("name", "expected a string")
        if doc["format"] != "clash4d-scene/1":
            self.bad("format", "expected \"clash4d-scene/1\"")
        self.time = self.numbers(doc["time"], "time", 2)
        if not self.time[0] < self.time[1]:
            self.bad("time", "expected tL < tH")
        objs = doc["objects"]
        if not isinstance(objs, list) or len(objs) < 2:
            self.bad("objects", "expected at least two objects")
        self.objects = {}
        self.order = []
        for i, o in enumerate(objs):
            p = f"objects[{i}]"
            self.keys(o, p, {"name", "shape"}, {"motion"})
            name = o["name"]
            if not isinstance(name, str) or not name or name in self.objects:
                self.bad(p + ".name", "expected a unique non-empty string")
            motion = self.motion(o.get("motion", "rest"), p + ".motion")
            self.objects[name] = Object(name, self.solid(o["shape"], p + ".shape"), motion)
            self.order.append(name)
        self.ignored = set()
        ign = doc.get("ignore", [])
        if not isinstance(ign, list):
            self.bad("ignore", "expected a list of name pairs")
        for i, pr in enumerate(ign):
            if (not isinstance(pr, list) or len(pr) != 2 or pr[0] == pr[1]
                    or not all(isinstance(n, str) and n in self.objects for n in pr)):
                self.bad(f"ignore[{i}]", "expected two distinct object names")
            self.ignored.add(frozenset(pr))

    @staticmethod
    def unique_keys(pairs):
        keys = [k for k, _ in pairs]
        if len(set(keys)) != len(keys):
            raise ValueError("a key appears twice in one object")
        return dict(pairs)

    def constant(self, name):
        raise ValueError(f"{name} is not a number")

    def bad(self, path, reason):
        raise Unreadable(f"{self.file}: {path}" if path else self.file, reason)

    def keys(self, obj, path, required, optional=frozenset()):
        check_keys(obj, path, required, optional, self.bad, lambda k: self.bad(path, f"unknown key \"{k}\""))

    def number(self, v, path):
        if isinstance(v, Fraction):
            return v
        if isinstance(v, str):
            try:
                return scene_number_from_text(v)
            except ValueError as e:
                self.bad(path, str(e))
        self.bad(path, "expected a number")

    def numbers(self, v, path, count):
        if not isinstance(v, list) or len(v) != count:
            self.bad(path, f"expected {count} numbers")
        return tuple(self.number(x, f"{path}[{i}]") for i, x in enumerate(v))

    def rows(self, v, path, count, minimum=1):
        if not isinstance(v, list) or len(v) < minimum:
            self.bad(path, f"expected at least {minimum} lists of {count} numbers")
        return [self.numbers(r, f"{path}[{i}]", count) for i, r in enumerate(v)]

    def halfspace(self, h, path):
        if h[:3] == (0, 0, 0):
            self.bad(path, "(a, b, c) is zero")
        return h

    def solid(self, s, path):
        """A solid's formula over atoms in the scene's coordinates (s2.1)."""
        if not isinstance(s, dict) or not s:
            self.bad(path, "expected a solid")
        kinds = [k for k in s if k != "solid"]
        if len(kinds) != 1:
            self.bad(path, "expected exactly one solid kind")
        kind = kinds[0]
        p = f"{path}.{kind}"
        if kind in ("translate", "rotate"):
            self.keys(s, path, {kind, "solid"})
        else:
            self.keys(s, path, {kind})
        arg = s[kind]
        if kind == "halfspace":
            return conj([self.halfspace(self.numbers(arg, p, 4), p)])
        if kind == "convex":
            return conj([self.halfspace(h, f"{p}[{i}]") for i, h in enumerate(self.rows(arg, p, 4))])
        if kind == "block":
            self.keys(arg, p, {"min", "max"})
            m, M = self.numbers(arg["min"], p + ".min", 3), self.numbers(arg["max"], p + ".max", 3)
            if not all(m[i] < M[i] for i in range(3)):
                self.bad(p, "expected min < max on every axis")
            atoms = []
            for i in range(3):
                e = [0, 0, 0]
                e[i] = 1
                atoms.append((*e, -M[i]))                       # x - M.x
                atoms.append((*[-x for x in e], m[i]))          # m.x - x
            return conj(atoms)
        if kind == "prism":
            self.keys(arg, p, {"base", "z"})
            base = self.rows(arg["base"], p + ".base", 2, 3)
            z0, z1 = self.numbers(arg["z"], p + ".z", 2)
            if not z0 < z1:
                self.bad(p + ".z", "expected z0 < z1")
            atoms, n = [], len(base)
            for i, (xi, yi) in enumerate(base):
                xj, yj = base[(i + 1) % n]
                dx, dy = xj - xi, yj - yi                      # dy (x - x_i) - dx (y - y_i)
                # strictly convex, counter-clockwise: every other vertex strictly left of the edge
                if any(dy * (x - xi) - dx * (y - yi) >= 0 for x, y in base[:i] + base[i + 2:] if (x, y) != (xj, yj)):
                    self.bad(p + ".base", "expected a strictly convex counter-clockwise polygon")
                atoms.append(self.halfspace((dy, -dx, 0, -dy * xi + dx * yi), f"{p}.base[{i}]"))
            return conj(atoms + [(0, 0, 1, -z1), (0, 0, -1, z0)])
        if kind == "hull":
            try:
                atoms = hull_atoms(self.rows(arg, p, 3, 4))
            except Flat:
                atoms = []
            if len(atoms) < 4:
                self.bad(p, "the points have no hull with an interior")
            return conj(atoms)
        if kind in ("union", "intersection", "difference"):
            if not isinstance(arg, list) or len(arg) < (2 if kind == "difference" else 1):
                self.bad(p, "expected a list of solids")
            kids = [self.solid(c, f"{p}[{i}]") for i, c in enumerate(arg)]
            if kind == "union":
                return ("or", kids)
            if kind == "intersection":
                return ("and", kids)
            return ("and", [kids[0]] + [f_not(c) for c in kids[1:]])
        if kind == "translate":
            dx, dy, dz = self.numbers(arg, p, 3)
            return f_map(self.solid(s["solid"], path + ".solid"),
                         lambda h: (h[0], h[1], h[2], h[3] - h[0] * dx - h[1] * dy - h[2] * dz))
        if kind == "rotate":
            q = self.numbers(arg, p, 4)
            if q == (0, 0, 0, 0):
                self.bad(p, "the quaternion is zero")
            R = rotation(q)
            return f_map(self.solid(s["solid"], path + ".solid"),
                         lambda h: (*(sum(R[i][j] * h[j] for j in range(3)) for i in range(3)), h[3]))
        if kind == "mesh":
            self.bad(p, "a mesh solid: this Python checker does not read meshes (their convex "
                        "decomposition is the C++ scene reader's, certificate-format.md section 7)")
        self.bad(path, f"unknown solid \"{kind}\"")

    def motion(self, text, path):
        """ROBMOD notation: segment ("until" T segment)*, segment = rest | vel vx vy vz."""
        if not isinstance(text, str):
            self.bad(path, "expected a string")
        toks, times, vels, i = text.split(), [], [], 0
        while True:
            if i < len(toks) and toks[i] == "rest":
                vels.append((Fraction(0),) * 3)
                i += 1
            elif i < len(toks) and toks[i] == "vel" and i + 3 < len(toks):
                vels.append(tuple(self.motion_number(t, path) for t in toks[i + 1:i + 4]))
                i += 4
            else:
                self.bad(path, f"expected \"rest\" or \"vel vx vy vz\" at token {i + 1}")
            if i == len(toks):
                break
            if toks[i] != "until" or i + 1 == len(toks):
                self.bad(path, f"expected \"until T\" at token {i + 1}")
            times.append(self.motion_number(toks[i + 1], path))
            if len(times) > 1 and not times[-2] < times[-1]:
                self.bad(path, "the times must increase strictly")
            i += 2
        return Motion(times, vels)

    def motion_number(self, tok, path):
        try:
            return scene_number_from_text(tok)
        except ValueError as e:
            self.bad(path, str(e))


# ------------------------------------------------------------ certificate

class Checker:
    def __init__(self, scene, cert_file):
        self.scene, self.file, self.steps = scene, cert_file, 0

    # -- reading (a wrong type or a missing key is exit 2, an unknown key exit 1)
    def bad(self, path, reason):
        raise Unreadable(f"{self.file}: {path}", reason)

    def keys(self, obj, path, required, optional=frozenset()):
        def unknown(k):
            raise Failed(f"{path}.{k}", "unknown key")
        return check_keys(obj, path, required, optional, self.bad, unknown)

    def array(self, v, path, count=None):
        if not isinstance(v, list) or (count is not None and len(v) != count):
            self.bad(path, "expected an array" + (f" of {count}" if count is not None else ""))
        return v

    def boolean(self, v, path):
        if not isinstance(v, bool):
            self.bad(path, "expected true or false")
        return v

    def num(self, v, path):
        if not isinstance(v, str) or not CERT_NUMBER.fullmatch(v):
            self.bad(path, "expected a number as a string, \"-12\" or \"p/q\"")
        if "/" not in v:
            return int(v)                 # an integer stays an int: cheaper arithmetic
        p, q = v.split("/")
        if int(q) == 0:
            self.bad(path, "zero denominator")
        return Fraction(int(p), int(q))

    def point(self, v, path):
        return tuple(self.num(x, f"{path}[{i}]") for i, x in enumerate(self.array(v, path, 4)))

    def literal(self, v, path):
        """A literal as written: five integers (s1, s3)."""
        nums = [self.num(x, f"{path}[{i}]") for i, x in enumerate(self.array(v, path, 5))]
        for i, x in enumerate(self.array(v, path, 5)):
            if "/" in x:
                self.bad(f"{path}[{i}]", "a literal holds integers only")
        lit = tuple(int(x) for x in nums)
        if not any(lit):
            raise Failed(path, "the literal is all zero")
        return lit

    # -- the document (s3)
    def check(self, doc):
        if not isinstance(doc, dict):
            self.bad("$", "expected an object")
        self.keys(doc, "$", {"format", "semantics", "time", "claim", "pairs"}, {"scene"})
        if not isinstance(doc["format"], str) or doc["format"] != "clash4d-certificate/1":
            self.bad("format", "expected \"clash4d-certificate/1\"")
        if not isinstance(doc["semantics"], str) or doc["semantics"] not in SEMANTICS:
            self.bad("semantics", "expected \"regularised\" or \"closed\"")
        if "scene" in doc and not isinstance(doc["scene"], str):
            self.bad("scene", "expected a string")
        self.closed = doc["semantics"] == "closed"
        tL, tH = self.scene.time
        for i, x in enumerate(self.array(doc["time"], "time", 2)):
            if self.num(x, f"time[{i}]") != (tL, tH)[i]:
                raise Failed(f"time[{i}]", f"{x} is not the scene's {('tL', 'tH')[i]} = {(tL, tH)[i]}")
        claim = self.keys(doc["claim"], "claim", {"collide", "earliest", "all_pairs"})
        pairs = self.array(doc["pairs"], "pairs")
        records, seen = [], set()
        for i, pair in enumerate(pairs):                         # rule 1
            path = f"pairs[{i}]"
            self.keys(pair, path, {"objects", "collide"}, {"apart", "witness", "touch", "earliest"})
            names = self.array(pair["objects"], path + ".objects", 2)
            for j, n in enumerate(names):
                if not isinstance(n, str):
                    self.bad(f"{path}.objects[{j}]", "expected a string")
                if n not in self.scene.objects:
                    raise Failed(f"{path}.objects[{j}]", f"\"{n}\" is not an object of the scene")
            key = frozenset(names)
            if len(key) != 2:
                raise Failed(path + ".objects", "the two objects are the same")
            if key in self.scene.ignored:
                raise Failed(path + ".objects", f"the pair {names[0]}/{names[1]} is ignored")
            records.append(self.pair(pair, path, *(self.scene.objects[n] for n in names)))
            if key in seen:
                raise Failed(path + ".objects", f"the pair {names[0]}/{names[1]} appears twice")
            seen.add(key)
        collide, earliest, all_pairs = (self.boolean(claim[k], "claim." + k)
                                        for k in ("collide", "earliest", "all_pairs"))
        return self.claim(records, seen, collide, earliest, all_pairs)

    def claim(self, records, seen, collide, earliest, all_pairs):
        """The rules of s3 that tie the PAIRs to the claim; returns the s5 line."""
        tL, tH = self.scene.time
        sem = "closed" if self.closed else "regularised"
        hits = [r for r in records if r["collide"]]
        if collide != bool(hits):                                   # rule 2
            raise Failed("claim.collide", f"is {str(collide).lower()}, but "
                         + ("a PAIR collides" if hits else "no PAIR collides"))
        tstar = None
        if earliest:                                                # rule 4
            for r in hits:
                if r["tstar"] is None:
                    raise Failed(r["path"], "the claim is earliest, but this pair has no earliest proof")
            if collide and not all_pairs:
                if len(hits) != 1:
                    raise Failed("pairs", f"{len(hits)} PAIRs collide; an earliest claim names one")
                tstar = hits[0]["tstar"]
        if not collide or all_pairs or tstar is not None:           # rules 3 and 4
            names = self.scene.order
            for a, b in itertools.combinations(names, 2):
                k = frozenset((a, b))
                if k not in self.scene.ignored and k not in seen:
                    raise Failed("pairs", f"no PAIR for {a}/{b}")
        for r in records:                                           # rule 5
            if r["collide"]:
                continue
            if tstar is not None:
                if r["until"] < tstar:
                    raise Failed(r["path"] + ".apart.until", f"{r['until']} is before t* = {tstar}")
            elif r["until"] != tH:
                raise Failed(r["path"] + ".apart.until", f"{r['until']} is not tH = {tH}")
            elif self.closed and r["open_end"]:
                raise Failed(r["path"] + ".apart.open_end", "must be false: a touch at tH counts")
        apart = len(records) - len(hits)
        plural = lambda n, w: f"{n} {w}" + ("" if n == 1 else "s")
        if not collide:
            return f"verified: no collision in [{tL}, {tH}] ({sem}): {plural(apart, 'pair')} apart"
        if all_pairs:
            listed = ", ".join(f"{r['names'][0]}/{r['names'][1]}"
                               + (f" at t* = {r['tstar']}" if earliest else "") for r in hits)
            return f"verified: colliding pairs ({sem}): {listed}; {plural(apart, 'other pair')} apart"
        r = hits[0]
        who = f"{r['names'][0]} and {r['names'][1]}"
        if earliest:
            return (f"verified: earliest collision ({sem}): {who} at t* = {r['tstar']}, "
                    f"contact {fmt_point(r['point'])}")
        return f"verified: collision ({sem}): {who} at {fmt_point(r['point'])}"

    def pair(self, pair, path, A, B):
        """One PAIR (s3): its proof, and what rule 5 needs of it."""
        tL, tH = self.scene.time
        rec = {"path": path, "names": (A.name, B.name), "tstar": None, "point": None,
               "until": None, "open_end": False}
        rec["collide"] = collide = self.boolean(pair["collide"], path + ".collide")
        # The proofs a PAIR holds: a wrong combination is a failure (1), as an unknown key.
        present = {k for k in ("apart", "witness", "touch", "earliest") if k in pair}
        if not collide and present != {"apart"}:
            raise Failed(path, "a PAIR with collide false holds apart and nothing else")
        if collide and present not in ({"witness"}, {"touch"}, {"earliest", "apart"}):
            raise Failed(path, "a colliding PAIR holds one of witness, touch, or earliest with apart")
        if present == {"witness"} and self.closed:
            raise Failed(path + ".witness", "a witness is for regularised semantics (closed: touch)")
        if present == {"touch"} and not self.closed:
            raise Failed(path + ".touch", "a touch is for closed semantics (regularised: witness)")
        if not collide:
            rec["until"], rec["open_end"] = self.apart(pair["apart"], path + ".apart", A, B)
        elif "witness" in pair:
            rec["point"] = w = self.point(pair["witness"], path + ".witness")
            self.witness(w, path + ".witness", A, B)
        elif "touch" in pair:
            t = self.keys(pair["touch"], path + ".touch", {"point", "inside"})
            rec["point"] = c = self.point(t["point"], path + ".touch.point")
            if not tL <= c[3] <= tH:
                raise Failed(path + ".touch.point[3]", f"{c[3]} is outside [{tL}, {tH}]")
            self.inside_closed(t["inside"], path + ".touch.inside", c, A, B)
        else:
            e = self.keys(pair["earliest"], path + ".earliest", {"t", "point", "inside"})
            p = path + ".earliest"
            rec["tstar"] = ts = self.num(e["t"], p + ".t")
            rec["point"] = c = self.point(e["point"], p + ".point")
            if c[3] != ts:
                raise Failed(p + ".point[3]", f"{c[3]} is not t = {ts}")
            if not (tL <= ts < tH if not self.closed else tL <= ts <= tH):
                raise Failed(p + ".t", f"{ts} is outside [{tL}, {tH}" + (")" if not self.closed else "]"))
            if self.closed:
                self.inside_closed(e["inside"], p + ".inside", c, A, B)
            else:
                ins = self.array(e["inside"], p + ".inside", 1)
                w = self.point(ins[0], p + ".inside[0]")
                self.witness(w, p + ".inside[0]", A, B)
                if not w[3] > ts:
                    raise Failed(p + ".inside[0][3]", f"{w[3]} is not after t* = {ts}")
                self.generic(c, w, p + ".inside[0]", [A, B])
            until, open_end = self.apart(pair["apart"], path + ".apart", A, B)
            if until != ts:
                raise Failed(path + ".apart.until", f"{until} is not t* = {ts}")
        return rec

    def inside_closed(self, v, path, c, A, B):
        ins = self.array(v, path, 2)
        for j, O in enumerate((A, B)):
            self.generic(c, self.point(ins[j], f"{path}[{j}]"), f"{path}[{j}]", [O])

    def witness(self, w, path, A, B):
        """A point strictly inside both objects, at a time that is no velocity change (s3)."""
        tL, tH = self.scene.time
        if not tL < w[3] < tH:
            raise Failed(path + "[3]", f"t = {w[3]} is not strictly inside ({tL}, {tH})")
        for O in (A, B):
            if O.motion.is_change(w[3]):
                raise Failed(path + "[3]", f"t = {w[3]} is a velocity change of {O.name}")
            if not strictly_true(O.formula_at(w[3]), w):
                raise Failed(path, f"{fmt_point(w)} is not inside {O.name} with strict signs")

    def generic(self, c, w, path, objs):
        """w is a generic witness of c for objs (s3): c is in the closure of their interior."""
        lo, hi = min(c[3], w[3]), max(c[3], w[3])
        for O in objs:
            T = O.motion.change_between(lo, hi)
            if T is not None:
                raise Failed(path + "[3]", f"a velocity change of {O.name} at t = {T} lies between "
                                       f"{c[3]} and {w[3]}")
        for O in objs:
            f = O.formula_at((lo + hi) / 2)
            if not strictly_true(f, w):
                raise Failed(path, f"{fmt_point(w)} is not inside {O.name} with strict signs")
            for k in sorted(literals_of(f, set())):
                lc = value(k, c)
                if lc != 0 and sign(lc) != sign(value(k, w)):
                    raise Failed(path, f"the literal {list(k)} of {O.name} is {lc} at "
                                       f"{fmt_point(c)} and {value(k, w)} at the witness")

    # -- APART (s3) and its leaves (s4)
    def apart(self, v, path, A, B):
        tL, tH = self.scene.time
        ap = self.keys(v, path, {"until", "pieces"}, {"open_end"})
        until = self.num(ap["until"], path + ".until")
        open_end = self.boolean(ap.get("open_end", False), path + ".open_end")
        if until > tH:
            raise Failed(path + ".until", f"{until} is after tH = {tH}")
        pieces = self.array(ap["pieces"], path + ".pieces")
        at = tL
        for i, pc in enumerate(pieces):
            pp = f"{path}.pieces[{i}]"
            pc = self.keys(pc, pp, {"t", "proof"})
            lo, hi = (self.num(x, f"{pp}.t[{j}]") for j, x in enumerate(self.array(pc["t"], pp + ".t", 2)))
            if lo != at:
                raise Failed(pp + ".t[0]", f"{lo} is not {at}" + (" (tL)" if i == 0 else " (the previous hi)"))
            if not lo < hi:
                raise Failed(pp + ".t[1]", f"lo = {lo} is not below hi = {hi}")
            for O in (A, B):
                T = O.motion.change_between(lo, hi)
                if T is not None:
                    raise Failed(pp + ".t", f"a velocity change of {O.name} at t = {T} lies inside")
            mid = (lo + hi) / 2
            slab_lo, slab_hi = primitive((0, 0, 0, -1, lo)), primitive((0, 0, 0, 1, -hi))
            strict_hi = slab_hi if self.closed and open_end and hi == until else None
            self.node(pc["proof"], pp + ".proof", A.formula_at(mid), B.formula_at(mid),
                      [slab_lo, slab_hi], [], strict_hi)
            at = hi
        if at != until:
            raise Failed(path + ".until", f"the pieces end at {at}, not at until = {until}")
        return until, open_end

    def node(self, v, path, fa, fb, slab, split_path, strict_hi):
        """A proof tree: splits down to leaves (s3 NODE); iterative, so depth is no recursion."""
        stack = [(v, path, split_path)]
        while stack:
            v, path, spl = stack.pop()
            if not isinstance(v, dict):
                self.bad(path, "expected an object")
            if "split" not in v:                  # s3: a NODE with a split is a split node
                self.keys(v, path, {"conflicts"})
                self.leaf(v["conflicts"], path, fa, fb, slab, spl, strict_hi)
                continue
            self.keys(v, path, {"split", "below", "above"})
            if len(spl) >= MAX_SPLIT_DEPTH:
                raise Failed(path, f"splits nested more than {MAX_SPLIT_DEPTH} deep")
            s = self.literal(v["split"], path + ".split")
            if not any(s[:4]):
                raise Failed(path + ".split", "(a, b, c, e_t) is zero: s = 0 is not a hyperplane")
            stack.append((v["above"], path + ".above", spl + [negate(s)]))
            stack.append((v["below"], path + ".below", spl + [s]))

    def leaf(self, v, path, fa, fb, slab, spl, strict_hi):
        """s4: every conflict's arithmetic, then every term closed off."""
        conflicts = []
        for j, cf in enumerate(self.array(v, path + ".conflicts")):
            cp = f"{path}.conflicts[{j}]"
            cf = self.keys(cf, cp, {"literals", "lambda"}, {"of"})
            of = cf.get("of", "both")
            if not isinstance(of, str):
                self.bad(cp + ".of", "expected a string")
            if of not in ("both", "A", "B"):
                raise Failed(cp + ".of", "expected \"both\", \"A\" or \"B\"")
            if not self.closed:
                of = "both"                       # regularised ignores `of`
            raw_lits = self.array(cf["literals"], cp + ".literals")
            raw_lams = self.array(cf["lambda"], cp + ".lambda")
            if not raw_lits:
                raise Failed(cp + ".literals", "a conflict needs at least one literal")
            if len(raw_lams) != len(raw_lits):
                raise Failed(cp + ".lambda", f"{len(raw_lams)} multipliers for {len(raw_lits)} literals")
            lits, lams = [], []
            for i, (lit, lam) in enumerate(zip(raw_lits, raw_lams)):
                lits.append(self.literal(lit, f"{cp}.literals[{i}]"))
                lams.append(self.num(lam, f"{cp}.lambda[{i}]"))
                if not lams[-1] > 0:
                    raise Failed(f"{cp}.lambda[{i}]", f"{lams[-1]} is not positive")
            # Over one common denominator, so the sums are of integers (linear in the conflict).
            den = 1
            for lam in lams:
                if isinstance(lam, Fraction) and den % lam.denominator:
                    den = den * lam.denominator // math.gcd(den, lam.denominator)
            scaled = [lam * den if isinstance(lam, int) else lam.numerator * (den // lam.denominator)
                      for lam in lams]
            total = [Fraction(sum(k * lit[m] for k, lit in zip(scaled, lits)), den) for m in range(5)]
            if any(total[:4]):
                raise Failed(cp, "sum lambda_i (a_i, b_i, c_i, e_t,i) = "
                             f"({', '.join(map(str, total[:4]))}), not zero")
            keys = [primitive(lit) for lit in lits]
            if not self.closed or of != "both":                # every literal strict
                ok = total[4] >= 0
            else:                                             # non-strict, but for t - hi
                ok = total[4] > 0 or (total[4] == 0 and strict_hi is not None and strict_hi in keys)
            if not ok:
                raise Failed(cp, f"sum lambda_i e_i = {total[4]}: the literals "
                             "are not in conflict")
            conflicts.append((of, frozenset(keys)))
        self.terms(path, fa, fb, slab, spl, conflicts)

    def step(self, path, n):
        """s4: a step is one node of the walk or one conflict's count updated."""
        self.steps += n
        if self.steps > STEP_LIMIT:
            raise Failed(path, f"more than {STEP_LIMIT:,} steps of term enumeration: "
                               "the certificate is too costly to check")

    def terms(self, path, fa, fb, slab, spl, conflicts):
        """Enumerate the terms (s4), closing off partial terms as soon as they are.

        Regularised: one pool of literals (terms of F_A AND F_B, path, slab); a pool is
        closed off by a literal and its negation or by a conflict inside it.  Closed: pool
        A holds TA and the slab, pool B TB and the slab, pool U all of TA, TB, path, slab;
        conflicts "of" A close pool A, "of" B pool B, "both" pool U.
        """
        closed = self.closed
        # Pools: 0 holds TA and the slab, 1 TB and the slab (closed only), 2 everything.
        # Each conflict keeps the count of its literals missing from its pool, so a
        # literal's coming or going costs one step per conflict holding it (s4).
        pools = ({}, {}, {})
        index = ({}, {}, {})     # per pool: literal key -> the conflicts holding it
        missing = []
        for c, (of, ks) in enumerate(conflicts):
            pid = {"A": 0, "B": 1, "both": 2}[of]
            missing.append(len(ks))
            self.step(path, len(ks))
            for k in ks:
                index[pid].setdefault(k, []).append(c)

        def inc(pid, k):
            pool = pools[pid]
            pool[k] = pool.get(k, 0) + 1
            hit = False
            if pool[k] == 1:
                watchers = index[pid].get(k, ())
                self.step(path, len(watchers))
                for c in watchers:
                    missing[c] -= 1
                    hit = hit or missing[c] == 0
            return hit

        def dec(pid, k):
            pool = pools[pid]
            pool[k] -= 1
            if not pool[k]:
                del pool[k]
                watchers = index[pid].get(k, ())
                self.step(path, len(watchers))
                for c in watchers:
                    missing[c] += 1

        U = pools[2]
        shut = False
        for k in [primitive(s) for s in spl] + slab:
            shut = inc(2, k) or shut
        if closed:
            for pid in (0, 1):
                for k in slab:
                    shut = inc(pid, k) or shut
        # closed off before any term literal?
        if shut or (not closed and any(negate(k) in U for k in U)):
            return
        term = []

        def add(k, side):
            term.append((k, side))
            hit = inc(2, k)
            if closed:
                hit = inc(side, k) or hit
            return hit or (not closed and negate(k) in U)

        def remove(k, side):
            term.pop()
            dec(2, k)
            if closed:
                dec(side, k)

        def dfs(pending):
            """True when every term completing the current partial term is closed off."""
            added = []
            try:
                while pending is not None:
                    self.step(path, 1)
                    (node, side), pending = pending
                    tag, arg = node
                    if tag == "lit":
                        added.append((arg, side))
                        if add(arg, side):
                            return True
                    elif tag == "and":
                        for c in reversed(arg):
                            pending = ((c, side), pending)
                    else:
                        return all(dfs(((c, side), pending)) for c in arg)
                # a whole term that no conflict closes off: the first failure
                shown = "; ".join(("A " if closed and s == 0 else "B " if closed else "")
                                  + str(list(k)) for k, s in term)
                raise Failed(path, "no conflict closes off the term "
                             + ("" if closed else "(with the path and slab) ") + f"[{shown}]")
            finally:
                for k, side in reversed(added):
                    remove(k, side)

        dfs(((fa, 0), ((fb, 1), None)))


def main(argv):
    """Runs the check in a thread with a large stack: deep JSON and formulas recurse."""
    result = [2]

    def run():
        result[0] = check_files(argv)
    old_limit, old_stack = sys.getrecursionlimit(), threading.stack_size()
    sys.setrecursionlimit(50000)
    threading.stack_size(256 << 20)
    try:
        t = threading.Thread(target=run)
        t.start()
        t.join()
    finally:
        sys.setrecursionlimit(old_limit)
        threading.stack_size(old_stack)
    return result[0]


def check_files(argv):
    if len(argv) != 3:
        print(f"usage: {PROG} SCENE.json CERT.json", file=sys.stderr)
        return 2
    try:
        scene = SceneReader(argv[1])
        doc = load_certificate(argv[2])
        line = Checker(scene, argv[2]).check(doc)
    except Unreadable as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    except Failed as e:
        print(f"{PROG}: {argv[2]}: {e}", file=sys.stderr)
        return 1
    except Limit as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 3
    except (MemoryError, RecursionError) as e:   # s6: a limit of this checker, nothing proved
        print(f"{PROG}: {argv[2]}: beyond this checker's limits ({type(e).__name__})", file=sys.stderr)
        return 3
    except Exception as e:                        # a flaw of this checker: nothing proved, no traceback
        print(f"{PROG}: {argv[2]}: internal error of the checker: {type(e).__name__}: {e}", file=sys.stderr)
        return 4
    print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
