"""Tests of the Python module clash4d (standard library unittest only).

Run by ctest as test_python, with PYTHONPATH holding the built module and
CLASH4D_FIXTURES the fixtures folder:
    PYTHONPATH=build/python CLASH4D_FIXTURES=fixtures python3 -m unittest -v test_clash4d
Every expected answer is derived by hand in the comment beside it.
"""
import copy
import dataclasses
import json
import os
import pathlib
import random
import signal
import sys
import threading
import time
import unittest
import unittest.mock
from decimal import Decimal
from fractions import Fraction

import clash4d

FIXTURES = pathlib.Path(os.environ.get("CLASH4D_FIXTURES", pathlib.Path(__file__).resolve().parents[2] / "fixtures"))


def block(lo, hi):
    return {"block": {"min": list(lo), "max": list(hi)}}


def scene(*objects, time=(0, 10)):
    return {"format": "clash4d-scene/1", "name": "test", "time": list(time), "objects": list(objects)}


def obj(name, shape, motion=None):
    o = {"name": name, "shape": shape}
    if motion is not None:
        o["motion"] = motion
    return o


# a = [t, 1 + t] and b = [2 - t, 3 - t] in x, y and z in [0, 1]: the gap of 1
# closes at relative speed 2, so t* = 1/2 at x = 3/2.
APPROACH = scene(obj("a", block((0, 0, 0), (1, 1, 1)), "vel 1 0 0"),
                 obj("b", block((2, 0, 0), (3, 1, 1)), "vel -1 0 0"))

# a moves by 1 between t = 0 and t = 1 and stops with its face x = 2 on b's.
TOUCH = scene(obj("a", block((0, 0, 0), (1, 1, 1)), "rest until 0 vel 1 0 0 until 1 rest"),
              obj("b", block((2, 0, 0), (3, 1, 1))))


class Check(unittest.TestCase):
    def test_approaching_blocks_earliest_half(self):
        r = clash4d.check(APPROACH, earliest=True)
        self.assertTrue(r["collide"])
        self.assertEqual(r["number"], "exact")
        self.assertEqual(r["semantics"], "regularised")
        self.assertEqual(r["earliest"]["objects"], ("a", "b"))
        self.assertEqual(r["earliest"]["t"], Fraction(1, 2))
        self.assertIsInstance(r["earliest"]["t"], Fraction)
        x, y, z = r["earliest"]["point"]
        self.assertEqual(x, Fraction(3, 2))
        self.assertTrue(0 <= y <= 1 and 0 <= z <= 1)
        self.assertFalse(r["earliest"]["at_start"])

    def test_witness_strictly_inside_both(self):
        r = clash4d.check(APPROACH)
        w = r["witness"]
        self.assertEqual(w["objects"], ("a", "b"))
        self.assertTrue(w["verified"])
        x, y, z, t = w["point"]
        self.assertTrue(all(isinstance(c, Fraction) for c in w["point"]))
        self.assertTrue(Fraction(1, 2) < t < 10)
        self.assertTrue(t < x < 1 + t and 2 - t < x < 3 - t)   # inside a and b at time t
        self.assertTrue(0 < y < 1 and 0 < z < 1)
        self.assertNotIn("earliest", r)

    def test_every_number_type_gives_half(self):
        for number in ("exact", "rational", "double"):
            with self.subTest(number=number):
                r = clash4d.check(APPROACH, number=number, earliest=True)
                self.assertTrue(r["collide"])
                self.assertEqual(r["number"], number)
                self.assertEqual(r["earliest"]["t"], Fraction(1, 2))

    def test_touching_regularised_no_closed_yes(self):
        self.assertFalse(clash4d.check(TOUCH)["collide"])
        self.assertNotIn("witness", clash4d.check(TOUCH))
        r = clash4d.check(TOUCH, semantics="closed", earliest=True)
        self.assertTrue(r["collide"])
        self.assertEqual(r["semantics"], "closed")
        self.assertEqual(r["earliest"]["t"], 1)   # first contact when a stops
        self.assertEqual(r["earliest"]["point"][0], 2)
        self.assertEqual(r["witness"]["point"][0], 2)   # a common point is on the face x = 2
        self.assertEqual(len(r["witness"]["inside"]), 2)

    def test_all_pairs(self):
        # a/b as in APPROACH (t* = 1/2); c and e, far away at rest, overlap in
        # x in [21/2, 11] from the start (t* = 0); a/c, b/e ... never meet.
        s = scene(obj("a", block((0, 0, 0), (1, 1, 1)), "vel 1 0 0"),
                  obj("b", block((2, 0, 0), (3, 1, 1)), "vel -1 0 0"),
                  obj("c", block((10, 10, 10), (11, 11, 11))),
                  obj("e", block(("10.5", 10, 10), (12, 11, 11))))
        r = clash4d.check(s, all_pairs=True, earliest=True)
        self.assertEqual([p["objects"] for p in r["pairs"]], [("a", "b"), ("c", "e")])
        # The typed form: Pairs with their t*, the reported pair the smallest t*.
        self.assertEqual([(p.objects, p.t) for p in r.pairs], [(("a", "b"), Fraction(1, 2)), (("c", "e"), 0)])
        self.assertEqual(r.objects, ("c", "e"))
        self.assertEqual([p["earliest"]["t"] for p in r["pairs"]], [Fraction(1, 2), 0])
        self.assertEqual(r["earliest"]["objects"], ("c", "e"))   # the smallest t*
        self.assertTrue(r["pairs"][1]["earliest"]["at_start"])
        self.assertEqual(len(clash4d.check(s)["pairs"]), 1)   # stops at the first

    def test_exact_numbers_in(self):
        # b's face at x = 2 - t reaches a's x = 1 + t at t = 1/2 for every way
        # of writing 2; the gap of 1/3 + 2/3 is exact only as rationals.
        for two in (2, Fraction(2), "2", "2/1", "2.0", 2.0, Decimal("2.00"), "0.2e1"):
            with self.subTest(two=two):
                s = scene(obj("a", block((0, 0, 0), (1, 1, 1)), "vel 1 0 0"),
                          obj("b", block((two, 0, 0), (3, 1, 1)), "vel -1 0 0"))
                self.assertEqual(clash4d.check(s, earliest=True)["earliest"]["t"], Fraction(1, 2))
        # a float is its exact binary value: 0.1 is not 1/10.
        s = scene(obj("a", block((0, 0, 0), (0.1, 1, 1))), obj("b", block((Fraction(1, 10), 0, 0), (1, 1, 1))))
        self.assertTrue(clash4d.check(s)["collide"])          # 0.1 > 1/10: a sliver of overlap
        s["objects"][0]["shape"]["block"]["max"][0] = "0.1"
        self.assertFalse(clash4d.check(s)["collide"])         # exactly 1/10: touching

    def test_fraction_motion(self):
        # b approaches at 1/3 from a gap of 1: t* = 3.
        s = scene(obj("a", block((0, 0, 0), (1, 1, 1))),
                  obj("b", block((2, 0, 0), (3, 1, 1)), f"vel {Fraction(-1, 3)} 0 0"))
        self.assertEqual(clash4d.check(s, earliest=True)["earliest"]["t"], 3)

    def test_prepared_scene_under_other_motions(self):
        s = clash4d.Scene(APPROACH)
        self.assertEqual(s.objects, ["a", "b"])
        self.assertEqual(s.time, (0, 10))
        # a at rest on [0, 1], b at -2 from [2, 3]: b's face 2 - 2t reaches 1 at t* = 1/2, x = 1.
        for number in ("exact", "rational", "double"):
            r = clash4d.check(s, number=number, earliest=True, motions=["rest", "vel -2 0 0"])
            self.assertEqual((r["earliest"]["t"], r["earliest"]["point"][0]), (Fraction(1, 2), 1), number)
        # Both at rest, a gap of 1: never; touching only when b covers the gap and stops (closed: t = 1).
        self.assertFalse(clash4d.check(s, motions=["rest", "rest"])["collide"])
        stop = ["rest", "vel -1 0 0 until 1 rest"]
        self.assertFalse(clash4d.check(s, motions=stop)["collide"])
        self.assertEqual(clash4d.check(s, semantics="closed", earliest=True, motions=stop)["earliest"]["t"], 1)
        # The scene's own motions again: t* = 1/2 at x = 3/2; a dict scene takes motions too.
        self.assertEqual(clash4d.check(s, earliest=True)["earliest"]["point"][0], Fraction(3, 2))
        self.assertEqual(clash4d.check(APPROACH, earliest=True, motions=["rest", "vel -2 0 0"])["earliest"]["t"],
                         Fraction(1, 2))

    def test_bad_motions(self):
        s = clash4d.Scene(APPROACH)
        for run in (clash4d.check, clash4d.compare):   # compare reads motions as check does
            with self.assertRaises(clash4d.InputError) as e:
                run(s, motions=["rest", "vel 1 0"])
            self.assertEqual(e.exception.place, "motions[1]")
            with self.assertRaises(ValueError):
                run(s, motions=["rest"])
        with self.assertRaises(TypeError):
            clash4d.compare(s, motions="rest")
        with self.assertRaises(clash4d.InputError):
            clash4d.Scene({"format": "clash4d-scene/1"})

    def test_path_fixture(self):
        head_on = FIXTURES / "contact" / "clear_collision_head_on.json"   # meeting at t = 2
        for path in (head_on, str(head_on)):
            r = clash4d.check(path, earliest=True)
            self.assertTrue(r["collide"])
            self.assertEqual(r["earliest"]["t"], 2)
        touch = FIXTURES / "contact" / "face_touch_static.json"
        self.assertFalse(clash4d.check(touch)["collide"])
        self.assertEqual(clash4d.check(touch, semantics="closed", earliest=True)["earliest"]["t"], 0)

    def test_bad_options(self):
        with self.assertRaises(ValueError):
            clash4d.check(APPROACH, number="float")
        with self.assertRaises(ValueError):
            clash4d.check(APPROACH, semantics="open")
        with self.assertRaises(TypeError):
            clash4d.check(42)


