"""Tests of the Python module clash4d (standard library unittest only).

Run by ctest as test_python, with PYTHONPATH holding the built module and
CLASH4D_FIXTURES the fixtures folder:
    PYTHONPATH=build/python CLASH4D_FIXTURES=fixtures python3 -m unittest -v test_clash4d
Every expected answer is derived by hand in the comment beside it.
"""
import os
import pathlib
import unittest
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
        with self.assertRaises(clash4d.InputError) as e:
            clash4d.check(s, motions=["rest", "vel 1 0"])
        self.assertEqual(e.exception.place, "motions[1]")
        with self.assertRaises(ValueError):
            clash4d.check(s, motions=["rest"])
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


if __name__ == "__main__":
    unittest.main()
