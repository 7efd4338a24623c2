"""The second certificate checker, verify/python/clash4d_verify.py (standard library unittest).

Run by ctest as test_verify_py, with CLASH4D_BINARY the clash4d binary and
CLASH4D_FIXTURES the fixtures folder:
    CLASH4D_BINARY=build/clash4d CLASH4D_FIXTURES=fixtures python3 -m unittest -v test_verify_py
For every fixture scene and mode, `clash4d check --certificate` writes a
certificate; the Python checker must accept it and print the claim line that
`clash4d verify` prints. Then a few tampered certificates must be refused.
"""
import contextlib
import importlib.util
import io
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time
import unittest

SOURCE = pathlib.Path(__file__).resolve().parents[2]
CHECKER = SOURCE / "verify" / "python" / "clash4d_verify.py"
FIXTURES = pathlib.Path(os.environ.get("CLASH4D_FIXTURES", SOURCE / "fixtures"))
BINARY = os.environ.get("CLASH4D_BINARY")
FOLDERS = ["paper", "contact", "found", "unbounded"]
MODES = [[], ["--earliest"], ["--all-pairs"], ["--semantics", "closed"],
         ["--semantics", "closed", "--earliest"]]
# The sanitizer run (which sets CLASH4D_CERTIFICATE_CASES) checks the
# default mode only: each check there costs ten times more.
QUICK = "CLASH4D_CERTIFICATE_CASES" in os.environ
if QUICK:
    MODES = [[], ["--semantics", "closed", "--earliest"]]

spec = importlib.util.spec_from_file_location("clash4d_verify", CHECKER)
clash4d_verify = importlib.util.module_from_spec(spec)
spec.loader.exec_module(clash4d_verify)


def scenes():
    for folder in FOLDERS:
        for path in sorted((FIXTURES / folder).glob("*.json")):
            if path.name != "expected.json":
                yield path


