"""clash4d: exact collision detection for moving polyhedral CSG solids.

    import clash4d
    scene = {
        "format": "clash4d-scene/1", "time": [0, 10],
        "objects": [
            {"name": "a", "shape": {"block": {"min": [0, 0, 0], "max": [1, 1, 1]}}, "motion": "vel 1 0 0"},
            {"name": "b", "shape": {"block": {"min": [2, 0, 0], "max": [3, 1, 1]}}, "motion": "vel -1 0 0"},
        ],
    }
    r = clash4d.check(scene, earliest=True)
    r            # Answer(collide=True, objects=('a', 'b'), earliest=Point(x=3/2, y=..., z=..., t=1/2), ...)
    r.t          # Fraction(1, 2)
    r.earliest   # Point(x=Fraction(3, 2), y=..., z=..., t=Fraction(1, 2)): x, y, z, t by name

A scene is a dict in the scene format, the path of a scene file (str or
os.PathLike), or a clash4d.Scene (read once, prepared once, checked many
times). Numbers in a dict are read exactly: int, fractions.Fraction (any
numbers.Rational), str ("0.1", "-2.5e-3", "1/3": the scene format's forms),
and float or decimal.Decimal by their exact value (Fraction(0.1) is
3602879701896397/36028797018963968, not 1/10: write "0.1" or Fraction(1, 10)
for a tenth). Motions are strings ("vel 1 0 0", "rest until 0 vel 1/2 0 0
until 5 rest") or poses, which may turn the object (the scene format's
section "Motion with rotation", poses):

    {"poses": [{"t": 0}, {"t": 1, "translate": [0, 0, 1], "rotate": [1, 0, 0, 1]}]}

(rotate: a quaternion w, x, y, z, not necessarily unit; defaults translate
[0, 0, 0], rotate [1, 0, 0, 0]). Relative file paths inside a dict scene
(mesh solids) are relative to the current directory.

check returns a clash4d.Answer (collide, the reported Pair, every Pair
found), its points clash4d.Point (x, y, z, t by name), every exact number a
fractions.Fraction or, where it is irrational (with rotation: t*, a contact
point, a closed witness), a clash4d.Algebraic (exact: poly, between,
approx, float() and exact comparisons with Fraction). Nothing on the way
is a float. answer["collide"], answer["earliest"]["t"], ... (the dict form
of `clash4d check --json`, which check returned before the typed answers)
still work and give that dict's values; they are deprecated: use the
attributes.

compare(scene, ...) runs every subject (double, double with tolerances,
exact on the rounded scene, optionally fcl and bullet) against exact and
returns a clash4d.Comparison: agree, its rows (clash4d.Row, one per
subject: collide, agrees, cause, witness and earliest as clash4d.Located)
and its disagreements; comparison["agree"], ... (the dict of `clash4d
compare --json`) still work, deprecated. validate and the CCD queries
(ccd_vertex_face, ccd_edge_edge, ccd_batch) return dicts.

Invalid input raises clash4d.InputError (a ValueError) with the attributes
file, place (e.g. "objects[0].shape.block.min"), message and exit_code
(EXIT_INVALID = 2, EXIT_LIMIT = 3). check and compare take max_seconds (a
time limit: InputError at place "max_seconds", EXIT_LIMIT) and stop on
Ctrl-C (KeyboardInterrupt) within about 50 ms plus one step of the search.

The compiled part is clash4d._core (pybind11, on the public C++ API); this
file adds the typed answers and reprs.
"""
import dataclasses
import json
from fractions import Fraction
from typing import NamedTuple, Optional, Tuple, Union

from . import _core
from ._core import (EXIT_INVALID, EXIT_LIMIT, Algebraic, InputError, Scene, __version__, ccd_batch,
                    ccd_edge_edge, ccd_vertex_face, scene_json, validate)

__all__ = ["Answer", "Pair", "Point", "Comparison", "Row", "Located", "Disagreement", "Scene", "Algebraic",
           "InputError", "EXIT_INVALID", "EXIT_LIMIT", "check", "compare", "validate", "scene_json",
           "ccd_vertex_face", "ccd_edge_edge", "ccd_batch", "__version__"]

# The compiled classes under the package's name (reprs and help() say clash4d.X).
for _cls in (Scene, Algebraic):
    _cls.__module__ = __name__

Number = Union[Fraction, Algebraic]


def _text(x):
    """An exact number as short text: 3/2, -1, or an Algebraic's
    "root of 8x^2 - 1 in (0, 1) ~ 0.3535533905932738"."""
    return str(x)


class Point(NamedTuple):
    """A point of space-time: x, y, z at time t, each a Fraction or, where
    irrational, a clash4d.Algebraic. A tuple too: x, y, z, t = point."""
    x: Number
    y: Number
    z: Number
    t: Number

    def __repr__(self):
        return "Point(x=%s, y=%s, z=%s, t=%s)" % tuple(_text(c) for c in self)


