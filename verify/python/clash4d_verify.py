#!/usr/bin/env python3
"""A second, independent checker of clash4d certificates, standard library only.

    python3 clash4d_verify.py SCENE.json CERT.json

Written from docs/certificate-format.md ("the doc", section numbers below as
"s2.1" and so on) and ../shared/spec/scene-format.md alone; it shares no code
with clash4d (not even the scene reader). Exits as `clash4d verify`: 0 and the
proved claim (s5), 1 and the first reason the certificate fails with its JSON
path, 2 when the scene or the certificate cannot be read, 3 beyond a limit
(nesting, memory), 4 on a flaw of this checker (never a traceback).

Two formats: clash4d-certificate/1, and clash4d-certificate/turning-1 for
scenes where some object turns (s8: literals whose coefficients are
polynomials in t, polynomial multipliers, TIMEs that are algebraic numbers),
each on its kind of scene only; verdicts and earliest times (s8.4: a witness
path on (t*, T1] in regularised semantics, the touch at t* in closed) in both.
The s8 part is exact polynomial arithmetic over Fraction: Sturm sequences count
roots, Yun's factorisation gives odd parts.
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
MAX_POSES = 10_000           # scene-format.md: poses of one motion (more: the scene is refused)
FORMAT_1 = "clash4d-certificate/1"
FORMAT_TURNING = "clash4d-certificate/turning-1"     # s8

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
    """The negation of a literal key: a /1 5-tuple, or a LIT's four coefficient tuples (s8.2)."""
    if k and type(k[0]) is tuple:
        return tuple(tuple(-x for x in p) for p in k)
    return tuple(-x for x in k)


def fmt_lit(k):
    if k and type(k[0]) is tuple:
        return "[" + ", ".join("[" + ", ".join(map(str, p or (0,))) + "]" for p in k) + "]"
    return str(list(k))


def value(k, p):
    """A literal [a, b, c, e_t, e] at a space-time point (x, y, z, t)."""
    return k[0] * p[0] + k[1] * p[1] + k[2] * p[2] + k[3] * p[3] + k[4]


def sign(x):
    return (x > 0) - (x < 0)


def fmt_point(p):
    """s5 and s8.5: rationals in lowest terms, TIMEs and FIELDs by their own str."""
    return "(" + ", ".join(str(x) for x in p) + ")"


# ---------------------------------------------- polynomials over Q (s8.1)
# A polynomial is a list of rationals (int or Fraction), constant term first,
# without trailing zeros: [] is the zero polynomial, [c] a constant.

def p_trim(p):
    p = list(p)
    while p and p[-1] == 0:
        p.pop()
    return p


def p_const(c):
    return p_trim([c])


def p_add(p, q):
    if len(p) < len(q):
        p, q = q, p
    return p_trim([a + (q[i] if i < len(q) else 0) for i, a in enumerate(p)])


def p_neg(p):
    return [-c for c in p]


def p_sub(p, q):
    return p_add(p, p_neg(q))


def p_scale(p, c):
    return p_trim([c * a for a in p])


def p_mul(p, q):
    if not p or not q:
        return []
    r = [0] * (len(p) + len(q) - 1)
    for i, a in enumerate(p):
        if a:
            for j, b in enumerate(q):
                r[i + j] += a * b
    return p_trim(r)


def p_sum(polys):
    total = []
    for p in polys:
        total = p_add(total, p)
    return total


def p_divmod(p, q):
    """Quotient and remainder of p by q != 0 (exact, over Fraction)."""
    if not q:
        raise ZeroDivisionError("polynomial division by zero")
    r = [Fraction(c) for c in p]
    dq, lead = len(q) - 1, Fraction(q[-1])
    quot = [Fraction(0)] * max(len(p) - dq, 0)
    for k in range(len(p) - 1 - dq, -1, -1):
        c = r[k + dq] / lead
        quot[k] = c
        if c:
            for j in range(dq + 1):
                r[k + j] -= c * q[j]
    return p_trim(quot), p_trim(r[:dq])


def p_div(p, q):
    return p_divmod(p, q)[0]


def p_monic(p):
    return [Fraction(c) / p[-1] for c in p] if p else []


def p_gcd(p, q):
    """The monic greatest common divisor (zero when both are zero)."""
    while q:
        p, q = q, p_monic(p_divmod(p, q)[1])
    return p_monic(p)


def p_deriv(p):
    return p_trim([i * p[i] for i in range(1, len(p))])


def p_eval(p, x):
    v = 0
    for c in reversed(p):
        v = v * x + c
    return v


def p_squarefree(p):
    """p divided by gcd(p, p'): the same roots, each simple."""
    return p_monic(p_div(p, p_gcd(p, p_deriv(p)))) if len(p) > 1 else p_monic(p)


def p_yun(p):
    """Yun's square-free factorisation of a non-constant p: [a_1, a_2, ...], monic, square-free
    and pairwise coprime, with p = c a_1 a_2^2 a_3^3 ... (s8.1)."""
    d0 = p_deriv(p)
    a0 = p_gcd(p, d0)
    b, c = p_div(p, a0), p_div(d0, a0)
    d = p_sub(c, p_deriv(b))
    factors = []
    while len(b) > 1:
        a = p_gcd(b, d)
        factors.append(a)
        b = p_div(b, a)
        d = p_sub(p_div(d, a), p_deriv(b))
    return factors


def p_odd_part(p):
    """g = p / s^2 where p = c s^2 g, g square-free: the factors of odd multiplicity (s8.1)."""
    g = [1]
    if len(p) > 1:
        for i, a in enumerate(p_yun(p)):
            if i % 2 == 0:                      # multiplicity i + 1 odd
                g = p_mul(g, a)
    return g