def run_inprocess(scene, cert):
    """The checker's main() in this process (no interpreter start per certificate)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = clash4d_verify.main([str(CHECKER), str(scene), str(cert)])
    return rc, out.getvalue(), err.getvalue()


def run_cli(scene, cert):
    p = subprocess.run([sys.executable, str(CHECKER), str(scene), str(cert)],
                       capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


@unittest.skipUnless(BINARY, "CLASH4D_BINARY is not set")
class Verify(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def certify(self, scene, mode, name="cert.json"):
        cert = self.dir / name
        p = subprocess.run([BINARY, "check", str(scene), *mode, "--certificate", str(cert)],
                           capture_output=True, text=True, timeout=600)
        self.assertIn(p.returncode, (0, 1), f"check {scene.name} {mode}: {p.stderr}")
        return cert

    def test_every_fixture_certificate_is_accepted_with_the_same_claim(self):
        accepted, start = 0, time.monotonic()
        for scene in scenes():
            for mode in MODES:
                if "skewed" in scene.name and mode:
                    continue              # seconds each: the default mode only
                with self.subTest(scene=scene.name, mode=" ".join(mode)):
                    cert = self.certify(scene, mode)
                    cpp = subprocess.run([BINARY, "verify", str(scene), str(cert)],
                                         capture_output=True, text=True, timeout=600)
                    self.assertEqual(cpp.returncode, 0, cpp.stderr)
                    rc, out, err = run_inprocess(scene, cert)
                    self.assertEqual(rc, 0, err)
                    self.assertEqual(out, cpp.stdout)
                    self.assertTrue(out.startswith("verified: "), out)
                    accepted += 1
        print(f"\n{accepted} certificates accepted in {time.monotonic() - start:.1f} s",
              file=sys.stderr)
        self.assertGreater(accepted, 150 if QUICK else 300)

    # A scene with one pair apart over one piece: a leaf with one conflict.
    APART = FIXTURES / "contact" / "clear_miss_parallel.json"
    # a-b touch, a-c and b-c apart over pieces split at c's velocity changes.
    PIECES = FIXTURES / "contact" / "three_objects_one_collides.json"

    def tampered(self, scene, mode, edit):
        cert = self.certify(scene, mode)
        doc = json.loads(cert.read_text())
        edit(doc)
        cert.write_text(json.dumps(doc))
        return run_cli(scene, cert)

    @staticmethod
    def leaves(node, path):
        if "conflicts" in node:
            yield node, path
        else:
            yield from Verify.leaves(node["below"], path + ".below")
            yield from Verify.leaves(node["above"], path + ".above")

    def first_leaf(self, doc):
        for i, pair in enumerate(doc["pairs"]):
            for j, piece in enumerate(pair.get("apart", {}).get("pieces", [])):
                for leaf, path in self.leaves(piece["proof"], f"pairs[{i}].apart.pieces[{j}].proof"):
                    if leaf["conflicts"]:
                        return leaf, path
        self.fail("no leaf with a conflict")

    def test_flipped_lambda_sign_fails_at_the_conflict(self):
        where = {}

        def flip(doc):
            leaf, path = self.first_leaf(doc)
            lam = leaf["conflicts"][0]["lambda"]
            lam[0] = lam[0][1:] if lam[0].startswith("-") else "-" + lam[0]
            where["path"] = path + ".conflicts[0]"
        for scene, mode in ((self.APART, []), (self.PIECES, ["--semantics", "closed", "--all-pairs"])):
            rc, out, err = self.tampered(scene, mode, flip)
            self.assertEqual(rc, 1, err)
            self.assertEqual(out, "")
            self.assertIn(where["path"], err)
            self.assertTrue(err.startswith("clash4d_verify.py: "), err)

    def test_dropped_conflict_fails(self):
        def drop(doc):
            leaf, _ = self.first_leaf(doc)
            del leaf["conflicts"][0]
        rc, out, err = self.tampered(self.APART, [], drop)
        self.assertEqual(rc, 1, err)
        self.assertIn("pairs[0].apart.pieces[0].proof: no conflict closes off the term", err)

    def test_dropped_piece_fails(self):
        def drop(doc):
            pieces = [p for p in doc["pairs"] if "apart" in p and len(p["apart"]["pieces"]) > 1]
            self.assertTrue(pieces)
            del pieces[0]["apart"]["pieces"][1]
        rc, out, err = self.tampered(self.PIECES, ["--all-pairs"], drop)
        self.assertEqual(rc, 1, err)
        self.assertRegex(err, r"pairs\[\d\]\.apart\.until: the pieces end at 7/2, not at until = 10")

    def test_claim_that_does_not_follow_fails(self):
        def lie(doc):
            doc["claim"]["collide"] = True
        rc, out, err = self.tampered(self.APART, [], lie)
        self.assertEqual(rc, 1, err)
        self.assertIn("claim.collide", err)

    def test_unknown_key_fails_and_wrong_type_is_unreadable(self):
        rc, _, err = self.tampered(self.APART, [], lambda d: d.update(extra="1"))
        self.assertEqual(rc, 1, err)
        # A JSON number anywhere is unreadable (section 1), an unknown key's value too.
        rc, _, err = self.tampered(self.APART, [], lambda d: d.update(extra=1))
        self.assertEqual(rc, 2, err)
        rc, _, err = self.tampered(self.APART, [], lambda d: d.update(time=[0, 10]))
        self.assertEqual(rc, 2, err)
        self.assertIn("time[0]", err)

    def test_truncated_certificate_is_unreadable(self):
        cert = self.certify(self.APART, [])
        text = cert.read_text()
        cert.write_text(text[:len(text) // 2])
        rc, out, err = run_cli(self.APART, cert)
        self.assertEqual(rc, 2, err)
        self.assertIn(str(cert), err)
        rc, out, err = run_cli(self.APART, self.dir / "missing.json")
        self.assertEqual(rc, 2, err)
        self.assertIn("missing.json", err)

    def test_mesh_scene_is_refused_as_unreadable(self):
        scene = FIXTURES / "meshes" / "scene_l_part.json"
        cert = self.certify(scene, [])
        rc, out, err = run_cli(scene, cert)
        self.assertEqual(rc, 2, err)
        self.assertIn("mesh", err)


CONFORMANCE = SOURCE / "fixtures" / "certificates" / "conformance"


def generated_text(case):
    """A generated case of the corpus: its base text with the edits, in order (manifest.json)."""
    text = (CONFORMANCE / case["from"]).read_text(encoding="utf-8")
    for e in case["edits"]:
        text = text.replace(e["replace"], e["prefix"] + e["unit"] * e["count"] + e["suffix"], 1)
    return text


class Conformance(unittest.TestCase):
    """The shared corpus (docs/certificate-format.md): each case's exit code, as the C++
    checker's test asserts it too (tests/test_verify.cpp)."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def expect(self, scene, cert, exit_code, why):
        rc, out, err = run_inprocess(scene, cert)
        self.assertEqual(rc, exit_code, f"{why}: {err}")
        self.assertNotIn("Traceback", err)
        if rc:
            self.assertTrue(err.startswith("clash4d_verify.py: ") and str(cert) in err, err)
        else:
            self.assertTrue(out.startswith("verified: "), out)

    def test_every_scene_document_of_the_corpus(self):
        # The scene side of the one document rule: the C++ scene reader's
        # exit comes from tests/test_verify.cpp; here the Python verifier's.
        manifest = json.loads((CONFORMANCE / "scenes" / "manifest.json").read_text())
        cert = CONFORMANCE / "valid.json"
        for case in manifest["cases"]:
            with self.subTest(scene=case["scene"]):
                rc, out, err = run_inprocess(CONFORMANCE / "scenes" / case["scene"], cert)
                self.assertEqual(rc, case["verify"], f"{case['why']}: {err}")
                self.assertNotIn("Traceback", err)

    def test_size_caps_read_no_further(self):
        # As clash4d verify: a certificate beyond its cap (256 MiB) is exit 3,
        # a scene beyond the reader's 64 MiB is unreadable (2). Lowered here.
        scene, cert = CONFORMANCE / "scene_apart.json", CONFORMANCE / "valid.json"
        for name, limit, code in (("MAX_CERTIFICATE_BYTES", 64, 3), ("MAX_SCENE_BYTES", 64, 2)):
            kept = getattr(clash4d_verify, name)
            setattr(clash4d_verify, name, limit)
            try:
                rc, out, err = run_inprocess(scene, cert)
            finally:
                setattr(clash4d_verify, name, kept)
            self.assertEqual(rc, code, err)
            self.assertIn("larger than the limit", err)

    def test_every_case_of_the_corpus(self):
        manifest = json.loads((CONFORMANCE / "manifest.json").read_text())
        scene = CONFORMANCE / manifest["scene"]
        for case in manifest["cases"]:
            with self.subTest(case=case["certificate"]):
                self.expect(scene, CONFORMANCE / case["certificate"], case["exit"], case["why"])
        for case in manifest["generated"]:
            with self.subTest(case=case["name"]):
                cert = self.dir / (case["name"] + ".json")
                cert.write_text(generated_text(case), encoding="utf-8")
                self.expect(scene, cert, case["exit"], case["why"])

    def test_an_internal_failure_is_exit_4_without_a_traceback(self):
        manifest = json.loads((CONFORMANCE / "manifest.json").read_text())
        scene = CONFORMANCE / manifest["scene"]
        broken = clash4d_verify.Checker.check
        clash4d_verify.Checker.check = lambda self, doc: 1 / 0
        try:
            rc, out, err = run_inprocess(scene, CONFORMANCE / "valid.json")
        finally:
            clash4d_verify.Checker.check = broken
        self.assertEqual(rc, 4, err)
        self.assertIn("internal error of the checker: ZeroDivisionError", err)
        self.assertNotIn("Traceback", err)