class Errors(unittest.TestCase):
    def test_bad_scene_names_the_place(self):
        s = scene(obj("a", {"block": {"min": [0, 0], "max": [1, 1, 1]}}), obj("b", block((2, 0, 0), (3, 1, 1))))
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.check(s)
        e = c.exception
        self.assertIsInstance(e, ValueError)
        self.assertEqual(e.place, "objects[0].shape.block.min")
        self.assertIn("objects[0].shape.block.min", str(e))
        self.assertEqual(e.file, "<scene>")
        self.assertEqual(e.exit_code, clash4d.EXIT_INVALID)
        self.assertTrue(e.message)

    def test_mesh_files_only_under_the_scene_folder(self):
        # docs/meshes.md: a dict's meshes are relative to the current
        # directory and must be under it, or under an allowed folder.
        meshes = FIXTURES / "meshes"
        s = scene(obj("a", {"mesh": str(meshes / "cube.off")}), obj("b", block((5, 5, 5), (6, 6, 6))))
        old = os.getcwd()
        try:
            os.chdir(FIXTURES / "paper")
            with self.assertRaises(clash4d.InputError) as c:
                clash4d.Scene(s)
            self.assertEqual(c.exception.place, "objects[0].shape.mesh")
            self.assertIn("outside the scene's folder", str(c.exception))
            self.assertFalse(clash4d.check(clash4d.Scene(s, allow_mesh_path=[str(meshes)]))["collide"])
            os.chdir(meshes)
            self.assertFalse(clash4d.check(s)["collide"])
        finally:
            os.chdir(old)

    def test_bad_fixture_file(self):
        path = FIXTURES / "bad" / "block_min_two_numbers.json"
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.validate(path)
        self.assertEqual(c.exception.file, str(path))
        self.assertEqual(c.exception.place, "objects[0].shape.block.min")
        self.assertTrue(str(c.exception).startswith(str(path) + ": objects[0].shape.block.min: "))

    def test_limit(self):
        path = FIXTURES / "bad" / "huge_exponent_number.json"   # a named limit: exit 3
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.check(path)
        self.assertEqual(c.exception.exit_code, clash4d.EXIT_LIMIT)

    def test_missing_file(self):
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.check("/nonexistent/scene.json")
        self.assertEqual(c.exception.exit_code, clash4d.EXIT_INVALID)

    def test_not_finite_and_not_json(self):
        s = scene(obj("a", block((0, 0, 0), (float("inf"), 1, 1))), obj("b", block((2, 0, 0), (3, 1, 1))))
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.check(s)
        self.assertEqual(c.exception.place, "objects[0].shape.block.max[0]")
        s = scene(obj("a", block((0, 0, 0), (1, 1, 1))), obj("b", {"block": object()}))
        with self.assertRaises(clash4d.InputError):
            clash4d.check(s)


class Validate_and_compare(unittest.TestCase):
    def test_validate(self):
        v = clash4d.validate(APPROACH)
        self.assertEqual(v["objects"], ["a", "b"])
        self.assertEqual(v["time"], (0, 10))
        self.assertIn('"1/2"', clash4d.scene_json(scene(obj("a", block((0, 0, 0), (Fraction(1, 2), 1, 1))),
                                                       obj("b", block((2, 0, 0), (3, 1, 1))))))

    def test_compare_agrees(self):
        c = clash4d.compare(APPROACH, earliest=True)
        self.assertTrue(c["agree"])
        self.assertEqual(c["disagreements"], [])
        rows = {r["subject"]: r for r in c["subjects"]}
        self.assertTrue(rows["exact"]["reference"])
        self.assertTrue(rows["exact"]["collide"])
        self.assertEqual(rows["exact"]["earliest"]["t"], Fraction(1, 2))
        self.assertTrue(rows["double"]["agrees"])

    def test_compare_contact_cause(self):
        # Touching: exact says no; a float subject with a tolerance that
        # counts the touching as overlap is not asked for here, so everyone
        # agrees, and closed_touch records that the closed objects meet.
        c = clash4d.compare(TOUCH)
        self.assertEqual(c["closed_touch"], True)
        rows = {r["subject"]: r for r in c["subjects"]}
        self.assertFalse(rows["exact"]["collide"])
        self.assertTrue(rows["exact closed"]["collide"])


# CCD queries (docs/ccd-queries.md): four vertices moving linearly over t in [0, 1].
F = Fraction
TRIANGLE = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]   # at rest in z = 0
# p = (1/4, 1/4, 1 - 2t) crosses z = 0 at t = 1/2, inside the triangle at (u, v) = (1/4, 1/4).
VF_HALF = ([[F(1, 4), F(1, 4), 1]] + TRIANGLE, [["1/4", "0.25", -1]] + TRIANGLE)
# a = (0,0,0), b = (1,0,0) at rest, c = (0, 1, 2t - 1); p = (1/8, t, 1/4 - t). The
# triangle's points (u, v, v (2t - 1)) meet p at u = 1/8, v = t and t (2t - 1) = 1/4 - t,
# that is 8t^2 = 1: t* = 1/(2 sqrt 2) ~ 0.35355 (the normal (0, 1 - 2t, 1) . p = 1/4 - 2t^2
# vanishes nowhere else in [0, 1]).
VF_ROOT = ([[F(1, 8), 0, F(1, 4)], [0, 0, 0], [1, 0, 0], [0, 1, -1]],
           [[F(1, 8), 1, F(-3, 4)], [0, 0, 0], [1, 0, 0], [0, 1, 1]])
# a0 = 0, a1 = (1, t, 0); b0 = (1/2, -1, -1/4 - t), b1 = (1/2, 1, -1/4 + t). The four are
# coplanar when det(a1, b0, b1) = 1/2 - t^2 = 0: t* = 1/sqrt 2. There a0 + u (a1 - a0) =
# b0 + v (b1 - b0) gives u = 1/2 (x), v = 1/2 + t/4 (y) and z: -1/4 + t^2/2 = 0. v is the
# root of 32v^2 - 32v + 7 (t = 4v - 2 in 2t^2 - 1) ~ 0.6768.
EE_ROOT = ([[0, 0, 0], [1, 0, 0], [F(1, 2), -1, F(-1, 4)], [F(1, 2), 1, F(-1, 4)]],
           [[0, 0, 0], [1, 1, 0], [F(1, 2), -1, F(-5, 4)], [F(1, 2), 1, F(3, 4)]])


