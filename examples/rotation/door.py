#!/usr/bin/env python3
"""A door on a hinge swinging shut against its stop, decided exactly.

Run (after building the Python module, target clash4d_python):
    PYTHONPATH=build/python python3 examples/rotation/door.py

The door is the thin block [0, 1] x [-1/10, 0] x [0, 2], hinged on the z
axis. Its motion is two poses: at t = 0 no rotation (the door open along
+x), at t = 1 the quaternion (1, 0, 0, 1), a quarter turn about z; between
them q(t) = (1, 0, 0, t), so the door is turned by the angle theta with
tan(theta / 2) = t:

    cos theta = (1 - t^2) / (1 + t^2),   sin theta = 2t / (1 + t^2),

theta = 90 degrees at t = 1 (the door shut along +y), where it then rests.
A door point (u, w) is at (u cos - w sin, u sin + w cos).

1. The stop is where the shut door lies: the block [-1/2, 0] x [1/2, 1] x
   [0, 2]. Door points have x = u cos - w sin >= 0 (u >= 0, w <= 0), and
   x = 0 before t = 1 only at the hinge (u = w = 0, y = 0, below the stop);
   at t = 1 the face w = 0 lies on x = 0 along the stop's face. The closed
   objects touch at t* = 1 and never share an interior point: no collision
   (regularised), first contact at t* = 1 (closed).

2. The stop set too far into the swing: the block [0, 1] x [9/10, 2] x
   [0, 2]. The door's highest point is its corner (u, w) = (1, 0), at y =
   sin theta, x = cos theta in [0, 1]; it reaches y = 9/10 when 2t / (1 +
   t^2) = 9/10, 9t^2 - 20t + 9 = 0, first at t* = (10 - sqrt 19) / 9 ~
   0.6268, then goes on into the stop: a collision in both semantics, t*
   irrational, at the corner edge x = cos theta = sqrt(19) / 10 (root of
   100x^2 - 19), y = 9/10, z in [0, 2].

Exits 1 when an answer is not the one derived above.
"""
import sys
from fractions import Fraction

import clash4d

DOOR = {"name": "door", "shape": {"block": {"min": [0, "-1/10", 0], "max": [1, 0, 2]}},
        "motion": {"poses": [{"t": 0}, {"t": 1, "rotate": [1, 0, 0, 1]}]}}


def door_scene(stop_min, stop_max):
    return {"format": "clash4d-scene/1", "name": "door", "time": [0, 2],
            "objects": [DOOR, {"name": "stop", "shape": {"block": {"min": stop_min, "max": stop_max}}}]}


def show(x):
    """An exact number and its decimal: a clash4d.Algebraic (an irrational
    root) prints its polynomial, interval and decimal; a Fraction, itself."""
    return str(x) if isinstance(x, clash4d.Algebraic) else f"{x} (= {float(x)!r})"


failures = 0


def expect(ok, what):
    global failures
    print(("  ok: " if ok else "  FAILED: ") + what)
    failures += not ok


print("1. the stop where the shut door lies")
shut = door_scene(["-1/2", "1/2", 0], [0, 1, 2])
r = clash4d.check(shut, earliest=True)
print(f"  regularised: {'collision' if r.collide else 'no collision'}")
expect(not r.collide, "regularised: no collision (the door only touches its stop)")
r = clash4d.check(shut, semantics="closed", earliest=True)
e = r.earliest   # a clash4d.Point: x, y, z, t
if e:
    print(f"  closed: first contact at t* = {show(e.t)}, x = {e.x}, y = {e.y}")
expect(r.collide and e is not None and e.t == 1 and e.x == 0 and Fraction(1, 2) <= e.y <= 1,
       "closed: first contact at t* = 1 on the stop's face x = 0")

print("2. the stop set too far into the swing")
early = door_scene([0, "9/10", 0], [1, 2, 2])
for semantics in ("regularised", "closed"):
    r = clash4d.check(early, semantics=semantics, earliest=True)
    e = r.earliest
    if e:
        x, y, z, t = e
        print(f"  {semantics}: t* = {show(t)}")
        print(f"    at x = {show(x)}, y = {y}, z = {z}")
    ok = (r.collide and e is not None and isinstance(e.t, clash4d.Algebraic) and e.t.poly == [9, -20, 9]
          and Fraction(6, 10) < e.t < Fraction(63, 100)
          and isinstance(x, clash4d.Algebraic) and x.poly == [-19, 0, 100] and x > 0
          and y == Fraction(9, 10) and 0 <= z <= 2)
    expect(ok, f"{semantics}: t* = (10 - sqrt 19) / 9 at x = sqrt(19) / 10, y = 9/10")

# The same question in plain doubles (the float subject a comparison holds
# against exact): a double t* within rounding of the exact one.
d = clash4d.check(early, number="double", earliest=True)
t = d.t
print(f"  number='double': t* = {float(t) if t is not None else None}")
expect(t is not None and abs(float(t) - 0.6267890062732585) < 1e-12, "double: t* within 1e-12 of (10 - sqrt 19) / 9")

print("FAILED" if failures else "all answers as derived")
sys.exit(1 if failures else 0)