_STURM = {}


def p_sturm(p):
    """Sturm sequence p, p', -rem, ... (each scaled by a positive number only)."""
    key = tuple(p)
    seq = _STURM.get(key)
    if seq is None:
        seq = [p, p_deriv(p)]
        while seq[-1]:
            r = p_neg(p_divmod(seq[-2], seq[-1])[1])
            seq.append(p_scale(r, 1 / abs(Fraction(r[-1]))) if r else r)
        seq.pop()
        if len(_STURM) > 4096:
            _STURM.clear()
        _STURM[key] = seq
    return seq


def sign_changes(seq, x):
    n, last = 0, 0
    for p in seq:
        s = sign(p_eval(p, x))
        if s:
            n += last * s < 0
            last = s
    return n


def roots_open(p, x, y):
    """Distinct real roots of p != 0 in the open interval (x, y), x < y rational: Sturm's count
    after dividing out the roots at the ends (s8.1)."""
    for e in (x, y):
        while len(p) > 1 and p_eval(p, e) == 0:
            p = p_div(p, [-e, 1])
    if len(p) <= 1:
        return 0
    seq = p_sturm(p)
    return sign_changes(seq, x) - sign_changes(seq, y)


# ---------------------------------------------------- TIMEs (s8.1)
# A TIME is a rational (int or Fraction) or an Algebraic: the one root of poly in (lo, hi).

class Algebraic:
    """The one real root of `poly` in the open interval `between` (s8.1), already validated.
    Its interval is refined in place (halving); `exact` holds the value once a midpoint is it."""

    def __init__(self, read, lo, hi):
        self.poly, self.between = read, (lo, hi)     # as read: what s8.5 prints
        self.sq = p_squarefree(p_trim(read))         # simple roots: a sign change at each
        self.lo, self.hi = Fraction(lo), Fraction(hi)
        self.sign_lo = sign(p_eval(self.sq, self.lo))
        self.exact = None

    def refine(self):
        """Halve the interval, keeping the half whose ends the square-free poly has opposite
        signs at, or stop at a midpoint that is the root."""
        m = (self.lo + self.hi) / 2
        s = sign(p_eval(self.sq, m))
        if s == 0:
            self.exact = m
        elif s == self.sign_lo:
            self.lo = m
        else:
            self.hi = m

    def __str__(self):
        """s8.5: `root of [c0, c1, ...] in (lo, hi)`, as read, in lowest terms."""
        return (f"root of [{', '.join(map(str, self.poly))}] in "
                f"({self.between[0]}, {self.between[1]})")


class AtT:
    """A FIELD {"at_t": POLY} (s8.1): POLY at the point's TIME."""

    def __init__(self, read):
        self.read, self.poly = read, p_trim(read)

    def __str__(self):
        """s8.5: `[c0, c1, ...](t)`, as read, in lowest terms."""
        return "[" + ", ".join(map(str, self.read)) + "](t)"


def field_poly(x):
    """A FIELD as a polynomial in t: a rational is a constant."""
    return x.poly if isinstance(x, AtT) else p_const(x)


def fmt_poly(p):
    return "[" + ", ".join(map(str, p or [0])) + "]"


def rat(x):
    """The rational value of a TIME, or None while it is known by an interval only."""
    if isinstance(x, Algebraic):
        return x.exact
    return x


def refine(x):
    if rat(x) is None:
        x.refine()


def sign_at(p, r):
    """The exact sign of the polynomial p at the TIME r (s8.1)."""
    q = rat(r)
    if q is not None:
        return sign(p_eval(p, q))
    if not p:
        return 0
    g = p_gcd(p, r.sq)                       # p(r) = 0 exactly when g has a root in (lo, hi)
    if len(g) > 1 and roots_open(g, r.lo, r.hi) > 0:
        return 0
    while roots_open(p, r.lo, r.hi) > 0:     # refine until p has no root in the interval
        r.refine()
        if r.exact is not None:
            return sign(p_eval(p, r.exact))
    return sign(p_eval(p, (r.lo + r.hi) / 2))


def cmp_time(a, b):
    """-1, 0 or 1 as the TIME a is below, equal to or above the TIME b, exactly (s8.1)."""
    qa, qb = rat(a), rat(b)
    if qa is not None and qb is not None:
        return sign(qa - qb)
    if qa is not None:
        return -cmp_time(b, a)
    if qb is not None:                       # a by its interval, b rational
        while True:
            if qb <= a.lo:
                return 1
            if qb >= a.hi:
                return -1
            if p_eval(a.sq, qb) == 0:        # the one root in (lo, hi)
                return 0
            a.refine()
            if a.exact is not None:
                return sign(a.exact - qb)
    g = p_gcd(a.sq, b.sq)                    # equal when g has a root in the overlap
    lo, hi = max(a.lo, b.lo), min(a.hi, b.hi)
    if len(g) > 1 and lo < hi and roots_open(g, lo, hi) > 0:
        return 0
    while True:                              # otherwise refine both until disjoint
        if a.hi <= b.lo:
            return -1
        if b.hi <= a.lo:
            return 1
        a.refine()
        b.refine()
        if a.exact is not None or b.exact is not None:
            return cmp_time(a, b)


def isolate(f, x):
    """Refine the TIME x until its interval holds no root of f but possibly x itself (s8.1)."""
    if rat(x) is None:
        own = 1 if sign_at(f, x) == 0 else 0
        while rat(x) is None and roots_open(f, x.lo, x.hi) != own:
            x.refine()