def cube_hull_scene(n, seed):
    """A hull of n points on the faces of [0,1000]^3 (its 8 corners among them) and a block
    at x in [1500,1600]; the certificate: the hull's x - 1000 and the block's 1500 - x, 1 and 1."""
    import random
    rnd = random.Random(seed)
    pts = [[x, y, z] for x in (0, 1000) for y in (0, 1000) for z in (0, 1000)]
    while len(pts) < n:
        c = [rnd.randint(0, 1000) for _ in range(3)]
        c[len(pts) % 3] = rnd.choice((0, 1000))
        pts.append(c)
    scene = {"format": "clash4d-scene/1", "time": [0, 10], "objects": [
        {"name": "A", "shape": {"hull": pts}},
        {"name": "B", "shape": {"block": {"min": [1500, 0, 0], "max": [1600, 100, 100]}}}]}
    leaf = {"conflicts": [{"literals": [["1", "0", "0", "0", "-1000"], ["-1", "0", "0", "0", "1500"]],
                           "lambda": ["1", "1"]}]}
    return scene, certificate([{"t": ["0", "10"], "proof": leaf}])


def certificate(pieces):
    return {"format": "clash4d-certificate/1", "semantics": "regularised", "time": ["0", "10"],
            "claim": {"collide": False, "earliest": False, "all_pairs": False},
            "pairs": [{"objects": ["A", "B"], "collide": False,
                       "apart": {"until": "10", "pieces": pieces}}]}


