#!/usr/bin/env python3
"""clash4d from Python, step by step: each step prints what it runs and what
comes back, and checks the answer against the one derived by hand beside it.

    PYTHONPATH=build/python python3 examples/python/walkthrough.py [FIXTURES]

(or with clash4d installed: cmake --install, or pip install
--no-build-isolation .). FIXTURES defaults to the source tree's fixtures/.
Exits 1 when an answer is not the derived one.
"""
import pathlib
import sys
from fractions import Fraction

import clash4d

FIXTURES = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2] / "fixtures")
failures = 0


def step(title):
    print("\n## " + title)


def show(code, value):
    print(">>> " + code)
    print(repr(value))
    return value


def expect(ok, what):
    global failures
    print(("ok: " if ok else "FAILED: ") + what)
    failures += not ok


step("1. Read a scene file once (validated, reusable)")
head_on = show('scene = clash4d.Scene(FIXTURES / "contact" / "clear_collision_head_on.json")',
               clash4d.Scene(FIXTURES / "contact" / "clear_collision_head_on.json"))

step("2. Check it: the typed answer")
r = show("r = clash4d.check(scene, earliest=True)", clash4d.check(head_on, earliest=True))
show("r.t", r.t)
show("r.earliest", r.earliest)
show("r.earliest.x, r.earliest.t", (r.earliest.x, r.earliest.t))
# a's face x = 1 + t meets b's x = 5 - t when 1 + t = 5 - t: t* = 2, at x = 3.
expect(r.collide and r.objects == ("a", "b") and r.t == Fraction(2) and isinstance(r.t, Fraction)
       and r.earliest.x == 3, "t* = 2 exactly (a Fraction), at x = 3")

step("3. Decimals are exact: a face stopping exactly on another")
touch = FIXTURES / "contact" / "approach_stop_decimal.json"
scene = show("scene = clash4d.Scene(FIXTURES / \"contact\" / \"approach_stop_decimal.json\")", clash4d.Scene(touch))
regularised = show("clash4d.check(scene)", clash4d.check(scene))
closed = show('clash4d.check(scene, semantics="closed", earliest=True)',
              clash4d.check(scene, semantics="closed", earliest=True))
# b's face x = 0.1 + 0.1 t stops at t = 2 on exactly 0.3, a's face: they touch, never
# overlap (regularised: no collision; closed: first contact at t* = 2, x = 3/10).
expect(not regularised.collide and closed.t == 2 and closed.earliest.x == Fraction(3, 10),
       "regularised: no collision; closed: first contact at t* = 2, x = 3/10")
double = show('clash4d.check(scene, number="double", earliest=True)', clash4d.check(scene, number="double", earliest=True))
# In doubles 0.1 + 0.1 * 2 = 0.30000000000000004 > 0.3: a sliver of overlap, just before t = 2.
expect(double.collide and Fraction(19, 10) < double.t <= 2, "double: a false collision near t = 2 (rounding)")

step("4. Compare the subjects against exact")
c = show("c = clash4d.compare(scene, earliest=True)", clash4d.compare(scene, earliest=True))
print(">>> for row in c.subjects: print(row)")
for row in c.subjects:
    print(row)
show('c.row("exact closed").earliest', c.row("exact closed").earliest)
causes = {d.subject: d.cause for d in c.disagreements}
expect(not c.agree and causes.get("double") == "input rounding" and c.row("exact closed").earliest.t == 2,
       "double disagrees with exact, and the cause is the rounding of the input")

step("5. The same shapes under other motions (check and compare)")
moved = show('clash4d.check(head_on, earliest=True, motions=["rest", "vel -2 0 0"])',
             clash4d.check(head_on, earliest=True, motions=["rest", "vel -2 0 0"]))
# a at rest on x in [0, 1], b's face 5 - 2t reaches 1 at t* = 2, x = 1.
expect(moved.t == 2 and moved.earliest.x == 1, "a at rest, b at speed 2: t* = 2 at x = 1")
c = show('clash4d.compare(head_on, motions=["rest", "rest"])', clash4d.compare(head_on, motions=["rest", "rest"]))
expect(c.agree and not any(row.collide for row in c.subjects), "both at rest: no subject sees a collision")

step("6. A turning scene: t* is irrational, and exact")
turning = show('scene = clash4d.Scene(FIXTURES / "rotation" / "square_into_slab.json")',
               clash4d.Scene(FIXTURES / "rotation" / "square_into_slab.json"))
r = show("r = clash4d.check(scene, earliest=True)", clash4d.check(turning, earliest=True))
show("r.t.poly, r.t.between, float(r.t)", (r.t.poly, r.t.between, float(r.t)))
# rotation/expected.json: t* = (5 - sqrt 14) / 11, the root of 11t^2 - 10t + 1 in (1/10, 1/8).
expect(isinstance(r.t, clash4d.Algebraic) and r.t.poly == [1, -10, 11] and Fraction(1, 10) < r.t < Fraction(1, 8),
       "t* = (5 - sqrt 14) / 11, a clash4d.Algebraic")

print("\n" + ("FAILED: %d" % failures if failures else "every answer as derived"))
sys.exit(1 if failures else 0)