def _point(coordinates, t=None):
    """A Point from the dict form's list: 4 coordinates, or 3 and the time t."""
    return Point(*coordinates) if t is None else Point(*coordinates, t)


def _inside(pair):
    return None if pair is None else (_point(pair[0]), _point(pair[1]))


class _DictForm:
    """The dict form an answer had before it was typed (deprecated, kept for
    code written against it): item access reads the dict self._dict."""

    def __getitem__(self, key):
        return self._dict[key]

    def __contains__(self, key):
        return key in self._dict

    def get(self, key, default=None):
        return self._dict.get(key, default)

    def keys(self):
        return self._dict.keys()


@dataclasses.dataclass(frozen=True)
class Pair:
    """A colliding pair of objects and what shows it.

    objects: (a, b), names in scene order. witness: a Point the two share
    (regularised: strictly inside both; closed: in both), verified: whether
    the witness was checked exactly. earliest (check(earliest=True)): the
    first collision (closed: first contact) as a Point, its t the time t*
    and x, y, z a contact point there; t is earliest.t. at_start: t* is the
    start of the time span (they collide from the start). witness_inside,
    earliest_inside: where given, a Point strictly inside each object near
    the witness or the contact (that makes the answer checkable); none with
    rotation."""
    objects: Tuple[str, str]
    witness: Point
    verified: bool
    earliest: Optional[Point] = None
    at_start: Optional[bool] = None
    witness_inside: Optional[Tuple[Point, Point]] = None
    earliest_inside: Optional[Tuple[Point, Point]] = None

    @property
    def t(self) -> Optional[Number]:
        """t*, the earliest collision time (None without earliest=True)."""
        return None if self.earliest is None else self.earliest.t

    @classmethod
    def _from(cls, witness, earliest):
        e = earliest or {}
        return cls(objects=tuple(witness["objects"]), witness=_point(witness["point"]),
                   verified=witness["verified"],
                   earliest=_point(e["point"], e["t"]) if earliest else None,
                   at_start=e.get("at_start"), witness_inside=_inside(witness.get("inside")),
                   earliest_inside=_inside(e.get("inside")))

    def __repr__(self):
        parts = ["objects=%r" % (self.objects,)]
        if self.earliest is not None:
            parts.append("earliest=%r" % (self.earliest,))
        parts.append("witness=%r" % (self.witness,))
        return "Pair(%s)" % ", ".join(parts)


@dataclasses.dataclass(frozen=True)
class Answer(_DictForm):
    """check's answer. collide: whether some pair collides. pair: the pair
    reported (the first found; with earliest=True the one with the smallest
    t*), None when nothing collides; pairs: every pair found (all of them
    with all_pairs=True, else the first). objects, witness, earliest and t
    are pair's. number, semantics: how it was decided.

    answer["collide"], answer["earliest"]["t"], ... give the values of the
    dict form check returned before (`clash4d check --json`'s; its points
    are lists, earliest's of 3 coordinates): deprecated, use the
    attributes."""
    collide: bool
    number: str
    semantics: str
    pair: Optional[Pair] = None
    pairs: Tuple[Pair, ...] = ()
    _dict: dict = dataclasses.field(default_factory=dict, compare=False, repr=False)

    @property
    def objects(self) -> Optional[Tuple[str, str]]:
        return None if self.pair is None else self.pair.objects

    @property
    def witness(self) -> Optional[Point]:
        return None if self.pair is None else self.pair.witness

    @property
    def earliest(self) -> Optional[Point]:
        return None if self.pair is None else self.pair.earliest

    @property
    def t(self) -> Optional[Number]:
        """t* of the reported pair (None when nothing collides or without earliest=True)."""
        return None if self.pair is None else self.pair.t

    @classmethod
    def _from(cls, d):
        pair = Pair._from(d["witness"], d.get("earliest")) if "witness" in d else None
        pairs = tuple(Pair._from(p["witness"], p.get("earliest")) for p in d["pairs"])
        return cls(collide=d["collide"], number=d["number"], semantics=d["semantics"], pair=pair, pairs=pairs,
                   _dict=d)

    def __repr__(self):
        parts = ["collide=%r" % self.collide]
        if self.pair is not None:
            parts.append("objects=%r" % (self.objects,))
            if self.earliest is not None:
                parts.append("earliest=%r" % (self.earliest,))
            parts.append("witness=%r" % (self.witness,))
            if len(self.pairs) > 1:
                parts.append("pairs=%d" % len(self.pairs))
        parts += ["number=%r" % self.number, "semantics=%r" % self.semantics]
        return "Answer(%s)" % ", ".join(parts)


