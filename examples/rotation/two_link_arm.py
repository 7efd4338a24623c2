#!/usr/bin/env python3
"""A two-link arm described by poses sweeping into an obstacle, decided exactly.

Run (after building the Python module, target clash4d_python):
    PYTHONPATH=build/python python3 examples/rotation/two_link_arm.py

The arm lies in the plane z = 0. The upper arm is the block [0, 2] x
[-1/10, 1/10]^2 turning about the shoulder (the z axis) by q1; the forearm
is [0, 1] x [-1/10, 1/10]^2 in its own frame, hinged at the elbow, the
upper arm's point (2, 0, 0), and turned against the upper arm by q2. Its
pose in the world composes the two: rotation q1 * q2 (the Hamilton
product), origin R(q1) (2, 0, 0). Written out at each pose time:

    t   q1         q2         upper arm          forearm: rotate = q1 q2, translate = R(q1) (2, 0, 0)
    0   (1,0,0,0)  (1,0,0,0)  rotate (1,0,0,0)   rotate (1,0,0,0), translate (2, 0, 0)
    1   (1,0,0,1)  (1,0,0,0)  rotate (1,0,0,1)   rotate (1,0,0,1), translate (0, 2, 0)
    2   (1,0,0,1)  (1,0,0,1)  rotate (1,0,0,1)   rotate (0,0,0,2), translate (0, 2, 0)

((1,0,0,1) (1,0,0,1) = (1 - 1, 0, 0, 1 + 1) = (0, 0, 0, 2): a half turn.)
First the shoulder turns a quarter turn, the arm straight; then the elbow
turns a quarter turn, the upper arm still. The scene format interpolates
each link's pose linearly between poses: on [1, 2] this is the composed arm
exactly (q1 q2(s) = (1 - s, 0, 0, 1 + s), s = t - 1, is linear in t, and the
elbow stays at (0, 2, 0)); on [0, 1] the forearm's origin moves on the chord
from (2, 0, 0) to (0, 2, 0) rather than the elbow's arc (more poses would
follow the arc closer). The links meet at the elbow by construction, so
their pair is ignored.

The obstacle is the block [-2, -9/10] x [2, 3] x [-1, 1].

On [0, 1] every arm point has x >= 2 - 2t - 1/10 (forearm) or x >= -1/10
(upper arm): nothing reaches x = -9/10. On [1, 2] the forearm has turned
by psi against the upper arm, tan(psi / 2) = s, so it points along (-sin
psi, cos psi) from the elbow (0, 2); its leftmost point is the corner
(1, 1/10) of its own frame, at x = -(sin psi + cos psi / 10). This reaches
-9/10 when sin psi + cos psi / 10 = 9/10, with sin psi = 2s / (1 + s^2),
cos psi = (1 - s^2) / (1 + s^2):  5s^2 - 10s + 4 = 0, s = 1 - sqrt(5) / 5,
so t* = 2 - sqrt(5) / 5 ~ 1.5528, the root of 5t^2 - 20t + 19 in (3/2, 8/5).
There the corner is at y = 2 + cos psi - sin psi / 10 = 2 + sqrt(5) / 5
((sin + cos/10)^2 + (cos - sin/10)^2 = 101/100, so (cos - sin/10)^2 =
20/100), the same polynomial's other root, inside the obstacle's y range;
after t* the corner goes on into the obstacle. So both semantics answer:
forearm and obstacle, t* = 2 - sqrt(5) / 5 at x = -9/10, y = 2 + sqrt(5) / 5,
z in [-1/10, 1/10] (the forearm's corner edge).

Exits 1 when an answer is not the one derived above.
"""
import sys
from fractions import Fraction

import clash4d


def link(length):
    return {"block": {"min": [0, "-1/10", "-1/10"], "max": [length, "1/10", "1/10"]}}


def quaternion_product(p, q):
    """The Hamilton product p q, exactly (the rotation q, then p)."""
    pw, px, py, pz = p
    qw, qx, qy, qz = q
    return [pw * qw - px * qx - py * qy - pz * qz,
            pw * qx + px * qw + py * qz - pz * qy,
            pw * qy - px * qz + py * qw + pz * qx,
            pw * qz + px * qy - py * qx + pz * qw]


def rotated(q, v):
    """R(q) v for a quaternion q, not necessarily unit, exactly."""
    w, x, y, z = (Fraction(c) for c in q)
    n = w * w + x * x + y * y + z * z
    r = [[w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z]]
    return [sum(r[i][k] * v[k] for k in range(3)) / n for i in range(3)]


# (t, q1 shoulder, q2 elbow) at each pose time
JOINTS = [(0, [1, 0, 0, 0], [1, 0, 0, 0]),
          (1, [1, 0, 0, 1], [1, 0, 0, 0]),
          (2, [1, 0, 0, 1], [1, 0, 0, 1])]
ELBOW = [2, 0, 0]   # in the upper arm's frame

upper = {"poses": [{"t": t, "rotate": q1} for t, q1, _ in JOINTS]}
fore = {"poses": [{"t": t, "translate": rotated(q1, ELBOW), "rotate": quaternion_product(q1, q2)}
                  for t, q1, q2 in JOINTS]}
assert fore["poses"][2]["rotate"] == [0, 0, 0, 2] and fore["poses"][1]["translate"] == [0, 2, 0]

SCENE = {"format": "clash4d-scene/1", "name": "two-link arm", "time": [0, 2],
         "objects": [{"name": "upper", "shape": link(2), "motion": upper},
                     {"name": "fore", "shape": link(1), "motion": fore},
                     {"name": "obstacle", "shape": {"block": {"min": [-2, 2, -1], "max": ["-9/10", 3, 1]}}}],
         "ignore": [["upper", "fore"]]}

failures = 0


def expect(ok, what):
    global failures
    print(("  ok: " if ok else "  FAILED: ") + what)
    failures += not ok


for semantics in ("regularised", "closed"):
    r = clash4d.check(SCENE, semantics=semantics, earliest=True)
    e = r.earliest   # a clash4d.Point: x, y, z, t
    print(f"{semantics}: {'collision' if r.collide else 'no collision'}")
    if e:
        t, x, y, z = e.t, e.x, e.y, e.z
        print(f"  {r.objects[0]} and {r.objects[1]}: t* = {t}")   # its polynomial, interval and decimal
        print(f"  contact x = {x}, y = {y}, z = {z}")
    ok = (r.collide and e is not None and r.objects == ("fore", "obstacle")
          and isinstance(t, clash4d.Algebraic) and t.poly == [19, -20, 5] and Fraction(3, 2) < t < Fraction(8, 5)
          and x == Fraction(-9, 10)
          and isinstance(y, clash4d.Algebraic) and y.poly == [19, -20, 5] and y > Fraction(12, 5)
          and Fraction(-1, 10) <= z <= Fraction(1, 10))
    expect(ok, f"{semantics}: fore and obstacle at t* = 2 - sqrt(5)/5, (-9/10, 2 + sqrt(5)/5)")

print("FAILED" if failures else "all answers as derived")
sys.exit(1 if failures else 0)