def rational_ends(a, b, strict):
    """Rationals a <= L <= U <= b (L < U when strict) with no point of (a, L) or (U, b) but
    what the TIMEs' intervals hold: a itself or its interval's upper end, b or its lower end."""
    while True:
        L = rat(a) if rat(a) is not None else a.hi
        U = rat(b) if rat(b) is not None else b.lo
        if L < U or (L == U and not strict):
            return L, U
        refine(a)
        refine(b)


def roots_between(f, a, b):
    """Distinct real roots of f != 0 in the open interval (a, b) of TIMEs a < b (s8.1): each
    algebraic end refined until its interval holds no root of f but the end itself, then
    Sturm's count between the rational ends, plus one for each such end that is a root."""
    if len(f) <= 1:
        return 0
    isolate(f, a)
    isolate(f, b)
    L, U = rational_ends(a, b, False)
    n = roots_open(f, L, U) if L < U else 0
    inner = {x for x in (L, U) if x != rat(a) and x != rat(b)}
    return n + sum(1 for x in inner if p_eval(f, x) == 0)


def point_inside(p, a, b):
    """A rational point of (a, b), TIMEs a < b, where p != 0 (p not the zero polynomial)."""
    L, U = rational_ends(a, b, True)
    k = 1
    while True:
        m = L + (U - L) / (1 << k)
        if p_eval(p, m) != 0:
            return m
        k += 1


def nonneg_on(p, a, b):
    """p >= 0 on [a, b] (s8.1): p is zero, or its odd part has no root in (a, b) and p is
    positive at some point of (a, b)."""
    if not p:
        return True
    if roots_between(p_odd_part(p), a, b) > 0:
        return False
    return p_eval(p, point_inside(p, a, b)) > 0


def positive_on(p, a, b, open_end=False):
    """p > 0 on [a, b] (s8.1), or on [a, b) when open_end."""
    if not p or sign_at(p, a) <= 0:
        return False
    if not open_end and sign_at(p, b) <= 0:
        return False
    return roots_between(p, a, b) == 0


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
    """D(t) = v_k t + o_k on segment k, between the listed times (scene-format.md, Motion).

    A pose motion (scene-format.md, "Motion with rotation (poses)") also keeps its poses
    (t, c, q): its breakpoints (s8.2) are the pose times; without rotation it is the
    piecewise-linear translation D(t) = c(t) (the offsets given), whose velocity changes are
    the pose times where the velocity changes, as the same motion written in ROBMOD."""

    def __init__(self, times, vels, offs=None, poses=None):
        self.times, self.vels, self.poses = times, vels, poses
        # s8: an object turns when some pose's rotate has a non-zero x, y or z
        self.turning = any(any(q[1:]) for _, _, q in poses or ())
        # A velocity change is every time the motion lists (s2.2), even between equal velocities.
        self.changes = list(times)
        # s8.2: the breakpoints, the pose times or a ROBMOD motion's until times
        self.breakpoints = [t for t, _, _ in poses] if poses is not None else self.changes
        if offs is not None:
            self.offs = offs
            return
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

    @staticmethod
    def from_poses(poses):
        """Poses (t_i, c_i, q_i): at rest at c_0 before t_0 and at c_m after t_m, c linear
        between (the translation of a motion without rotation). As the scene reader does, a
        pose time where the velocity does not change is no velocity change: the same motion
        written in ROBMOD has none there."""
        zero = (Fraction(0),) * 3
        times, vels, offs = [], [zero], [poses[0][1]]
        for i, (t0, c0, _) in enumerate(poses):
            if i + 1 < len(poses):
                t1, c1, _ = poses[i + 1]
                v = tuple((c1[k] - c0[k]) / (t1 - t0) for k in range(3))
            else:
                v = zero
            if v != vels[-1]:
                times.append(t0)
                vels.append(v)
                offs.append(tuple(c0[k] - v[k] * t0 for k in range(3)))
        return Motion(times, vels, offs, poses)

    def piece_qc(self, k):
        """q(t) and c(t) as polynomials on motion piece k (s8.2): the k-th open interval
        between breakpoints. ROBMOD: q = (1, 0, 0, 0), c(t) = D(t) = v_k t + o_k."""
        if self.poses is None:                      # the pieces are the segments
            v, o = self.vels[k], self.offs[k]
            return ([1], [], [], []), tuple(p_trim([o[i], v[i]]) for i in range(3))
        P = self.poses
        if k == 0 or k == len(P):                   # before the first pose, after the last
            _, c, q = P[0] if k == 0 else P[-1]
            return tuple(map(p_const, q)), tuple(map(p_const, c))
        (t0, c0, q0), (t1, c1, q1) = P[k - 1], P[k]
        s = [-t0 / (t1 - t0), 1 / (t1 - t0)]        # s = (t - t_i) / (t_{i+1} - t_i)
        return (tuple(p_add(p_const(q0[i]), p_scale(s, q1[i] - q0[i])) for i in range(4)),
                tuple(p_add(p_const(c0[i]), p_scale(s, c1[i] - c0[i])) for i in range(3)))

    def piece_at(self, T, after):
        """The motion piece holding the TIME T (k: the number of breakpoints below T); with
        `after`, the piece just after T (the breakpoints at most T)."""
        lo, hi = 0, len(self.breakpoints)
        while lo < hi:
            mid = (lo + hi) // 2
            c = cmp_time(self.breakpoints[mid], T)
            if c < 0 or (c == 0 and after):
                lo = mid + 1
            else:
                hi = mid
        return lo

    # The times increase strictly: binary searches, so a motion of many
    # segments costs a logarithm per piece, not a scan.
    def segment(self, t):
        return bisect.bisect_left(self.times, t)

    def is_breakpoint(self, t):
        i = bisect.bisect_left(self.breakpoints, t)
        return i < len(self.breakpoints) and self.breakpoints[i] == t

    def is_change(self, t):
        i = bisect.bisect_left(self.times, t)
        return i < len(self.times) and self.times[i] == t

    def change_between(self, lo, hi):
        """The first velocity change strictly between lo < hi, or None."""
        i = bisect.bisect_right(self.times, lo)
        return self.times[i] if i < len(self.times) and self.times[i] < hi else None