class Ccd(unittest.TestCase):
    def test_vertex_face_rational(self):
        r = clash4d.ccd_vertex_face(*VF_HALF)
        self.assertEqual(r, {"collide": True, "t": F(1, 2), "uv": (F(1, 4), F(1, 4))})
        self.assertIsInstance(r["t"], Fraction)
        for number in ("rational", "double"):
            self.assertEqual(clash4d.ccd_vertex_face(*VF_HALF, number=number), r, number)
        self.assertEqual(clash4d.ccd_vertex_face(*VF_HALF, earliest=False), {"collide": True})
        # p at (2, 2) passes beside the triangle.
        miss = ([[2, 2, 1]] + TRIANGLE, [[2, 2, -1]] + TRIANGLE)
        self.assertEqual(clash4d.ccd_vertex_face(*miss), {"collide": False, "t": None})
        # Touching counts: p comes down to z = 0 at t = 1 and stops there.
        touch = ([[F(1, 4), F(1, 4), 1]] + TRIANGLE, [[F(1, 4), F(1, 4), 0]] + TRIANGLE)
        self.assertEqual(clash4d.ccd_vertex_face(*touch)["t"], 1)

    def test_vertex_face_irrational(self):
        r = clash4d.ccd_vertex_face(*VF_ROOT)
        self.assertTrue(r["collide"])
        t = r["t"]
        u, v = r["uv"]
        self.assertIsInstance(t, clash4d.Algebraic)
        self.assertEqual(t.poly, [-1, 0, 8])
        self.assertTrue(all(type(c) is int for c in t.poly))
        self.assertEqual(t.between, (0, 1))   # the coarsest [n/10^k, (n+1)/10^k] without the root -t*
        self.assertEqual(t.approx, "0.3535533905932738")
        self.assertTrue(F(35, 100) < t < F(36, 100))
        self.assertTrue(F(35, 100) <= t <= F(36, 100) and t > F(35, 100) and t >= F(35, 100))
        self.assertTrue(0 < t < 1 and 0.35 < t < 0.36)
        self.assertNotEqual(t, F(35355339, 10 ** 8))
        self.assertFalse(t == F(35355339, 10 ** 8))
        self.assertAlmostEqual(float(t), 0.35355339059327373, places=15)
        self.assertEqual(repr(t), "Algebraic(root of 8x^2 - 1 in (0, 1) ~ 0.3535533905932738)")
        self.assertEqual(str(t), "root of 8x^2 - 1 in (0, 1) ~ 0.3535533905932738")
        self.assertEqual(u, F(1, 8))
        self.assertIsInstance(u, Fraction)
        self.assertIsInstance(v, clash4d.Algebraic)
        self.assertTrue(v == t and not v != t and v <= t and hash(v) == hash(t))   # v = t*
        self.assertEqual(len({t, v}), 1)
        # The reference gives the same numbers; double gives decimals near them.
        self.assertEqual(clash4d.ccd_vertex_face(*VF_ROOT, number="rational"), r)
        d = clash4d.ccd_vertex_face(*VF_ROOT, number="double")
        self.assertIsInstance(d["t"], Fraction)
        self.assertAlmostEqual(float(d["t"]), 0.35355339, places=7)

    def test_edge_edge_irrational(self):
        r = clash4d.ccd_edge_edge(*EE_ROOT)
        self.assertTrue(r["collide"])
        t = r["t"]
        u, v = r["uv"]
        self.assertEqual(t.poly, [-1, 0, 2])   # 1/sqrt 2
        self.assertTrue(F(707, 1000) < t < F(708, 1000))
        self.assertEqual(u, F(1, 2))
        self.assertEqual(v.poly, [7, -32, 32])
        self.assertTrue(F(676, 1000) < v < F(677, 1000))
        self.assertAlmostEqual(float(v), 0.5 + float(t) / 4, places=15)
        # [0, 1] also holds the other root 1/2 - t*/4 ~ 0.32: between is [6/10, 7/10].
        self.assertEqual(repr(v), "Algebraic(root of 32x^2 - 32x + 7 in (3/5, 7/10) ~ 0.6767766952966369)")
        # Comparisons between algebraic numbers: vertex-face's 1/(2 sqrt 2) is half of 1/sqrt 2.
        vf_t = clash4d.ccd_vertex_face(*VF_ROOT)["t"]
        self.assertTrue(vf_t < t and t > vf_t and vf_t != t and not vf_t == t)
        self.assertTrue(v < t and v <= t and t >= v and v != t)   # 0.6768 < 0.7071
        # Not numbers: no order, and never equal.
        self.assertFalse(t == "0.7")
        with self.assertRaises(TypeError):
            t < "0.7"
        self.assertFalse(t == float("nan") or t < float("nan"))
        self.assertTrue(t < float("inf") and t > float("-inf"))

    def test_batch_keeps_order(self):
        def falling(z1):   # p = (1/4, 1/4, 1 + (z1 - 1) t) meets z = 0 at t = 1 / (1 - z1)
            return ([[F(1, 4), F(1, 4), 1]] + TRIANGLE, [[F(1, 4), F(1, 4), z1]] + TRIANGLE)
        queries = [falling(-1), VF_ROOT, falling(-3), ([[2, 2, 1]] + TRIANGLE, [[2, 2, -1]] + TRIANGLE),
                   {"t0": falling(0)[0], "t1": falling(0)[1], "type": "vertex-face", "label": 1}]
        rs = clash4d.ccd_batch(queries)
        self.assertEqual([r["collide"] for r in rs], [True, True, True, False, True])
        self.assertEqual(rs[0]["t"], F(1, 2))
        self.assertEqual(rs[1]["t"].poly, [-1, 0, 8])
        self.assertEqual(rs[2]["t"], F(1, 4))
        self.assertIsNone(rs[3]["t"])
        self.assertEqual(rs[4]["t"], 1)
        self.assertEqual(rs[2]["uv"], (F(1, 4), F(1, 4)))
        self.assertEqual(clash4d.ccd_batch(queries, "vf", number="double")[2]["t"], F(1, 4))
        self.assertEqual([r["collide"] for r in clash4d.ccd_batch(queries, earliest=False)],
                         [True, True, True, False, True])
        ee = clash4d.ccd_batch(iter([EE_ROOT, EE_ROOT]), type="edge-edge")
        self.assertEqual([r["uv"][0] for r in ee], [F(1, 2), F(1, 2)])
        self.assertEqual(clash4d.ccd_batch([]), [])
        # Many at once, in parallel: each answer is its own query's.
        many = [falling(-k) for k in range(1, 60)]
        self.assertEqual([r["t"] for r in clash4d.ccd_batch(many)], [F(1, 1 + k) for k in range(1, 60)])

    def test_bad_input(self):
        p0, p1 = VF_HALF
        with self.assertRaises(clash4d.InputError) as c:   # a point of 2 numbers
            clash4d.ccd_vertex_face([[0, 0]] + TRIANGLE, p1)
        self.assertEqual((c.exception.file, c.exception.place), ("<query>", "t0[0]"))
        self.assertEqual(c.exception.exit_code, clash4d.EXIT_INVALID)
        with self.assertRaises(clash4d.InputError) as c:   # not a number
            clash4d.ccd_vertex_face(p0, [[0, 0, "abc"]] + TRIANGLE)
        self.assertEqual(c.exception.place, "t1[0][2]")
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.ccd_edge_edge(p0, p1[:3])   # 3 points
        self.assertEqual(c.exception.place, "t1")
        for bad in (None, True, float("nan"), [1]):
            with self.assertRaises(clash4d.InputError):
                clash4d.ccd_vertex_face(p0, [[0, 0, bad]] + TRIANGLE)
        with self.assertRaises(clash4d.InputError) as c:   # beyond double's range, for double only
            clash4d.ccd_vertex_face(p0, [[0, "1e400", 0]] + TRIANGLE, number="double")
        self.assertEqual(c.exception.place, "t1[0][1]")
        # Exact reads it: p = ((1 - t)/4, 10^400 t, 1 - t) reaches z = 0 only at t = 1, far away.
        self.assertFalse(clash4d.ccd_vertex_face(p0, [[0, "1e400", 0]] + TRIANGLE)["collide"])
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.ccd_batch([VF_HALF, (p0, [[0, 0]] + TRIANGLE)])
        self.assertEqual(c.exception.place, "queries[1].t1[0]")
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.ccd_batch([VF_HALF, {"t0": p0, "t1": p1, "type": "edge-edge"}])
        self.assertEqual(c.exception.place, "queries[1].type")
        with self.assertRaises(clash4d.InputError):
            clash4d.ccd_batch([{"t0": p0, "t2": p1}])
        with self.assertRaises(clash4d.InputError):
            clash4d.ccd_batch([VF_HALF[0]])   # not (t0, t1)
        with self.assertRaises(ValueError):
            clash4d.ccd_batch([VF_HALF], type="face-face")
        with self.assertRaises(ValueError):
            clash4d.ccd_vertex_face(*VF_HALF, number="float")
        with self.assertRaises(ValueError):
            clash4d.ccd_vertex_face(*VF_HALF, tolerance=1e-9)   # double only
        with self.assertRaises(ValueError):
            clash4d.ccd_vertex_face(*VF_HALF, separation=-1)
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.ccd_vertex_face(*VF_HALF, separation="x")
        self.assertEqual(c.exception.place, "separation")
        with self.assertRaises(TypeError):
            clash4d.Algebraic()

    def test_separation(self):
        # p = (1/4, 1/4, 1 - 2t) is at distance |1 - 2t| from the triangle (it projects
        # inside it): within D = 1/2 from t* = 1/4, the closest point at (u, v) = (1/4, 1/4).
        r = clash4d.ccd_vertex_face(*VF_HALF, separation=F(1, 2))
        self.assertEqual(r, {"collide": True, "t": F(1, 4), "uv": (F(1, 4), F(1, 4))})
        for number in ("rational", "double"):
            self.assertEqual(clash4d.ccd_vertex_face(*VF_HALF, separation="0.5", number=number), r, number)
        self.assertEqual(clash4d.ccd_batch([VF_HALF], separation=0.5), [r])
        self.assertEqual(clash4d.ccd_vertex_face(*VF_HALF, separation=0), clash4d.ccd_vertex_face(*VF_HALF))
        # p beside the triangle at (2, 2): its closest point is (1/2, 1/2, 0) on the edge
        # b c, at distance 3/sqrt 2 ~ 2.12 at t = 1/2 (more at other times).
        miss = ([[2, 2, 1]] + TRIANGLE, [[2, 2, -1]] + TRIANGLE)
        self.assertFalse(clash4d.ccd_vertex_face(*miss, separation=2)["collide"])
        self.assertTrue(clash4d.ccd_vertex_face(*miss, separation=3)["collide"])