def check(scene, number="exact", semantics="regularised", earliest=False, all_pairs=False, tolerance=0.0,
          motions=None, *, max_seconds=0.0):
    """Decides whether any pair of objects collides (`clash4d check`): a clash4d.Answer.

    number: "exact" (filtered exact, the default), "rational" (every sign in
    rationals) or "double" (plain doubles; its numbers are the exact values
    of the shortest decimals of the doubles). semantics: "regularised"
    (touching is not a collision) or "closed" (touching counts). earliest:
    also the earliest collision (closed: first contact), answer.earliest, a
    Point whose t is t* (answer.t). all_pairs: every colliding pair
    (answer.pairs), not only the first. tolerance: double only.

    motions: a motion per object, in scene order, in place of the scene's
    own (the same shapes moving otherwise): a ROBMOD string or a dict
    {"poses": [...]}; with a clash4d.Scene, exact keeps its preparation
    across such checks (not with poses). A bad motion raises
    clash4d.InputError at place "motions[i]" (or "motions[i].poses[j]...");
    a count that is not the scene's, ValueError.

    Scenes where some object turns (pose motions with rotation) are decided
    by time slices with number "exact" or "rational" (t* and points may be
    clash4d.Algebraic); number "double" raises clash4d.InputError
    (EXIT_INVALID) at the first turning object's motion, as does a
    degenerate case this release cannot decide (its message says "not
    decided: ..."); too large a system of polynomials, EXIT_LIMIT.

    max_seconds (keyword only): a time limit on the check, as `clash4d
    check --max-seconds` (0, the default: none; reading the scene is not
    counted): past it the check stops with no answer and raises
    clash4d.InputError with place "max_seconds" and exit_code EXIT_LIMIT.
    Negative or nan: ValueError. Ctrl-C (KeyboardInterrupt, or any exception
    a signal handler raises) stops the check and is raised."""
    return Answer._from(_core.check(scene, number, semantics, earliest, all_pairs, tolerance, motions,
                                    max_seconds=max_seconds))


def compare(scene, semantics="regularised", tolerances=(1e-9,), earliest=False, rounded=True, fcl=False,
            bullet=False, *, motions=None, max_seconds=0.0):
    """Runs every subject (double, double with each tolerance, exact on the
    rounded scene, optionally fcl and bullet) and holds each against the
    exact answer in its own semantics (`clash4d compare`).

    Returns a clash4d.Comparison (agree, closed_touch, subjects: a
    clash4d.Row each, disagreements). comparison["subjects"], ... give the
    dict of `clash4d compare --json` (deprecated).

    motions (keyword only): a motion per object in place of the scene's, as
    for check: every subject sees the moved scene. tolerances are the
    double subjects' (floats: a tolerance is a float parameter, not input
    geometry). max_seconds and Ctrl-C as for check."""
    return Comparison._from(_core.compare(scene, semantics, list(tolerances), earliest, rounded, fcl, bullet,
                                          motions=motions, max_seconds=max_seconds))


@dataclasses.dataclass(frozen=True)
class Located:
    """A witness or an earliest contact as a subject of compare gave it.
    point: a Point of Fractions, None where the subject gave none or a
    coordinate is irrational (a turning scene's exact answer); t (earliest
    only): t* as a Fraction when rational, else None. point_text, t_text:
    the exact text, always there when given: a rational ("3/10"), a double's
    decimal, or "root of [...] in (lo, hi) ~ approx" (never a rounded
    stand-in)."""
    objects: Tuple[str, str]
    point: Optional[Point] = None
    t: Optional[Fraction] = None
    point_text: Optional[Tuple[str, str, str, str]] = None
    t_text: Optional[str] = None

    @classmethod
    def _from(cls, d):
        if d is None:
            return None
        return cls(objects=tuple(d["objects"]), point=None if d["point"] is None else _point(d["point"]),
                   t=d.get("t"), point_text=d.get("point_text"), t_text=d.get("t_text"))

    def __repr__(self):
        parts = ["objects=%r" % (self.objects,)]
        if self.t_text is not None:
            parts.append("t=%s" % (self.t if self.t is not None else self.t_text))
        if self.point is not None:
            parts.append("point=%r" % (self.point,))
        elif self.point_text is not None:
            parts.append("point_text=%r" % (self.point_text,))
        return "Located(%s)" % ", ".join(parts)