def extrude(node, literal):
    """The formula with each atom (a, b, c, d) replaced by ("lit", literal(atom))."""
    tag, arg = node
    if tag == "atom":
        return ("lit", literal(arg))
    kids = []
    for c in (extrude(c, literal) for c in arg):      # flatten AND of AND, OR of OR
        kids.extend(c[1] if c[0] == tag else [c])
    return kids[0] if len(kids) == 1 else (tag, kids)


def members(node):
    """s8.3's members: an OR's members are its children's, an AND of one child has that
    child's, any other node is one member (extrude leaves no AND or OR of one child)."""
    tag, arg = node
    if tag == "or" or (tag == "and" and len(arg) == 1):
        return [m for c in arg for m in members(c)]
    return [node]


def rotation_polys(q):
    """N(q) = |q|^2 R(q), the un-normalised rotation matrix, and |q|^2, of a quaternion of
    polynomials (s8.2)."""
    w, x, y, z = q
    sq = lambda a: p_mul(a, a)
    two = lambda a, b: p_scale(p_mul(a, b), 2)
    w2, x2, y2, z2 = sq(w), sq(x), sq(y), sq(z)
    N = [[p_sub(p_add(w2, x2), p_add(y2, z2)), p_sub(two(x, y), two(w, z)), p_add(two(x, z), two(w, y))],
         [p_add(two(x, y), two(w, z)), p_sub(p_add(w2, y2), p_add(x2, z2)), p_sub(two(y, z), two(w, x))],
         [p_sub(two(x, z), two(w, y)), p_add(two(y, z), two(w, x)), p_sub(p_add(w2, z2), p_add(x2, y2))]]
    return N, p_sum((w2, x2, y2, z2))