def valid_scene():
    return copy.deepcopy(APPROACH)


def nested(depth, leaf=0):
    """depth lists, one in another, around leaf: [[...[leaf]...]]."""
    v = leaf
    for _ in range(depth):
        v = [v]
    return v


class Hostile_dicts(unittest.TestCase):
    """A dict scene is refused with clash4d.InputError at the place of the
    fault, whatever it holds; never a crash (issue 59, item 1)."""

    def refused(self, s, exit_code=clash4d.EXIT_INVALID):
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.validate(s)
        self.assertEqual(c.exception.exit_code, exit_code, str(c.exception))
        return c.exception

    def test_a_list_that_contains_itself(self):
        s = valid_scene()
        loop = [1]
        loop.append(loop)
        s["meta"] = {"notes": loop}
        e = self.refused(s)
        self.assertEqual(e.place, "meta.notes[1]")
        self.assertIn("cycle", e.message)
        self.assertIn("also at meta.notes", e.message)
        s = valid_scene()
        s["objects"][1]["shape"] = {"union": [block((0, 0, 0), (1, 1, 1)), s["objects"]]}
        self.assertEqual(self.refused(s).place, "objects[1].shape.union[1]")

    def test_a_dict_that_contains_itself(self):
        s = valid_scene()
        s["meta"] = s
        e = self.refused(s)
        self.assertEqual(e.place, "meta")
        self.assertIn("cycle", e.message)
        # the same list twice, side by side, is not a cycle
        shared = [1, 2]
        s = valid_scene()
        s["meta"] = [shared, shared]
        clash4d.validate(s)

    def test_deep_nesting_is_the_readers_limit(self):
        limit = 256   # scene/Json_reader.h, CLASH4D_MAX_JSON_DEPTH: the scene is level 1
        for depth in (30000, 10000, limit):
            s = valid_scene()
            s["meta"] = nested(depth)
            e = self.refused(s, clash4d.EXIT_LIMIT)
            self.assertIn("nesting deeper than the limit of 256 levels", e.message)
            self.assertTrue(e.place.startswith("meta[0]"), e.place)
        # 255 lists in meta: the scene is level 1, the deepest list level 256,
        # the most both this writer and the scene reader take
        s = valid_scene()
        s["meta"] = nested(limit - 1)
        clash4d.validate(s)

    def test_huge_integers(self):
        for n in (10 ** 100000, -(10 ** 5000), Fraction(1, 10 ** 2000)):
            s = scene(obj("a", block((0, 0, 0), (n, 1, 1))), obj("b", block((2, 0, 0), (3, 1, 1))))
            e = self.refused(s, clash4d.EXIT_LIMIT)
            self.assertEqual(e.place, "objects[0].shape.block.max[0]")
            self.assertIn("limit of 1000 characters", e.message)
        # Python's own limit on writing an int in decimal, lowered: refused as a limit
        if hasattr(sys, "set_int_max_str_digits"):
            old = sys.get_int_max_str_digits()
            sys.set_int_max_str_digits(640)
            try:
                s = scene(obj("a", block((0, 0, 0), (10 ** 700, 1, 1))), obj("b", block((2, 0, 0), (3, 1, 1))))
                e = self.refused(s, clash4d.EXIT_LIMIT)
                self.assertEqual(e.place, "objects[0].shape.block.max[0]")
            finally:
                sys.set_int_max_str_digits(old)

    def test_not_finite(self):
        for x in (float("nan"), float("inf"), -float("inf"), Decimal("NaN"), Decimal("-Infinity")):
            s = scene(obj("a", block((0, 0, 0), (x, 1, 1))), obj("b", block((2, 0, 0), (3, 1, 1))))
            e = self.refused(s)
            self.assertEqual(e.place, "objects[0].shape.block.max[0]")
            self.assertIn("not a finite number", e.message)

    def test_floats_and_decimals_by_their_exact_value(self):
        # 0.5 and Decimal("5E-1") are exactly 1/2: the blocks meet at t* = 1/2 as with ints
        for half in (0.5, Decimal("5E-1"), Decimal("0.50")):
            s = scene(obj("a", block((0, 0, 0), (2 * half, 1, 1)), "vel 1 0 0"),
                      obj("b", block((4 * half, 0, 0), (3, 1, 1)), "vel -1 0 0"))
            self.assertEqual(clash4d.check(s, earliest=True)["earliest"]["t"], Fraction(1, 2), repr(half))

    def test_keys_that_are_not_strings(self):
        for key in (1, b"name", None, (1, 2), 1.5):
            s = valid_scene()
            s["meta"] = {"notes": {key: 1}}
            e = self.refused(s)
            self.assertEqual(e.place, "meta.notes")
            self.assertIn("a key is not a string", e.message)

    def test_values_that_are_not_json(self):
        for v in (b"bytes", b"x" * 10 ** 6, bytearray(b"x"), object(), {1, 2}, frozenset(), complex(1, 2),
                  range(3), iter([1]), Fraction, print):
            s = valid_scene()
            s["objects"][1]["shape"] = v
            e = self.refused(s)
            self.assertEqual(e.place, "objects[1].shape")
            self.assertIn("not a JSON value", e.message)
            self.assertLess(len(e.message), 200)   # a short repr, never a megabyte of it

    def test_bool_is_never_a_number(self):
        s = scene(obj("a", block((0, 0, 0), (True, 1, 1))), obj("b", block((2, 0, 0), (3, 1, 1))))
        e = self.refused(s)
        self.assertTrue(e.place.startswith("objects[0].shape.block.max"), e.place)
        s = valid_scene()
        s["time"] = [False, 10]
        e = self.refused(s)
        self.assertTrue(e.place.startswith("time"), e.place)

    def test_a_string_that_is_not_text(self):
        s = valid_scene()
        s["objects"][0]["name"] = "a\ud800"
        e = self.refused(s)
        self.assertEqual(e.place, "objects[0].name")
        s = valid_scene()
        s["meta"] = {"\udfff": 1}
        self.assertEqual(self.refused(s).place, "meta")

    def test_a_list_subclass_is_read_as_stored(self):
        class Endless(list):
            def __iter__(self):
                while True:
                    yield 0
        s = valid_scene()
        s["meta"] = Endless([1, 2])
        clash4d.validate(s)   # its items, not its endless __iter__