class Costs(unittest.TestCase):
    """Issue 59 item 4: a 300-point hull and a 9,999-segment motion verify within the suite's
    ordinary time (no timing assert: before, they took minutes)."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def run_pair(self, scene, cert):
        (self.dir / "s.json").write_text(json.dumps(scene))
        (self.dir / "c.json").write_text(json.dumps(cert))
        return run_inprocess(self.dir / "s.json", self.dir / "c.json")

    def test_a_hull_of_300_points_on_a_cube(self):
        seed = 59
        print(f"\nseed {seed}", file=sys.stderr)
        rc, out, err = self.run_pair(*cube_hull_scene(300, seed))
        self.assertEqual(rc, 0, err)
        self.assertEqual(out, "verified: no collision in [0, 10] (regularised): 1 pair apart\n")

    def test_the_hull_atoms_are_the_facet_planes(self):
        from fractions import Fraction
        pts = [tuple(map(Fraction, p)) for p in
               [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)]]
        pts.append((Fraction(1, 10), Fraction(1, 10), Fraction(1, 10)))   # inside
        pts.append((Fraction(1, 2), Fraction(1, 2), Fraction(0)))         # on a face
        keys = {clash4d_verify.primitive(a) for a in clash4d_verify.hull_atoms(pts)}
        # the bipyramid's six faces: three at the origin's coordinate planes, three through (1,1,1)
        self.assertEqual(keys, {(-1, 0, 0, 0), (0, -1, 0, 0), (0, 0, -1, 0),
                                (1, 1, -1, -1), (1, -1, 1, -1), (-1, 1, 1, -1)})

    def test_a_motion_of_9999_segments(self):
        n = 9999
        motion = " ".join(f"vel 0 0 0 until {k}/1000" for k in range(1, n + 1)) + " vel 0 0 0"
        scene = {"format": "clash4d-scene/1", "time": [0, 10], "objects": [
            {"name": "A", "shape": {"block": {"min": [0, 0, 0], "max": [1, 1, 1]}}},
            {"name": "B", "shape": {"block": {"min": [2, 0, 0], "max": [3, 1, 1]}}, "motion": motion}]}
        leaf = {"conflicts": [{"literals": [["1", "0", "0", "0", "-1"], ["-1", "0", "0", "0", "2"]],
                               "lambda": ["1", "1"]}]}
        cuts = ["0"] + [f"{k}/1000" for k in range(1, n + 1)] + ["10"]
        pieces = [{"t": [cuts[k], cuts[k + 1]], "proof": leaf} for k in range(n + 1)]
        rc, out, err = self.run_pair(scene, certificate(pieces))
        self.assertEqual(rc, 0, err)


if __name__ == "__main__":
    unittest.main()