def lit_key(polys):
    """The coprime form of a LIT (s8.2): the four polynomials times the one positive rational
    making all coefficients coprime integers, trailing zeros dropped; None when all are zero."""
    den, g = 1, 0
    for p in polys:
        for c in p:
            den = math.lcm(den, Fraction(c).denominator)
    ints = [[int(c * den) for c in p] for p in polys]
    for p in ints:
        for c in p:
            g = math.gcd(g, c)
    if g == 0:
        return None
    return tuple(tuple(c // g for c in p_trim(p)) for p in ints)


class Object:
    def __init__(self, name, formula, motion):
        self.name, self.formula, self.motion = name, formula, motion
        self.cache = {}
        self.turning_cache = {}

    def formula_at(self, t):
        """The object's formula over literals on the motion segment holding t (s2.2)."""
        k = self.motion.segment(t)
        if k not in self.cache:
            v, o = self.motion.vels[k], self.motion.offs[k]

            def literal(atom):
                n, d = atom[:3], atom[3]
                nv = sum(n[i] * v[i] for i in range(3))
                no = sum(n[i] * o[i] for i in range(3))
                return primitive((*n, -nv, d - no))
            self.cache[k] = extrude(self.formula, literal)
        return self.cache[k]

    def turning_formula(self, k):
        """The object's formula over LITs (coprime keys) on motion piece k (s8.2):
        atom (n, d) -> N(q(t)) n . x + |q(t)|^2 d - (N(q(t)) n) . c(t)."""
        if k not in self.turning_cache:
            q, c = self.motion.piece_qc(k)
            N, norm = rotation_polys(q)

            def literal(atom):
                n, d = atom[:3], atom[3]
                nt = [p_sum(p_scale(N[i][j], n[j]) for j in range(3)) for i in range(3)]
                e = p_sub(p_scale(norm, d), p_sum(p_mul(nt[i], c[i]) for i in range(3)))
                return lit_key(nt + [e])
            self.turning_cache[k] = extrude(self.formula, literal)
        return self.turning_cache[k]


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


def strictly_true_by(node, sgn):
    """The formula with strict signs, each literal's sign given by sgn(key)."""
    tag, arg = node
    if tag == "lit":
        return sgn(arg) < 0
    if tag == "and":
        return all(strictly_true_by(c, sgn) for c in arg)
    return any(strictly_true_by(c, sgn) for c in arg)


def lit_value_poly(key, point):
    """A LIT at a point of FIELDs: n_x(t) X(t) + n_y(t) Y(t) + n_z(t) Z(t) + e(t) (s8.4)."""
    return p_add(p_sum(p_mul(list(key[i]), field_poly(point[i])) for i in range(3)), list(key[3]))


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
        # s8: the scene needs the turning format when some object turns
        self.turning = any(o.motion.turning for o in self.objects.values())
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
        """ROBMOD notation: segment ("until" T segment)*, segment = rest | vel vx vy vz;
        or an object of poses."""
        if isinstance(text, dict):
            return self.pose_motion(text, path)
        if not isinstance(text, str):
            self.bad(path, "expected a ROBMOD string or {\"poses\": [...]}")
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

    def pose_motion(self, v, path):
        """scene-format.md, "Motion with rotation (poses)": {"poses": [{"t", "translate",
        "rotate"}, ...]}, t strictly increasing, rotate != 0, consecutive quaternions not
        negative multiples of each other, at most MAX_POSES poses."""
        self.keys(v, path, {"poses"})
        poses = v["poses"]
        if not isinstance(poses, list) or not poses:
            self.bad(path + ".poses", "expected a non-empty list of poses")
        if len(poses) > MAX_POSES:
            self.bad(path + ".poses", f"more than the limit of {MAX_POSES} poses")
        out = []
        for i, pose in enumerate(poses):
            p = f"{path}.poses[{i}]"
            self.keys(pose, p, {"t"}, {"translate", "rotate"})
            t = self.number(pose["t"], p + ".t")
            c = self.numbers(pose.get("translate", ["0", "0", "0"]), p + ".translate", 3)
            q = self.numbers(pose.get("rotate", ["1", "0", "0", "0"]), p + ".rotate", 4)
            if not any(q):
                self.bad(p + ".rotate", "the quaternion must not be zero")
            if out:
                t0, _, q0 = out[-1]
                if not t0 < t:
                    self.bad(p + ".t", f"times must be strictly increasing ({t} after {t0})")
                parallel = all(q0[a] * q[b] == q0[b] * q[a] for a in range(4) for b in range(a))
                if parallel and sum(q0[a] * q[a] for a in range(4)) < 0:
                    self.bad(p + ".rotate", f"a negative multiple of the quaternion of poses[{i - 1}]: "
                                            "the interpolated quaternion would pass through 0")
            out.append((t, c, q))
        return Motion.from_poses(out)

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
        if not isinstance(doc["format"], str) or doc["format"] not in (FORMAT_1, FORMAT_TURNING):
            self.bad("format", f"expected \"{FORMAT_1}\" or \"{FORMAT_TURNING}\"")
        # s8: each format on its kind of scene only; a turning object is never read as resting
        self.turning = doc["format"] == FORMAT_TURNING
        if self.turning != self.scene.turning:
            needed = FORMAT_TURNING if self.scene.turning else FORMAT_1
            raise Failed("format", f"the scene needs the format \"{needed}\" (section 8): "
                         + ("some object turns" if self.scene.turning else "no object turns"))
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
            prove = self.turning_pair if self.turning else self.pair
            records.append(prove(pair, path, *(self.scene.objects[n] for n in names)))
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
            if tstar is not None:                                   # compared exactly (s8.4)
                if cmp_time(r["until"], tstar) < 0:
                    raise Failed(r["path"] + ".apart.until", f"{r['until']} is before t* = {tstar}")
            elif cmp_time(r["until"], tH) != 0:
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
            if r["point"] is None:          # s8.5: a turning pair's regularised earliest is a path
                return f"verified: earliest collision ({sem}): {who} at t* = {r['tstar']}"
            return (f"verified: earliest collision ({sem}): {who} at t* = {r['tstar']}, "
                    f"contact {fmt_point(r['point'])}")
        if r["point"] is None:              # s8.5: a path proves a collision just after t*, no point
            return f"verified: collision ({sem}): {who} at t* = {r['tstar']}"
        return f"verified: collision ({sem}): {who} at {fmt_point(r['point'])}"

    def proofs_present(self, pair, path, collide):
        """The proofs a PAIR holds (s3): a wrong combination is a failure (1), as an unknown key."""
        present = {k for k in ("apart", "witness", "touch", "earliest") if k in pair}
        if not collide and present != {"apart"}:
            raise Failed(path, "a PAIR with collide false holds apart and nothing else")
        if collide and present not in ({"witness"}, {"touch"}, {"earliest", "apart"}):
            raise Failed(path, "a colliding PAIR holds one of witness, touch, or earliest with apart")
        if present == {"witness"} and self.closed:
            raise Failed(path + ".witness", "a witness is for regularised semantics (closed: touch)")
        if present == {"touch"} and not self.closed:
            raise Failed(path + ".touch", "a touch is for closed semantics (regularised: witness)")
        return present

    def pair(self, pair, path, A, B):
        """One PAIR (s3): its proof, and what rule 5 needs of it."""
        tL, tH = self.scene.time
        rec = {"path": path, "names": (A.name, B.name), "tstar": None, "point": None,
               "until": None, "open_end": False}
        rec["collide"] = collide = self.boolean(pair["collide"], path + ".collide")
        self.proofs_present(pair, path, collide)
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
            of = self.conflict_of(cf, cp)
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
                                  + fmt_lit(k) for k, s in term)
                raise Failed(path, "no conflict closes off the term "
                             + ("" if closed or self.turning else "(with the path and slab) ")
                             + f"[{shown}]")
            finally:
                for k, side in reversed(added):
                    remove(k, side)

        dfs(((fa, 0), ((fb, 1), None)))

    # -- s8: scenes where objects turn (format clash4d-certificate/turning-1)
    def poly_read(self, v, path, integers=False):
        """A POLY (s8.1) as read: an array of at least one number, constant term first."""
        if not isinstance(v, list) or not v:
            self.bad(path, "expected a polynomial: an array of at least one number")
        out = []
        for i, x in enumerate(v):
            out.append(self.num(x, f"{path}[{i}]"))
            if integers and "/" in x:
                self.bad(f"{path}[{i}]", "a TIME's poly holds integers only")
        return out

    def poly(self, v, path):
        return p_trim(self.poly_read(v, path))

    def time(self, v, path):
        """A TIME (s8.1): a rational, or the one root of poly in (lo, hi); each failed
        requirement a failure (1) at its place."""
        if isinstance(v, str):
            return self.num(v, path)
        t = self.keys(v, path, {"poly", "between"}, {"approx"})
        if "approx" in t and not isinstance(t["approx"], str):
            self.bad(path + ".approx", "expected a string (never read as a number)")
        read = self.poly_read(t["poly"], path + ".poly", integers=True)
        lo, hi = (self.num(x, f"{path}.between[{j}]")
                  for j, x in enumerate(self.array(t["between"], path + ".between", 2)))
        P = p_trim(read)
        if not lo < hi:
            raise Failed(path + ".between", f"lo = {lo} is not below hi = {hi}")
        if not P:
            raise Failed(path + ".poly", "the zero polynomial has no isolated root")
        for j, e in enumerate((lo, hi)):
            if p_eval(P, e) == 0:
                raise Failed(f"{path}.between[{j}]", f"{e} is a root of poly")
        n = roots_open(P, lo, hi)
        if n != 1:
            raise Failed(path, f"poly {fmt_poly(P)} has {n} distinct real roots in ({lo}, {hi}), "
                               "not exactly one")
        return Algebraic(read, lo, hi)

    def field(self, v, path):
        """A FIELD (s8.1): a rational, or {"at_t": POLY}, POLY at the point's TIME."""
        if isinstance(v, str):
            return self.num(v, path)
        f = self.keys(v, path, {"at_t"})
        return AtT(self.poly_read(f["at_t"], path + ".at_t"))

    def turning_point(self, v, path):
        """[X, Y, Z, T]: three FIELDs and a TIME (s8.4)."""
        v = self.array(v, path, 4)
        return tuple(self.field(v[i], f"{path}[{i}]") for i in range(3)) + (self.time(v[3], path + "[3]"),)

    def lit(self, v, path):
        """A LIT (s8.2): [POLY_x, POLY_y, POLY_z, POLY_e], its normal not all zero."""
        polys = [self.poly(x, f"{path}[{i}]") for i, x in enumerate(self.array(v, path, 4))]
        if not any(polys[:3]):
            raise Failed(path, "n_x, n_y and n_z are all the zero polynomial")
        return polys

    def turning_pair(self, pair, path, A, B):
        """One PAIR of a turning scene (s8.4)."""
        tL, tH = self.scene.time
        rec = {"path": path, "names": (A.name, B.name), "tstar": None, "point": None,
               "until": None, "open_end": False}
        rec["collide"] = collide = self.boolean(pair["collide"], path + ".collide")
        self.proofs_present(pair, path, collide)
        if not collide:
            rec["until"], rec["open_end"] = self.turning_apart(pair["apart"], path + ".apart", A, B)
        elif "witness" in pair:
            rec["point"] = w = self.point(pair["witness"], path + ".witness")
            self.turning_witness(w, path + ".witness", A, B)
        elif "touch" in pair:
            t = self.keys(pair["touch"], path + ".touch", {"point", "inside"})
            rec["point"] = c = self.turning_point(t["point"], path + ".touch.point")
            if cmp_time(c[3], tL) < 0 or cmp_time(c[3], tH) > 0:
                raise Failed(path + ".touch.point[3]", f"{c[3]} is outside [{tL}, {tH}]")
            self.turning_inside(t["inside"], path + ".touch.inside", c, A, B)
        else:
            p = path + ".earliest"
            if self.closed:
                e = self.keys(pair["earliest"], p, {"t", "point", "inside"})
            else:
                e = self.keys(pair["earliest"], p, {"t", "path"})
            rec["tstar"] = ts = self.time(e["t"], p + ".t")
            if self.closed:                                  # the touch at t* (s8.4)
                rec["point"] = c = self.turning_point(e["point"], p + ".point")
                if cmp_time(c[3], ts) != 0:
                    raise Failed(p + ".point[3]", f"{c[3]} is not t = {ts}")
            if cmp_time(ts, tL) < 0 or cmp_time(ts, tH) > (-1 if not self.closed else 0):
                raise Failed(p + ".t", f"{ts} is outside [{tL}, {tH}" + (")" if not self.closed else "]"))
            if self.closed:
                self.turning_inside(e["inside"], p + ".inside", c, A, B)
            else:
                self.turning_path(e["path"], p + ".path", ts, A, B)
            # the APART until t*: closed, open_end true or false (false is stronger)
            until, _ = self.turning_apart(pair["apart"], path + ".apart", A, B)
            if cmp_time(until, ts) != 0:
                raise Failed(path + ".apart.until", f"{until} is not t* = {ts}")
        return rec

    def turning_inside(self, v, path, c, A, B):
        """A touch's [WA, WB] (s8.4): generic witnesses of c for A and for B at c's time."""
        ins = self.array(v, path, 2)
        for j, O in enumerate((A, B)):
            wp = f"{path}[{j}]"
            w = self.turning_point(ins[j], wp)
            if cmp_time(w[3], c[3]) != 0:
                raise Failed(wp + "[3]", f"{w[3]} is not the point's time {c[3]}")
            self.turning_generic(c, w, wp, O)

    def turning_path(self, v, path, ts, A, B):
        """s8.4, regularised earliest: the witness path W(t) = (x, y, z)(t) / w(t) on (t*, T1].
        Every literal of A and B keeps on (t*, T1] the sign it has at W(T1) (L = n.(x, y, z) + e w
        has no root there, w > 0), and both formulas are true there with strict signs: the
        objects collide at every time of (t*, T1]."""
        tH = self.scene.time[1]
        pt = self.keys(v, path, {"x", "y", "z", "w", "to"})
        xyz = [self.poly(pt[a], f"{path}.{a}") for a in "xyz"]
        w = self.poly(pt["w"], path + ".w")
        if isinstance(pt["to"], dict):                       # a TIME object: T1 is rational (s8.4)
            raise Failed(path + ".to", "T1 must be a rational number (a string), not a TIME object")
        T1 = self.num(pt["to"], path + ".to")
        if cmp_time(ts, T1) >= 0:
            raise Failed(path + ".to", f"T1 = {T1} is not after t* = {ts}")
        if not T1 < tH:
            raise Failed(path + ".to", f"T1 = {T1} is not before tH = {tH}")
        ks = []
        for O in (A, B):
            k = O.motion.piece_at(ts, True)                   # the piece just after t*
            bps = O.motion.breakpoints
            if k < len(bps) and cmp_time(bps[k], T1) <= 0:
                where = "is T1" if bps[k] == T1 else f"lies between t* = {ts} and T1 = {T1}"
                raise Failed(path + ".to", f"a breakpoint of {O.name} at t = {bps[k]} {where}")
            ks.append(k)
        if not (p_eval(w, T1) > 0 and roots_between(w, ts, T1) == 0):   # W is needed on (t*, T1] only
            raise Failed(path + ".w", f"{fmt_poly(w)} is not > 0 on ({ts}, {T1}]")
        for O, k in zip((A, B), ks):
            f = O.turning_formula(k)
            signs = {}
            for key in sorted(literals_of(f, set())):
                L = p_add(p_sum(p_mul(list(key[i]), xyz[i]) for i in range(3)), p_mul(list(key[3]), w))
                s = signs[key] = sign(p_eval(L, T1))
                if s == 0:
                    raise Failed(path, f"the literal {fmt_lit(key)} of {O.name} is zero at W(T1), T1 = {T1}")
                if roots_between(L, ts, T1) > 0:
                    raise Failed(path, f"the literal {fmt_lit(key)} of {O.name} at W(t), {fmt_poly(L)}, "
                                       f"has a root in (t*, T1) = ({ts}, {T1})")
            if not strictly_true_by(f, signs.__getitem__):
                raise Failed(path, f"W(T1) at T1 = {T1} is not inside {O.name} with strict signs")
        wT = p_eval(w, T1)
        return tuple(p_eval(c, T1) / Fraction(wT) for c in xyz) + (T1,)

    def turning_witness(self, w, path, A, B):
        """s8.4: a rational point strictly inside both objects, at a time that is no breakpoint."""
        tL, tH = self.scene.time
        T = w[3]
        if not tL < T < tH:
            raise Failed(path + "[3]", f"t = {T} is not strictly inside ({tL}, {tH})")
        for O in (A, B):
            if O.motion.is_breakpoint(T):
                raise Failed(path + "[3]", f"t = {T} is a breakpoint of {O.name}")
            f = O.turning_formula(O.motion.piece_at(T, False))
            at_w = lambda k: sign(sum(p_eval(k[i], T) * w[i] for i in range(3)) + p_eval(k[3], T))
            if not strictly_true_by(f, at_w):
                raise Failed(path, f"{fmt_point(w)} is not inside {O.name} with strict signs")

    def turning_generic(self, c, w, path, O):
        """s8.4: w is a generic witness of c for O at time T: O's formula true at w with strict
        signs, and every literal zero at c or of the sign it has at w (signs exact at T)."""
        T = c[3]
        f = O.turning_formula(O.motion.piece_at(T, False))   # at a breakpoint either piece's
        signs = {}

        def at(point, k):
            key = (point is w, k)
            if key not in signs:
                signs[key] = sign_at(lit_value_poly(k, point), T)
            return signs[key]
        if not strictly_true_by(f, lambda k: at(w, k)):
            raise Failed(path, f"{fmt_point(w)} is not inside {O.name} with strict signs")
        for k in sorted(literals_of(f, set())):
            sc = at(c, k)
            if sc != 0 and sc != at(w, k):
                raise Failed(path, f"the literal {fmt_lit(k)} of {O.name} has sign {sc} at "
                                   f"{fmt_point(c)} and {at(w, k)} at the witness")

    def turning_apart(self, v, path, A, B):
        """s8.3: pieces covering [tL, until] between TIMEs, no breakpoint strictly inside one;
        or `members`: such pieces for each pair of a member of A and a member of B."""
        tL, tH = self.scene.time
        ap = self.keys(v, path, {"until"}, {"open_end", "pieces", "members"})
        until = self.time(ap["until"], path + ".until")
        open_end = self.boolean(ap.get("open_end", False), path + ".open_end")
        if cmp_time(until, tH) > 0:
            raise Failed(path + ".until", f"{until} is after tH = {tH}")
        if ("pieces" in ap) == ("members" in ap):
            raise Failed(path, "an APART holds one of pieces and members")
        if "pieces" in ap:
            self.turning_pieces(ap["pieces"], path + ".pieces", A, B, until, open_end, path + ".until", None)
            return until, open_end
        count = [len(members(O.turning_formula(0))) for O in (A, B)]
        seen = set()
        for e, entry in enumerate(self.array(ap["members"], path + ".members")):
            ep = f"{path}.members[{e}]"
            entry = self.keys(entry, ep, {"a", "b", "pieces"})
            ij = []
            for key, O, n in (("a", A, count[0]), ("b", B, count[1])):
                m = self.num(entry[key], f"{ep}.{key}")
                if not isinstance(m, int) or not 0 <= m < n:
                    raise Failed(f"{ep}.{key}", f"not a member of {O.name} (it has {n})")
                ij.append(m)
            if tuple(ij) in seen:
                raise Failed(ep, f"a second entry for members {ij[0]} and {ij[1]}")
            seen.add(tuple(ij))
            self.turning_pieces(entry["pieces"], ep + ".pieces", A, B, until, open_end, ep + ".pieces", tuple(ij))
        for i in range(count[0]):
            for j in range(count[1]):
                if (i, j) not in seen:
                    raise Failed(path + ".members", f"no entry for members {i} of {A.name} and {j} of {B.name}")
        return until, open_end

    def turning_pieces(self, pieces, path, A, B, until, open_end, end_path, member):
        """s8.3's pieces from tL to until; member: (i, j) of the members form, or None."""
        tL = self.scene.time[0]
        pieces = self.array(pieces, path)
        at = tL
        for i, pc in enumerate(pieces):
            pp = f"{path}[{i}]"
            pc = self.keys(pc, pp, {"t", "proof"})
            lo, hi = (self.time(x, f"{pp}.t[{j}]") for j, x in enumerate(self.array(pc["t"], pp + ".t", 2)))
            if cmp_time(lo, at) != 0:
                raise Failed(pp + ".t[0]", f"{lo} is not {at}" + (" (tL)" if i == 0 else " (the previous hi)"))
            if cmp_time(lo, hi) >= 0:
                raise Failed(pp + ".t[1]", f"lo = {lo} is not below hi = {hi}")
            ks = []
            for O in (A, B):
                k = O.motion.piece_at(lo, True)              # the piece just after lo
                bps = O.motion.breakpoints
                if k < len(bps) and cmp_time(bps[k], hi) < 0:
                    raise Failed(pp + ".t", f"a breakpoint of {O.name} at t = {bps[k]} lies inside")
                ks.append(k)
            open_last = open_end and i == len(pieces) - 1
            self.turning_leaf(pc["proof"], pp + ".proof", A, B, ks, lo, hi, open_last, member)
            at = hi
        if cmp_time(at, until) != 0:
            raise Failed(end_path, f"the pieces end at {at}, not at until = {until}")

    def conflict_of(self, cf, cp):
        """A CONFLICT's `of` (s3): closed semantics only, default "both"."""
        of = cf.get("of", "both")
        if not isinstance(of, str):
            self.bad(cp + ".of", "expected a string")
        if of not in ("both", "A", "B"):
            raise Failed(cp + ".of", "expected \"both\", \"A\" or \"B\"")
        return of if self.closed else "both"          # regularised ignores `of`

    def turning_leaf(self, v, path, A, B, ks, lo, hi, open_last, member=None):
        """s8.3: a leaf (split is an unknown key); every conflict's arithmetic, then every term
        closed off (s4's enumeration, without slab or path literals)."""
        node = self.keys(v, path, {"conflicts"})
        conflicts = []
        for j, cf in enumerate(self.array(node["conflicts"], path + ".conflicts")):
            cp = f"{path}.conflicts[{j}]"
            cf = self.keys(cf, cp, {"literals", "lambda"}, {"of"})
            of = self.conflict_of(cf, cp)
            raw_lits = self.array(cf["literals"], cp + ".literals")
            raw_lams = self.array(cf["lambda"], cp + ".lambda")
            if not raw_lits:
                raise Failed(cp + ".literals", "a conflict needs at least one literal")
            if len(raw_lams) != len(raw_lits):
                raise Failed(cp + ".lambda", f"{len(raw_lams)} multipliers for {len(raw_lits)} literals")
            lits = [self.lit(x, f"{cp}.literals[{i}]") for i, x in enumerate(raw_lits)]
            lams = [self.poly(x, f"{cp}.lambda[{i}]") for i, x in enumerate(raw_lams)]
            strict = not self.closed or of != "both"
            self.turning_conflict(cp, lits, lams, lo, hi, strict, open_last)
            conflicts.append((of, frozenset(lit_key(lit) for lit in lits)))
        fa, fb = A.turning_formula(ks[0]), B.turning_formula(ks[1])
        if member is not None:
            fa, fb = members(fa)[member[0]], members(fb)[member[1]]
        self.terms(path, fa, fb, [], [], conflicts)

    def turning_conflict(self, cp, lits, lams, lo, hi, strict, open_last):
        """s8.3's arithmetic of one conflict on the piece [lo, hi]."""
        for m, axis in enumerate("xyz"):                      # identity
            s = p_sum(p_mul(lam, lit[m]) for lam, lit in zip(lams, lits))
            if s:
                raise Failed(cp, f"sum lambda_i n_{axis},i = {fmt_poly(s)}, not the zero polynomial")
        for i, lam in enumerate(lams):                        # signs
            if not nonneg_on(lam, lo, hi):
                raise Failed(f"{cp}.lambda[{i}]", f"{fmt_poly(lam)} is not >= 0 on [{lo}, {hi}]")
        esum = p_sum(p_mul(lam, lit[3]) for lam, lit in zip(lams, lits))
        if strict:
            if not any(lams):
                raise Failed(cp + ".lambda", "every multiplier is the zero polynomial")
            if not nonneg_on(esum, lo, hi):
                raise Failed(cp, f"sum lambda_i e_i = {fmt_poly(esum)} is not >= 0 on [{lo}, {hi}]: "
                                 "the literals are not in conflict")
        elif not positive_on(esum, lo, hi, open_last):
            raise Failed(cp, f"sum lambda_i e_i = {fmt_poly(esum)} is not > 0 on [{lo}, {hi}"
                             + (")" if open_last else "]") + ": the literals are not in conflict")


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