def hostile_value(rng, ancestors):
    """A value to put somewhere in a scene: wrong types, limits, cycles."""
    kinds = [
        lambda: rng.choice(ancestors),                       # a cycle to a container on the path
        lambda: nested(rng.choice([255, 256, 257, 5000, 40000])),
        lambda: rng.choice([10 ** 100000, -(10 ** 999), 10 ** 1001, 2 ** 64, -1, 0]),
        lambda: rng.choice([float("nan"), float("inf"), -0.0, 1e308, 5e-324, 0.1]),
        lambda: rng.choice([Decimal("1e999999999"), Decimal("-0"), Decimal("sNaN"), Decimal("1.5")]),
        lambda: rng.choice([Fraction(1, 3), Fraction(10 ** 3000, 7)]),
        lambda: rng.choice([True, False, None]),
        lambda: rng.choice([b"x", bytearray(3), object(), {1}, 1j, print, int]),
        lambda: rng.choice(["", "0.1", "1/0", "1/3", "vel 1 0 0", "\ud800", "\x00", "x" * 100000, "1e1000"]),
        lambda: rng.choice([{}, [], (), {1: 2}, {"block": None}, [[]] * 3]),
    ]
    return rng.choice(kinds)()


def mutate(rng, s):
    """One random change somewhere in the scene s (in place)."""
    ancestors = [s]
    node = s
    while True:
        keys = list(node.keys()) if isinstance(node, dict) else list(range(len(node)))
        if not keys:
            return
        k = rng.choice(keys)
        child = node[k]
        if isinstance(child, (dict, list)) and child and rng.random() < 0.7:
            ancestors.append(child)
            node = child
            continue
        action = rng.random()
        if action < 0.15 and isinstance(node, dict):
            del node[k]
        elif action < 0.25 and isinstance(node, dict):
            node[rng.choice(["meta", "extra", "block", "z"])] = hostile_value(rng, ancestors)
        else:
            node[k] = hostile_value(rng, ancestors)
        return


class Random_hostile_dicts(unittest.TestCase):
    def test_every_call_answers_or_raises_input_error(self):
        """Seeded: CLASH4D_PY_SEED overrides the seed, CLASH4D_PY_CASES the count."""
        seed = int(os.environ.get("CLASH4D_PY_SEED", "59"))
        cases = int(os.environ.get("CLASH4D_PY_CASES", "300"))
        print(f"\nhostile dicts: seed {seed}, {cases} cases (CLASH4D_PY_SEED, CLASH4D_PY_CASES)", file=sys.stderr)
        rng = random.Random(seed)
        outcomes = {}
        for i in range(cases):
            s = valid_scene()
            for _ in range(rng.randint(1, 3)):
                mutate(rng, s)
            try:
                if i % 2:
                    r = clash4d.check(s, max_seconds=5)
                    self.assertIn(r["collide"], (True, False))
                else:
                    self.assertIsInstance(clash4d.validate(s), dict)
                outcome = "answered"
            except clash4d.InputError as e:
                self.assertIn(e.exit_code, (clash4d.EXIT_INVALID, clash4d.EXIT_LIMIT))
                self.assertTrue(str(e).startswith("<scene>: "), f"seed {seed} case {i}: {e}")
                outcome = "refused"
            outcomes[outcome] = outcomes.get(outcome, 0) + 1
        print(f"hostile dicts: {outcomes}", file=sys.stderr)
        self.assertGreater(outcomes.get("refused", 0), 0)


ROTATION = FIXTURES / "rotation"
EXPECTED = json.loads((ROTATION / "expected.json").read_text())   # hand-derived, with the derivations


def expected_number(x, want):
    """Whether x is the number fixtures/rotation/expected.json describes: a
    rational "p/q" (then a Fraction), {"range": [lo, hi]} (lo <= x <= hi,
    where contact points are not unique) or {"poly", "between"} (the
    irrational root, then a clash4d.Algebraic)."""
    if isinstance(want, str):
        return isinstance(x, Fraction) and x == Fraction(want)
    if "range" in want:
        lo, hi = (Fraction(v) for v in want["range"])
        return lo <= x <= hi
    lo, hi = (Fraction(v) for v in want["between"])
    return isinstance(x, clash4d.Algebraic) and x.poly == [int(c) for c in want["poly"]] and lo < x < hi


def quarter_turn(translate_end=(0, 0, 0)):
    """A motion turning a quarter turn about z over [0, 1]: q(t) = (1, 0, 0, t)."""
    return {"poses": [{"t": 0}, {"t": 1, "translate": list(translate_end), "rotate": [1, 0, 0, 1]}]}


# fixtures/rotation/square_into_slab.json written as a dict, numbers as Fractions.
SQUARE_INTO_SLAB = scene(obj("square", block((-1, -1, -1), (1, 1, 1)), quarter_turn()),
                         obj("slab", block((Fraction(6, 5), -1, -1), (3, 1, 1))), time=(0, 1))