@dataclasses.dataclass(frozen=True)
class Row:
    """One subject of compare held against exact. subject: "exact", "exact
    closed", "double", "double tol=1e-09", "exact-rounded", "fcl", ...;
    reference: the exact subject. collide, witness, earliest (Located):
    its answer (None when it did not answer: ok False with error, or
    skipped with why). witness_valid: the witness checked exactly. t_error:
    |t* - exact t*|, text. agrees, and cause where it does not
    ("arithmetic", "input rounding", "contact", "invalid witness")."""
    subject: str
    semantics: str
    collide: Optional[bool]
    agrees: Optional[bool]
    cause: Optional[str] = None
    witness: Optional[Located] = None
    witness_valid: Optional[bool] = None
    earliest: Optional[Located] = None
    t_error: Optional[str] = None
    tolerance: Optional[float] = None
    reference: bool = False
    ok: bool = True
    error: str = ""
    skipped: Optional[str] = None

    @classmethod
    def _from(cls, d):
        return cls(subject=d["subject"], semantics=d["semantics"], collide=d["collide"], agrees=d["agrees"],
                   cause=d["cause"], witness=Located._from(d["witness"]), witness_valid=d["witness_valid"],
                   earliest=Located._from(d["earliest"]), t_error=d["t_error"], tolerance=d["tolerance"],
                   reference=d["reference"], ok=d["ok"], error=d["error"], skipped=d["skipped"])

    def __repr__(self):
        parts = [repr(self.subject), "collide=%r" % self.collide, "agrees=%r" % self.agrees]
        if self.cause is not None:
            parts.append("cause=%r" % self.cause)
        if self.earliest is not None:
            parts.append("t=%s" % (self.earliest.t if self.earliest.t is not None else self.earliest.t_text))
        if self.skipped is not None:
            parts.append("skipped=%r" % self.skipped)
        if not self.ok:
            parts.append("error=%r" % self.error)
        return "Row(%s)" % ", ".join(parts)


@dataclasses.dataclass(frozen=True)
class Disagreement:
    subject: str
    cause: str
    detail: str
    semantics: str


@dataclasses.dataclass(frozen=True)
class Comparison(_DictForm):
    """compare's answer. agree: no subject disagrees with exact. subjects:
    a Row per subject, in order (row("double") finds one by name).
    disagreements: a Disagreement (subject, cause, detail, semantics) each.
    closed_touch: where exact (regularised) says no collision, whether the
    closed objects meet all the same. file, name: the scene's."""
    agree: bool
    subjects: Tuple[Row, ...]
    disagreements: Tuple[Disagreement, ...] = ()
    closed_touch: Optional[bool] = None
    file: str = ""
    name: str = ""
    _dict: dict = dataclasses.field(default_factory=dict, compare=False, repr=False)

    def row(self, subject):
        """The row of the subject of this name; KeyError naming the subjects there are."""
        for r in self.subjects:
            if r.subject == subject:
                return r
        raise KeyError("no subject %r (the subjects: %s)" % (subject, ", ".join(r.subject for r in self.subjects)))

    @classmethod
    def _from(cls, d):
        return cls(agree=d["agree"], subjects=tuple(Row._from(r) for r in d["subjects"]),
                   disagreements=tuple(Disagreement(**x) for x in d["disagreements"]),
                   closed_touch=d["closed_touch"], file=d["file"], name=d["name"], _dict=d)

    def __repr__(self):
        parts = ["agree=%r" % self.agree, "subjects=%r" % [r.subject for r in self.subjects]]
        if self.disagreements:
            parts.append("disagreements=[%s]" % ", ".join("%s: %s" % (x.subject, x.cause) for x in self.disagreements))
        if self.closed_touch is not None:
            parts.append("closed_touch=%r" % self.closed_touch)
        return "Comparison(%s)" % ", ".join(parts)


# ---------------------------------------------------------------- Scene's repr

def _is_zero(text):
    return Fraction(text) == 0   # the scene writer's exact strings ("0", "1/2", "-2.5e-3")


def _motion_kind(motion):
    """A short description of a scene-format motion: its ROBMOD text, or
    "poses (n)" with ", turning" when some pose rotates."""
    if motion is None:
        return "rest"
    if isinstance(motion, str):
        return motion if len(motion) <= 48 else motion[:45] + "..."
    poses = motion.get("poses", [])
    turning = any(not all(_is_zero(c) for c in p.get("rotate", [1, 0, 0, 0])[1:]) for p in poses)
    return "poses (%d%s)" % (len(poses), ", turning" if turning else "")


def _scene_repr(self):
    # From the scene's own JSON (every number an exact string; parse_* keep any
    # bare JSON number as text, never a float).
    d = json.loads(scene_json(self), parse_float=str, parse_int=str)
    objects = ["%s: %s" % (o["name"], _motion_kind(o.get("motion"))) for o in d["objects"]]
    if len(objects) > 8:
        objects = objects[:7] + ["... %d objects in all" % len(objects)]
    lo, hi = self.time
    head = "Scene(%r, " % self.name if self.name else "Scene("
    return "%stime=[%s, %s], objects=[%s])" % (head, lo, hi, ", ".join(objects))


Scene.__repr__ = _scene_repr