class Rotation(unittest.TestCase):
    """Scenes whose objects turn (pose motions), decided by time slices, against
    the hand-derived answers of fixtures/rotation/expected.json."""

    def check_expected(self, r, want, name):
        self.assertEqual(r["collide"], want["collide"], name)
        if not want["collide"]:
            self.assertNotIn("witness", r)
            return
        e = r["earliest"]
        if "pair" in want:
            self.assertEqual(e["objects"], tuple(want["pair"]), name)
        self.assertTrue(expected_number(e["t"], want["t"]), f"{name}: t* = {e['t']!r}, expected {want['t']}")
        for x, w in zip(e["point"], want["point"]):
            self.assertTrue(expected_number(x, w), f"{name}: contact {e['point']!r}, expected {want['point']}")
        self.assertNotIn("inside", e)   # time slices give no generic inside points
        self.assertTrue(r["witness"]["verified"], name)

    def test_fixtures_as_derived_by_hand(self):
        for name, answers in EXPECTED.items():
            for semantics in ("regularised", "closed"):
                with self.subTest(fixture=name, semantics=semantics):
                    r = clash4d.check(ROTATION / name, semantics=semantics, earliest=True)
                    self.check_expected(r, answers[semantics], name)

    def test_square_into_slab_t_star(self):
        # 11t^2 - 10t + 1 = 0 at t = (5 - sqrt 14) / 11 in (0, 1/2).
        t = clash4d.check(ROTATION / "square_into_slab.json", earliest=True)["earliest"]["t"]
        self.assertEqual(t.poly, [1, -10, 11])
        self.assertEqual(t.approx, "0.11439478302055078")
        self.assertTrue(Fraction(0) < t < Fraction(1, 2))

    def test_regularised_witness_is_rational_closed_may_not_be(self):
        r = clash4d.check(ROTATION / "square_into_slab.json")
        self.assertTrue(all(isinstance(x, Fraction) for x in r["witness"]["point"]))
        # The closed objects meet only at t = sqrt 2 - 1: the witness is then.
        r = clash4d.check(ROTATION / "touch_at_irrational_time.json", semantics="closed", earliest=True)
        w = r["witness"]["point"]
        self.assertIsInstance(w[3], clash4d.Algebraic)
        self.assertEqual(w[3], r["earliest"]["t"])
        self.assertTrue(r["witness"]["verified"])

    def test_rational_gives_the_same_answers(self):
        for name in ("square_into_slab.json", "corner_at_rational_time.json", "touch_at_irrational_time.json"):
            for semantics in ("regularised", "closed"):
                with self.subTest(fixture=name, semantics=semantics):
                    r = clash4d.check(ROTATION / name, number="rational", semantics=semantics, earliest=True)
                    self.assertEqual(r["number"], "rational")
                    self.check_expected(r, EXPECTED[name][semantics], name)

    def test_a_dict_with_poses_answers_as_the_file(self):
        for semantics in ("regularised", "closed"):
            self.assertEqual(clash4d.check(SQUARE_INTO_SLAB, semantics=semantics, earliest=True),
                             clash4d.check(ROTATION / "square_into_slab.json", semantics=semantics, earliest=True))
        named = dict(SQUARE_INTO_SLAB, name=json.loads((ROTATION / "square_into_slab.json").read_text())["name"])
        self.assertEqual(clash4d.scene_json(named), clash4d.scene_json(ROTATION / "square_into_slab.json"))

    def test_given_pose_motions(self):
        at_rest = clash4d.Scene(scene(obj("square", block((-1, -1, -1), (1, 1, 1))),
                                      obj("slab", block((Fraction(6, 5), -1, -1), (3, 1, 1))), time=(0, 1)))
        self.assertFalse(clash4d.check(at_rest)["collide"])
        r = clash4d.check(at_rest, earliest=True, motions=[quarter_turn(), "rest"])
        self.check_expected(r, EXPECTED["square_into_slab.json"]["regularised"], "given motions")
        self.assertEqual(r["earliest"]["t"], clash4d.check(SQUARE_INTO_SLAB, earliest=True)["earliest"]["t"])

    def test_poses_without_rotation_are_the_robmod_motion(self):
        # a moves by 1 per unit of time over [0, 10], written both ways: t* = 1/2 against b.
        robmod = scene(obj("a", block((0, 0, 0), (1, 1, 1)), "rest until 0 vel 1 0 0 until 10 rest"),
                       obj("b", block((2, 0, 0), (3, 1, 1)), "vel -1 0 0"))
        posed = copy.deepcopy(robmod)
        posed["objects"][0]["motion"] = {"poses": [{"t": 0}, {"t": 10, "translate": [10, 0, 0]}]}
        for number in ("exact", "rational", "double"):
            for semantics in ("regularised", "closed"):
                with self.subTest(number=number, semantics=semantics):
                    r = clash4d.check(posed, number=number, semantics=semantics, earliest=True)
                    self.assertEqual(r, clash4d.check(robmod, number=number, semantics=semantics, earliest=True))
                    self.assertEqual(r["earliest"]["t"], Fraction(1, 2))
        s = clash4d.Scene(robmod)
        self.assertEqual(clash4d.check(s, earliest=True, motions=[posed["objects"][0]["motion"], "vel -1 0 0"]),
                         clash4d.check(robmod, earliest=True))

    def test_compare_on_a_turning_scene(self):
        # Every own subject answers; the exact t* is irrational, so it comes
        # as text only (t_text), never as a rounded Fraction.
        c = clash4d.compare(SQUARE_INTO_SLAB, earliest=True)
        rows = {r["subject"]: r for r in c["subjects"]}
        exact = rows["exact"]["earliest"]
        self.assertNotIn("t", exact)
        self.assertTrue(exact["t_text"].startswith("root of [1, -10, 11]"))
        self.assertTrue(rows["double"]["collide"])
        self.assertLess(abs(float(rows["double"]["earliest"]["t"]) - 0.11439478302055078), 1e-12)

    def test_double_is_the_float_subject(self):
        # The same time slices in doubles: t* is a double's exact value,
        # near the hand-derived (5 - sqrt 14) / 11.
        r = clash4d.check(SQUARE_INTO_SLAB, number="double", earliest=True)
        self.assertTrue(r["collide"])
        t = r["earliest"]["t"]
        self.assertIsInstance(t, Fraction)
        self.assertAlmostEqual(float(t), 0.11439478302055078, delta=1e-12)

    def test_max_seconds(self):
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.check(ROTATION / "pocket_past_peg.json", earliest=True, max_seconds=1e-9)
        self.assertEqual((c.exception.exit_code, c.exception.place), (clash4d.EXIT_LIMIT, "max_seconds"))

    def test_bad_poses(self):
        s = clash4d.Scene(SQUARE_INTO_SLAB)
        for motion, place in (({"poses": [{"t": 0, "rotate": [0, 0, 0, 0]}]}, "motions[0].poses[0]"),
                              ({"poses": [{"t": 1}, {"t": 0}]}, "motions[0].poses[1]"),
                              ({"poses": []}, "motions[0]"),
                              ({"poses": [{"t": 0, "turn": 1}]}, "motions[0].poses[0]"),
                              ({"poses": [{"t": True}]}, "motions[0].poses[0].t"),
                              ({"poses": [{"t": 0, "translate": [1, 2]}]}, "motions[0].poses[0].translate"),
                              ({"poses": [{"t": 0}], "vel": 1}, "motions[0]"),
                              (42, "motions[0]")):
            with self.subTest(motion=motion):
                with self.assertRaises(clash4d.InputError) as c:
                    clash4d.check(s, motions=[motion, "rest"])
                self.assertTrue(c.exception.place.startswith(place), c.exception.place)
                self.assertEqual(c.exception.exit_code, clash4d.EXIT_INVALID)
        bad = copy.deepcopy(SQUARE_INTO_SLAB)
        bad["objects"][0]["motion"]["poses"][1]["rotate"] = [-1, 0, 0, 0]   # q(t) passes through 0
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.check(bad)
        self.assertTrue(c.exception.place.startswith("objects[0].motion.poses"), c.exception.place)


def slow_scene(copies):
    """copies of the skewed section 6 scene's pair, 1000 apart in x: in
    rationals each pair takes seconds (papers/cameron1990/README.md)."""
    one = json.loads((FIXTURES / "paper" / "section6_weaving_vehicle_skewed.json").read_text())
    objects = []
    for k in range(copies):
        for o in one["objects"]:
            objects.append({"name": f"{o['name']}{k}", "motion": o.get("motion", "rest"),
                            "shape": {"translate": [1000 * k, 0, 0], "solid": o["shape"]}})
    return {"format": "clash4d-scene/1", "time": one["time"], "objects": objects}


SLOW = slow_scene(4)
GENEROUS = 15   # seconds: far less than the slow scene's full check in rationals, far more than a stop needs


def assert_ctrl_c_stops(test, work, after=0.5):
    """Ctrl-C (SIGINT) `after` seconds into work() raises KeyboardInterrupt
    out of it well within GENEROUS seconds."""
    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(after, os.kill, (os.getpid(), signal.SIGINT))
    start = time.monotonic()
    try:
        timer.start()
        with test.assertRaises(KeyboardInterrupt):
            work()
        test.assertLess(time.monotonic() - start, GENEROUS)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, old)


class Time_limit_and_interrupt(unittest.TestCase):
    """max_seconds as `clash4d check --max-seconds`, and Ctrl-C during a
    check (issue 59, item 8)."""

    def test_max_seconds_stops_a_long_check(self):
        prepared = clash4d.Scene(SLOW)
        start = time.monotonic()
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.check(prepared, number="rational", all_pairs=True, max_seconds=0.5)
        self.assertLess(time.monotonic() - start, GENEROUS)
        e = c.exception
        self.assertEqual(e.exit_code, clash4d.EXIT_LIMIT)
        self.assertEqual(e.place, "max_seconds")
        self.assertIn("the work budget of max_seconds 0.5 ran out before an answer", e.message)

    def test_a_prepared_scene_answers_after_a_stopped_check(self):
        path = FIXTURES / "paper" / "section6_weaving_vehicle_skewed.json"
        prepared = clash4d.Scene(path)
        with self.assertRaises(clash4d.InputError):
            clash4d.check(prepared, earliest=True, max_seconds=1e-9)
        self.assertEqual(clash4d.check(prepared, earliest=True), clash4d.check(path, earliest=True))

    def test_max_seconds_within_the_limit_and_refused(self):
        self.assertEqual(clash4d.check(APPROACH, earliest=True, max_seconds=1000),
                         clash4d.check(APPROACH, earliest=True))
        for bad in (-1, float("nan")):
            with self.assertRaises(ValueError):
                clash4d.check(APPROACH, max_seconds=bad)

    def test_compare_and_ccd_batch_have_the_limit(self):
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.compare(FIXTURES / "paper" / "section6_weaving_vehicle_skewed.json", max_seconds=1e-9)
        self.assertEqual(c.exception.exit_code, clash4d.EXIT_LIMIT)
        t0 = [[Fraction(1, 4), Fraction(1, 4), 1], [0, 0, 0], [1, 0, 0], [0, 1, 0]]
        t1 = [[Fraction(1, 4), Fraction(1, 4), -1], [0, 0, 0], [1, 0, 0], [0, 1, 0]]
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.ccd_batch([(t0, t1)] * 100, max_seconds=1e-9)
        self.assertEqual(c.exception.place, "max_seconds")
        self.assertEqual(len(clash4d.ccd_batch([(t0, t1)] * 3, max_seconds=1000)), 3)

    def test_ctrl_c_interrupts_a_long_check(self):
        assert_ctrl_c_stops(self, lambda: clash4d.check(SLOW, number="rational", all_pairs=True))
        # the module is whole afterwards
        self.assertEqual(clash4d.check(APPROACH, earliest=True)["earliest"]["t"], Fraction(1, 2))


def bowl_off(m):
    """A non-convex part of about 2 m^2 triangles in OFF (as
    scripts/decomposition-bench makes): z = x^2 + y^2 over an m x m grid on
    [-1, 1]^2, walls and a lid at z = 3, one grid point in three pushed up
    into the solid along a diagonal. Its decomposition takes seconds."""
    xs = [Fraction(-1) + Fraction(2 * i, m) for i in range(m + 1)]
    pts, at = [], {}
    for i, x in enumerate(xs):
        for j, y in enumerate(xs):
            at[i, j] = len(pts)
            pushed = 0 < i == j < m and i % 3 == 0
            pts.append((x, y, x * x + y * y + (Fraction(2, m) if pushed else 0)))
    for x in (-1, 1):
        for y in (-1, 1):
            at["top", x, y] = len(pts)
            pts.append((Fraction(x), Fraction(y), Fraction(3)))
    tris = []
    for i in range(m):
        for j in range(m):   # seen from below: clockwise from above
            tris += [(at[i, j], at[i, j + 1], at[i + 1, j + 1]), (at[i, j], at[i + 1, j + 1], at[i + 1, j])]
    sides = [([at[m, j] for j in range(m + 1)], ("top", 1, -1), ("top", 1, 1)),
             ([at[i, m] for i in range(m, -1, -1)], ("top", 1, 1), ("top", -1, 1)),
             ([at[0, j] for j in range(m, -1, -1)], ("top", -1, 1), ("top", -1, -1)),
             ([at[i, 0] for i in range(m + 1)], ("top", -1, -1), ("top", 1, -1))]
    for chain, apex, other in sides:   # counter-clockwise seen from outside
        tris += [(at[apex], chain[k], chain[k + 1]) for k in range(m)] + [(at[apex], chain[m], at[other])]
    lid = [at["top", -1, -1], at["top", 1, -1], at["top", 1, 1], at["top", -1, 1]]
    tris += [(lid[0], lid[1], lid[2]), (lid[0], lid[2], lid[3])]
    text = lambda v: str(Decimal(v.numerator) / Decimal(v.denominator))
    return "OFF\n%d %d 0\n" % (len(pts), len(tris)) + "".join(
        " ".join(text(v) for v in p) + "\n" for p in pts) + "".join("3 %d %d %d\n" % t for t in tris)


class Interrupted_mesh_reading(unittest.TestCase):
    """Ctrl-C during a scene's reading, while CGAL decomposes a mesh (issue
    58 item 3: the decomposition runs where it can be stopped)."""

    def test_ctrl_c_interrupts_a_long_decomposition(self):
        import tempfile
        with tempfile.TemporaryDirectory() as folder:
            folder = pathlib.Path(folder)
            # Read and checked in 0.6 to 1 s, decomposed in 1.6 to 7 s, by machine
            # (`check --stats` gives the decomposition's seconds): Ctrl-C after
            # 1 s falls inside the decomposition, or just before it, never after.
            (folder / "bowl.off").write_text(bowl_off(64))
            scene = {"format": "clash4d-scene/1", "time": [0, 1],
                     "objects": [{"name": "bowl", "shape": {"mesh": "bowl.off"}},
                                 {"name": "probe", "shape": {"block": {"min": [5, 5, 5], "max": [6, 6, 6]}}}]}
            (folder / "scene.json").write_text(json.dumps(scene))
            with unittest.mock.patch.dict(os.environ, {"CLASH4D_CACHE_DIR": str(folder / "cache")}):
                assert_ctrl_c_stops(self, lambda: clash4d.Scene(folder / "scene.json"), after=1.0)
            self.assertEqual(list((folder / "cache").glob("*.pieces")), [])   # nothing half-made was kept


class Typed_answers(unittest.TestCase):
    """check's clash4d.Answer, Pair and Point (issue 60, item 5)."""

    def test_point_has_four_named_coordinates(self):
        self.assertEqual(clash4d.Point._fields, ("x", "y", "z", "t"))
        r = clash4d.check(APPROACH, earliest=True)
        self.assertIsInstance(r, clash4d.Answer)
        self.assertIsInstance(r.pair, clash4d.Pair)
        for p in (r.earliest, r.witness):
            self.assertIsInstance(p, clash4d.Point)
            self.assertEqual(len(p), 4)
            self.assertTrue(all(isinstance(c, Fraction) for c in p), p)
        # APPROACH: t* = 1/2 at x = 3/2 (derived above it); the contact point is on both blocks.
        e = r.earliest
        self.assertEqual((e.x, e.t), (Fraction(3, 2), Fraction(1, 2)))
        self.assertTrue(0 <= e.y <= 1 and 0 <= e.z <= 1)
        self.assertEqual(r.t, Fraction(1, 2))
        self.assertEqual(r.objects, ("a", "b"))
        x, y, z, t = r.witness   # strictly inside a = [t, 1 + t] and b = [2 - t, 3 - t] at its t
        self.assertTrue(t < x < 1 + t and 2 - t < x < 3 - t and 0 < y < 1 and 0 < z < 1)
        self.assertTrue(r.pair.verified)
        self.assertFalse(r.pair.at_start)

    def test_fixtures_hand_known_fractions(self):
        # clear_collision_head_on: a's face x = 1 + t meets b's x = 5 - t at t* = 2, x = 3.
        r = clash4d.check(FIXTURES / "contact" / "clear_collision_head_on.json", earliest=True)
        self.assertEqual((r.t, r.earliest.x), (2, 3))
        self.assertIsInstance(r.t, Fraction)
        # approach_stop_decimal (contact/expected.json): b's face 0.1 + 0.1 t stops at t = 2
        # on exactly 0.3 = a's face: never overlapping, first contact at t* = 2, x = 3/10;
        # read from the decimals as decimals (in doubles 0.1 + 0.1 * 2 > 0.3).
        path = FIXTURES / "contact" / "approach_stop_decimal.json"
        self.assertFalse(clash4d.check(path).collide)
        r = clash4d.check(path, semantics="closed", earliest=True)
        self.assertEqual((r.collide, r.t, r.earliest.x), (True, 2, Fraction(3, 10)))
        # rotation/corner_at_rational_time (rotation/expected.json): turning, yet rational:
        # t* = 1/3 with the corner at (7/5, -1/5).
        r = clash4d.check(ROTATION / "corner_at_rational_time.json", earliest=True)
        self.assertEqual((r.t, r.earliest.x, r.earliest.y), (Fraction(1, 3), Fraction(7, 5), Fraction(-1, 5)))
        self.assertTrue(-1 <= r.earliest.z <= 1)

    def test_irrational_numbers_stay_algebraic(self):
        # square_into_slab (rotation/expected.json): t* = (5 - sqrt 14) / 11, the root of
        # 11t^2 - 10t + 1 in (1/10, 1/8), at y = -sqrt(14) / 5 (root of 25y^2 - 14), x = 6/5.
        r = clash4d.check(ROTATION / "square_into_slab.json", earliest=True)
        t, e = r.t, r.earliest
        self.assertIsInstance(t, clash4d.Algebraic)
        self.assertEqual(t.poly, [1, -10, 11])
        self.assertTrue(Fraction(1, 10) < t < Fraction(1, 8))
        self.assertEqual(e.t, t)
        self.assertEqual(e.x, Fraction(6, 5))
        self.assertEqual(e.y.poly, [-14, 0, 25])
        self.assertTrue(e.y < 0)
        self.assertIn("t=root of 11x^2 - 10x + 1", repr(e))

    def test_no_collision(self):
        r = clash4d.check(TOUCH)
        self.assertEqual((r.collide, r.pair, r.pairs, r.t, r.earliest, r.witness), (False, None, (), None, None, None))
        self.assertEqual(repr(r), "Answer(collide=False, number='exact', semantics='regularised')")
        # Closed: the touching counts; first contact at t = 1 on the face x = 2, and the
        # closed witness comes with a point strictly inside each object.
        r = clash4d.check(TOUCH, semantics="closed", earliest=True)
        self.assertEqual((r.t, r.earliest.x, r.witness.x), (1, 2, 2))
        self.assertEqual(len(r.pair.witness_inside), 2)
        self.assertIsInstance(r.pair.witness_inside[0], clash4d.Point)

    def test_reprs(self):
        self.assertEqual(repr(clash4d.Point(Fraction(3, 2), 0, Fraction(-1, 3), Fraction(1, 2))),
                         "Point(x=3/2, y=0, z=-1/3, t=1/2)")
        r = clash4d.check(FIXTURES / "contact" / "clear_collision_head_on.json", earliest=True)
        self.assertTrue(repr(r).startswith("Answer(collide=True, objects=('a', 'b'), earliest=Point(x=3, "), repr(r))
        self.assertIn("t=2)", repr(r.earliest))
        self.assertTrue(repr(r.pair).startswith("Pair(objects=('a', 'b'), earliest=Point("), repr(r.pair))
        self.assertEqual(repr(clash4d.Scene(APPROACH)), "Scene('test', time=[0, 10], objects=[a: vel 1 0 0, b: vel -1 0 0])")
        self.assertEqual(repr(clash4d.Scene(TOUCH)),
                         "Scene('test', time=[0, 10], objects=[a: rest until 0 vel 1 0 0 until 1 rest, b: rest])")
        self.assertIn("square: poses (2, turning), slab: rest", repr(clash4d.Scene(SQUARE_INTO_SLAB)))
        moving = scene(*(obj("o%d" % i, block((3 * i, 0, 0), (3 * i + 1, 1, 1))) for i in range(12)))
        self.assertIn("... 12 objects in all", repr(clash4d.Scene(moving)))

    def test_dict_form_still_answers(self):
        # Deprecated, kept: the values of the dict that check returned before.
        r = clash4d.check(APPROACH, earliest=True)
        self.assertTrue(r["collide"])
        self.assertEqual(r["earliest"]["t"], r.t)
        self.assertEqual(r["earliest"]["point"], [r.earliest.x, r.earliest.y, r.earliest.z])
        self.assertEqual(r["witness"]["point"], list(r.witness))
        self.assertIn("earliest", r)
        self.assertNotIn("earliest", clash4d.check(APPROACH))
        self.assertIsNone(clash4d.check(TOUCH).get("witness"))

    def test_answers_compare_equal(self):
        self.assertEqual(clash4d.check(APPROACH, earliest=True), clash4d.check(clash4d.Scene(APPROACH), earliest=True))
        self.assertNotEqual(clash4d.check(APPROACH, earliest=True), clash4d.check(APPROACH))
        with self.assertRaises(dataclasses.FrozenInstanceError):   # answers are values
            clash4d.check(APPROACH).collide = False


class Compare_with_motions(unittest.TestCase):
    """compare(..., motions=[...]): every subject sees the scene moved otherwise."""

    def rows(self, c):   # the dict form's rows (deprecated, still answering)
        return {r["subject"]: r for r in c["subjects"]}

    def test_other_motions(self):
        # As test_prepared_scene_under_other_motions: a at rest, b at -2: t* = 1/2 at x = 1.
        for s in (clash4d.Scene(APPROACH), APPROACH):
            c = clash4d.compare(s, earliest=True, motions=["rest", "vel -2 0 0"])
            self.assertTrue(c["agree"])
            exact = self.rows(c)["exact"]["earliest"]
            self.assertEqual((exact["t"], exact["point"][0]), (Fraction(1, 2), 1))
        # b covers the gap of 1 and stops touching a: no collision, but the closed objects meet.
        c = clash4d.compare(APPROACH, motions=["rest", "vel -1 0 0 until 1 rest"])
        self.assertEqual(c["closed_touch"], True)
        self.assertFalse(self.rows(c)["exact"]["collide"])
        self.assertTrue(self.rows(c)["exact closed"]["collide"])
        # Both at rest: nobody collides.
        c = clash4d.compare(APPROACH, motions=["rest", "rest"])
        self.assertFalse(any(r["collide"] for r in c["subjects"] if r["collide"] is not None))

    def test_turning_motions(self):
        # The square at rest beside the slab, given square_into_slab's quarter turn:
        # its exact t* is irrational, so text only (t_text, never a rounded Fraction).
        at_rest = scene(obj("square", block((-1, -1, -1), (1, 1, 1))),
                        obj("slab", block((Fraction(6, 5), -1, -1), (3, 1, 1))), time=(0, 1))
        self.assertFalse(clash4d.compare(at_rest)["subjects"][0]["collide"])
        c = clash4d.compare(at_rest, earliest=True, motions=[quarter_turn(), "rest"])
        exact = self.rows(c)["exact"]["earliest"]
        self.assertNotIn("t", exact)
        self.assertTrue(exact["t_text"].startswith("root of [1, -10, 11]"), exact["t_text"])


    def test_typed_comparison(self):
        # approach_stop_decimal (contact/expected.json): exact says touching only (closed:
        # first contact at t* = 2, x = 3/10); double, reading 0.1 + 0.1 * 2 > 0.3, collides.
        c = clash4d.compare(FIXTURES / "contact" / "approach_stop_decimal.json", earliest=True)
        self.assertIsInstance(c, clash4d.Comparison)
        self.assertFalse(c.agree)
        self.assertTrue(c.closed_touch)
        self.assertEqual(c.row("exact").collide, False)
        self.assertTrue(c.row("exact").reference)
        e = c.row("exact closed").earliest
        self.assertIsInstance(e, clash4d.Located)
        self.assertEqual((e.objects, e.t, e.point.x, e.t_text), (("a", "b"), 2, Fraction(3, 10), "2"))
        self.assertIsInstance(e.point, clash4d.Point)
        double = c.row("double")
        self.assertEqual((double.collide, double.agrees, double.cause), (True, False, "input rounding"))
        self.assertIn(clash4d.Disagreement("double", "input rounding", c.disagreements[0].detail, "regularised"),
                      c.disagreements)
        self.assertTrue(repr(c).startswith("Comparison(agree=False, subjects=['exact', "), repr(c))
        self.assertIn("double: input rounding", repr(c))
        self.assertEqual(repr(c.row("exact")), "Row('exact', collide=False, agrees=True)")
        with self.assertRaises(KeyError):
            c.row("no such subject")
        self.assertEqual(c["agree"], False)   # the dict form, deprecated
        self.assertEqual(c["subjects"][0]["subject"], "exact")
        # Turning: the exact t* and contact point are irrational: text only, never rounded.
        e = clash4d.compare(SQUARE_INTO_SLAB, earliest=True).row("exact").earliest
        self.assertIsNone(e.t)
        self.assertIsNone(e.point)
        self.assertTrue(e.t_text.startswith("root of [1, -10, 11]"), e.t_text)
        self.assertEqual(e.point_text[0], "6/5")
        self.assertTrue(e.point_text[1].startswith("root of [-14, 0, 25]"), e.point_text)

    def test_ctrl_c_interrupts_a_compare_with_motions(self):
        # 24 copies of the skewed pair: the whole comparison takes about 9 s here
        # (its exact subject, filtered, about 4 s per 12 copies); stopped after 0.3 s.
        slow = slow_scene(24)
        prepared = clash4d.Scene(slow)
        own = [o["motion"] for o in slow["objects"]]
        old = signal.signal(signal.SIGINT, signal.default_int_handler)
        timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
        start = time.monotonic()
        try:
            timer.start()
            with self.assertRaises(KeyboardInterrupt):
                clash4d.compare(prepared, motions=own)
            self.assertLess(time.monotonic() - start, 3)
        finally:
            timer.cancel()
            signal.signal(signal.SIGINT, old)

    def test_max_seconds_with_motions(self):
        path = FIXTURES / "paper" / "section6_weaving_vehicle_skewed.json"
        own = [o.get("motion", "rest") for o in json.loads(path.read_text())["objects"]]
        with self.assertRaises(clash4d.InputError) as c:
            clash4d.compare(clash4d.Scene(path), motions=own, max_seconds=1e-9)
        self.assertEqual((c.exception.exit_code, c.exception.place), (clash4d.EXIT_LIMIT, "max_seconds"))
        r = clash4d.check(APPROACH, earliest=True, max_seconds=1000)
        self.assertEqual(r.t, Fraction(1, 2))


if __name__ == "__main__":
    unittest.main()
