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
from fractions import Fraction

SOURCE = pathlib.Path(__file__).resolve().parents[2]
CHECKER = SOURCE / "verify" / "python" / "clash4d_verify.py"
FIXTURES = pathlib.Path(os.environ.get("CLASH4D_FIXTURES", SOURCE / "fixtures"))
BINARY = os.environ.get("CLASH4D_BINARY")
FOLDERS = ["paper", "contact", "found", "unbounded", "rotation", "certificates/split"]
MODES = [[], ["--earliest"], ["--all-pairs"], ["--semantics", "closed"],
         ["--semantics", "closed", "--earliest"]]

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
        self.assertGreater(accepted, 300)

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


# ------------------------------------------------------------------------------------------
# Section 8: scenes where objects turn (clash4d-certificate/turning-1). The certificates are
# written by hand from the doc's worked example (8.6): the block [-1, 1]^3 turning about z
# with q(t) = (1, 0, 0, t), the slab [6/5, 3] x [-1, 1]^2 waiting.

TURNING = SOURCE / "tests" / "data" / "turning"
SQUARE_TENTH = TURNING / "square_slab_tenth.json"            # span [0, 1/10]
SQUARE_SCENE = FIXTURES / "rotation" / "square_into_slab.json"  # span [0, 1]
L1 = [["1", "0", "-1"], ["0", "2"], ["0"], ["-1", "0", "-1"]]       # x - 1 of the square
L2 = [["0", "2"], ["-1", "0", "1"], ["0"], ["-1", "0", "-1"]]       # -y - 1 of the square
L3 = [["-5"], ["0"], ["0"], ["6"]]                                   # 6/5 - x of the slab
LAMBDA = [["5", "0", "-5"], ["0", "10"], ["1", "0", "2", "0", "1"]]
TSTAR = {"poly": ["1", "-10", "11"], "between": ["1/10", "1/8"], "approx": "0.114394783"}
NO_COLLISION = "verified: no collision in [0, 1/10] ({}): 1 pair apart\n"


def conflict(lits=(L1, L2, L3), lams=LAMBDA):
    return {"proof": {"conflicts": [{"literals": [list(x) for x in lits], "lambda": [list(x) for x in lams]}]}}


def turning_certificate(pieces, until="1/10", semantics="regularised", tH=None):
    """A no-collision certificate of the square and the slab over the given pieces."""
    return {"format": "clash4d-certificate/turning-1", "semantics": semantics,
            "time": ["0", tH or until], "claim": {"collide": False, "earliest": False, "all_pairs": False},
            "pairs": [{"objects": ["square", "slab"], "collide": False,
                       "apart": {"until": until, "pieces": pieces}}]}


def example_86(semantics="regularised"):
    """The doc's 8.6 certificate, as printed there: one piece [0, 1/10], one conflict."""
    return turning_certificate([dict(t=["0", "1/10"], **conflict())], semantics=semantics)


def square_scene(tH, slab_motion=None):
    scene = json.loads(SQUARE_SCENE.read_text())
    scene["time"] = [0, tH]
    if slab_motion:
        scene["objects"][1]["motion"] = slab_motion
    return scene


class TurningCase(unittest.TestCase):
    """Runs hand-written certificates of turning scenes in this process."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def run_cert(self, cert, scene=SQUARE_TENTH):
        if isinstance(scene, dict):
            (self.dir / "scene.json").write_text(json.dumps(scene))
            scene = self.dir / "scene.json"
        (self.dir / "cert.json").write_text(json.dumps(cert))
        rc, out, err = run_inprocess(scene, self.dir / "cert.json")
        self.assertNotIn("Traceback", err)
        return rc, out, err

    def accepted(self, cert, line, scene=SQUARE_TENTH):
        rc, out, err = self.run_cert(cert, scene)
        self.assertEqual((rc, err), (0, ""))
        self.assertEqual(out, line)

    def refused(self, cert, where, scene=SQUARE_TENTH, code=1):
        rc, out, err = self.run_cert(cert, scene)
        self.assertEqual(rc, code, err)
        self.assertEqual(out, "")
        self.assertIn(where, err)
        return err


class TurningCertificates(TurningCase):
    """s8: the worked example accepted, and each kind of tampering refused (exit 1)."""

    def test_the_worked_example_is_accepted_in_both_semantics(self):
        for sem in ("regularised", "closed"):
            with self.subTest(semantics=sem):
                self.accepted(example_86(sem), NO_COLLISION.format(sem))
        # the same certificate through the command line
        (self.dir / "cert.json").write_text(json.dumps(example_86()))
        rc, out, err = run_cli(SQUARE_TENTH, self.dir / "cert.json")
        self.assertEqual((rc, out), (0, NO_COLLISION.format("regularised")), err)

    def test_a_lambda_coefficient_changed_fails_the_identity(self):
        cert = example_86()
        cert["pairs"][0]["apart"]["pieces"][0]["proof"]["conflicts"][0]["lambda"][0] = ["5", "0", "-4"]
        err = self.refused(cert, "pairs[0].apart.pieces[0].proof.conflicts[0]: sum lambda_i n_x,i")
        self.assertIn("not the zero polynomial", err)

    def test_a_lambda_negative_on_the_piece_fails_its_sign(self):
        # every multiplier times (t - 1/20): the identity still holds, lambda_0 < 0 on [0, 1/20)
        t_minus = lambda p: [str(c) for c in clash4d_verify.p_mul(
            [Fraction(x) for x in p], [Fraction(-1, 20), 1])]
        cert = turning_certificate([dict(t=["0", "1/10"], **conflict(lams=[t_minus(p) for p in LAMBDA]))])
        self.refused(cert, "conflicts[0].lambda[0]: ")

    def test_a_multiplier_zero_at_an_end_is_strict_only(self):
        # every multiplier times t: sum lambda_i e_i = t (1 + t^2)(11 t^2 - 10 t + 1) >= 0 on
        # [0, 1/10] (regularised: strict literals), but not > 0 at t = 0 (closed, of both)
        times_t = [["0"] + p for p in LAMBDA]
        for sem in ("regularised", "closed"):
            cert = turning_certificate([dict(t=["0", "1/10"], **conflict(lams=times_t))], semantics=sem)
            if sem == "regularised":
                self.accepted(cert, NO_COLLISION.format(sem))
            else:
                self.refused(cert, "conflicts[0]: sum lambda_i e_i = [0, 1, -10, 12, -10, 11] is not > 0")
        # multipliers that are all zero make no conflict
        zero = turning_certificate([dict(t=["0", "1/10"], **conflict(lams=[["0"], ["0"], ["0"]]))])
        self.refused(zero, "conflicts[0].lambda: every multiplier is the zero polynomial")

    def test_open_end_asks_positivity_on_lo_hi_open_only(self):
        # every multiplier times (1/10 - t): sum lambda_i e_i > 0 on [0, 1/10) and 0 at 1/10
        times_end = [[str(c) for c in clash4d_verify.p_mul([Fraction(x) for x in p], [Fraction(1, 10), -1])]
                     for p in LAMBDA]
        for sem, open_end, where in (
                ("regularised", False, None), ("regularised", True, None),
                ("closed", False, "pairs[0].apart.pieces[0].proof.conflicts[0]: sum lambda_i e_i = "),
                # the leaf holds on [0, 1/10), but no collision needs the touch at tH counted (rule 5)
                ("closed", True, "pairs[0].apart.open_end: must be false")):
            with self.subTest(semantics=sem, open_end=open_end):
                cert = turning_certificate([dict(t=["0", "1/10"], **conflict(lams=times_end))], semantics=sem)
                cert["pairs"][0]["apart"]["open_end"] = open_end
                if where is None:
                    self.accepted(cert, NO_COLLISION.format(sem))
                else:
                    self.refused(cert, where)

    def test_a_piece_dropped_or_its_end_moved_fails(self):
        self.refused(turning_certificate([]), "pairs[0].apart.until: the pieces end at 0, not at until = 1/10")
        cert = turning_certificate([dict(t=["0", "1/11"], **conflict())])
        self.refused(cert, "pairs[0].apart.until: the pieces end at 1/11, not at until = 1/10")
        cert = turning_certificate([dict(t=["1/100", "1/10"], **conflict())])
        self.refused(cert, "pairs[0].apart.pieces[0].t[0]: 1/100 is not 0 (tL)")

    def test_pieces_cut_at_an_algebraic_time(self):
        # 1/sqrt(200) ~ 0.0707, as the root of 200 t^2 - 1 and as one of (200 t^2 - 1)(t + 5)
        cut = {"poly": ["-1", "0", "200"], "between": ["0", "1/10"]}
        same = {"poly": ["-5", "-1", "1000", "200"], "between": ["1/20", "1/10"]}
        other = {"poly": ["-1", "0", "199"], "between": ["0", "1/10"]}
        pieces = lambda hi, lo: [dict(t=["0", hi], **conflict()), dict(t=[lo, "1/10"], **conflict())]
        self.accepted(turning_certificate(pieces(cut, cut)), NO_COLLISION.format("regularised"))
        self.accepted(turning_certificate(pieces(cut, same)), NO_COLLISION.format("regularised"))
        self.refused(turning_certificate(pieces(cut, other)),
                     "pairs[0].apart.pieces[1].t[0]: root of [-1, 0, 199] in (0, 1/10) is not "
                     "root of [-1, 0, 200] in (0, 1/10) (the previous hi)")
        # a piece whose ends are equal, and pieces in the wrong order
        self.refused(turning_certificate([dict(t=["0", cut], **conflict()), dict(t=[same, same], **conflict()),
                                          dict(t=[same, "1/10"], **conflict())]), "pieces[1].t[1]: lo = ")

    def test_the_span_past_t_star_fails_the_e_sum(self):
        # t* = (5 - sqrt 14)/11 ~ 0.1144 < 1/8: 11 t^2 - 10 t + 1 changes sign inside [0, 1/8]
        for sem in ("regularised", "closed"):
            cert = turning_certificate([dict(t=["0", "1/8"], **conflict())], until="1/8", semantics=sem)
            err = self.refused(cert, "pairs[0].apart.pieces[0].proof.conflicts[0]: sum lambda_i e_i = "
                                     "[1, -10, 12, -10, 11] is not", scene=square_scene("1/8"))
            self.assertIn("the literals are not in conflict", err)

    def test_a_time_with_two_roots_or_a_root_at_an_end_fails(self):
        for between, where in ((["1/10", "1"], "t[1]: poly [1, -10, 11] has 2 distinct real roots in (1/10, 1)"),
                               (["0", "1/10"], "t[1]: poly [1, -10, 11] has 0 distinct real roots"),
                               (["1/10", "1/20"], "t[1].between: lo = 1/10 is not below hi = 1/20"),
                               (["1", "3"], "t[1].between[0]: 1 is a root of poly")):
            with self.subTest(between=between):
                hi = {"poly": ["-1", "1"] if between[0] == "1" else ["1", "-10", "11"], "between": between}
                self.refused(turning_certificate([dict(t=["0", hi], **conflict())]),
                             "pairs[0].apart.pieces[0]." + where)
        zero = {"poly": ["0", "0"], "between": ["0", "1"]}
        self.refused(turning_certificate([dict(t=["0", zero], **conflict())]), "t[1].poly: the zero polynomial")
        # a TIME's poly holds integers (unreadable otherwise), its approx is a string never read
        half = {"poly": ["1/2", "-5", "11/2"], "between": ["1/10", "1/8"]}
        self.refused(turning_certificate([dict(t=["0", half], **conflict())]), "t[1].poly[0]", code=2)
        odd = dict(TSTAR, approx="not a number")
        self.refused(turning_certificate([dict(t=["0", odd], **conflict())]),
                     "pairs[0].apart.until: the pieces end at root of [1, -10, 11] in (1/10, 1/8), not at until = 1/10")

    def test_a_touch_at_the_irrational_time(self):
        # closed: the corner (1, -1) reaches x = 6/5 at t*, at y = (11 t* - 5)/5
        def touch(point_time, inside_time):
            return {"format": "clash4d-certificate/turning-1", "semantics": "closed", "time": ["0", "1/2"],
                    "claim": {"collide": True, "earliest": False, "all_pairs": False},
                    "pairs": [{"objects": ["square", "slab"], "collide": True, "touch": {
                        "point": ["6/5", {"at_t": ["-1", "11/5"]}, "0", point_time],
                        "inside": [["0", "0", "0", inside_time], ["2", "0", "0", inside_time]]}}]}
        half = square_scene("1/2")
        self.accepted(touch(TSTAR, TSTAR), "verified: collision (closed): square and slab at "
                      "(6/5, [-1, 11/5](t), 0, root of [1, -10, 11] in (1/10, 1/8))\n", half)
        # the same number, another interval and an unreduced spelling: printed as read, in lowest terms
        other_spelling = {"poly": ["2", "-20", "22", "0"], "between": ["2/20", "0012/100"]}
        self.accepted(touch(other_spelling, TSTAR), "verified: collision (closed): square and slab at "
                      "(6/5, [-1, 11/5](t), 0, root of [2, -20, 22, 0] in (1/10, 3/25))\n", half)
        # the interval moved onto the other root (5 + sqrt 14)/11 ~ 0.795: outside [0, 1/2]
        far = {"poly": ["1", "-10", "11"], "between": ["3/4", "1"]}
        self.refused(touch(far, far), "pairs[0].touch.point[3]: root of [1, -10, 11] in (3/4, 1) is outside [0, 1/2]",
                     scene=half)
        self.refused(touch(TSTAR, far), "pairs[0].touch.inside[0][3]: root of [1, -10, 11] in (3/4, 1) is not",
                     scene=half)
        # the contact moved off the slab's face: not a generic witness for the slab
        moved = touch(TSTAR, TSTAR)
        moved["pairs"][0]["touch"]["point"][0] = "11/10"
        self.refused(moved, "pairs[0].touch.inside[1]: the literal [[-5], [0], [0], [6]] of slab", scene=half)
        # a witness outside the square
        outside = touch(TSTAR, TSTAR)
        outside["pairs"][0]["touch"]["inside"][0][:3] = ["2", "0", "0"]
        self.refused(outside, "pairs[0].touch.inside[0]: (2, 0, 0, root of", scene=half)

    def test_a_regularised_witness(self):
        cert = {"format": "clash4d-certificate/turning-1", "semantics": "regularised", "time": ["0", "1"],
                "claim": {"collide": True, "earliest": False, "all_pairs": False},
                "pairs": [{"objects": ["square", "slab"], "collide": True, "witness": ["5/4", "0", "0", "1/2"]}]}
        # at t = 1/2 (a turn by 2 atan(1/2): cos 3/5, sin 4/5) the corner (1, -1) is at (7/5, 1/5)
        cert["pairs"][0]["witness"][1] = "1/5"
        self.accepted(cert, "verified: collision (regularised): square and slab at (5/4, 1/5, 0, 1/2)\n",
                      SQUARE_SCENE)
        cert["pairs"][0]["witness"][3] = "1"
        self.refused(cert, "pairs[0].witness[3]: t = 1 is not strictly inside (0, 1)", SQUARE_SCENE)
        cert["pairs"][0]["witness"][3] = "1/20"
        self.refused(cert, "pairs[0].witness: (5/4, 1/5, 0, 1/20) is not inside square", SQUARE_SCENE)

    def test_each_format_on_its_kind_of_scene_only(self):
        # a /1 certificate on a turning scene, shaped right (its literal would hold for a square at rest)
        one = {"format": "clash4d-certificate/1", "semantics": "regularised", "time": ["0", "1/10"],
               "claim": {"collide": False, "earliest": False, "all_pairs": False},
               "pairs": [{"objects": ["square", "slab"], "collide": False, "apart": {"until": "1/10", "pieces": [
                   {"t": ["0", "1/10"], "proof": {"conflicts": [{"literals": [
                       ["1", "0", "0", "0", "-1"], ["-5", "0", "0", "0", "6"]], "lambda": ["5", "1"]}]}}]}}]}
        self.refused(one, 'format: the scene needs the format "clash4d-certificate/turning-1"')
        # the turning format on a scene where nothing turns (the square at rest)
        rest = square_scene("1/10")
        del rest["objects"][0]["motion"]
        self.refused(example_86(), 'format: the scene needs the format "clash4d-certificate/1"', scene=rest)
        self.accepted(one, NO_COLLISION.format("regularised"), scene=rest)
        # a scale-only pose (x = y = z = 0) does not turn
        rest["objects"][0]["motion"] = {"poses": [{"t": 0, "rotate": [2, 0, 0, 0]}, {"t": 1, "rotate": [3, 0, 0, 0]}]}
        self.accepted(one, NO_COLLISION.format("regularised"), scene=rest)

    def test_splits_are_not_in_this_version(self):
        cert = example_86()
        cert["pairs"][0]["apart"]["pieces"][0]["proof"]["split"] = ["1", "0", "0", "0", "0"]
        self.refused(cert, "pairs[0].apart.pieces[0].proof.split: unknown key")
        # an earliest claim without a collision needs no earliest proof (rule 4)
        cert = example_86()
        cert["claim"]["earliest"] = True
        self.accepted(cert, NO_COLLISION.format("regularised"))

    def test_a_literal_not_of_the_term_does_not_close_it(self):
        # the slab's literal in another scale is the same literal; another literal is not
        scaled = turning_certificate([dict(t=["0", "1/10"], **conflict(
            lits=(L1, L2, [["-10"], ["0"], ["0"], ["12"]]), lams=LAMBDA[:2] + [["1/2", "0", "1", "0", "1/2"]]))])
        self.accepted(scaled, NO_COLLISION.format("regularised"))
        foreign = turning_certificate([dict(t=["0", "1/10"], **conflict(
            lits=(L1, L2, [["-5"], ["0"], ["0"], ["6", "0", "0", "0", "0"]], [["1"], ["0"], ["0"], ["0"]]),
            lams=LAMBDA + [["0"]]))])
        self.refused(foreign, "pairs[0].apart.pieces[0].proof: no conflict closes off the term [")
        flat = turning_certificate([dict(t=["0", "1/10"], **conflict(lits=(L1, [["0"], ["0", "0"], ["0"], ["1"]]),
                                                                 lams=(["1"], ["1"])))])
        self.refused(flat, "conflicts[0].literals[1]: n_x, n_y and n_z are all the zero polynomial")

    def test_a_literal_and_its_negation_close_a_term_in_regularised_semantics(self):
        # a twin block [1, 3] x [-1, 1]^2 turning with the square: its 1 - x is the negation of
        # the square's x - 1 at every t, so the pair only touches; the slab overlaps the twin
        scene = square_scene(1)
        twin = {"name": "twin", "shape": {"block": {"min": [1, -1, -1], "max": [3, 1, 1]}},
                "motion": scene["objects"][0]["motion"]}
        scene["objects"].append(twin)
        apart = {"objects": ["square", "twin"], "collide": False,
                 "apart": {"until": "1", "pieces": [{"t": ["0", "1"], "proof": {"conflicts": []}}]}}
        cert = turning_certificate([], until="1")
        cert["pairs"] = [apart]
        cert["claim"]["all_pairs"] = False
        two = dict(scene, objects=scene["objects"][0::2])
        self.accepted(cert, "verified: no collision in [0, 1] (regularised): 1 pair apart\n", two)
        closed = dict(cert, semantics="closed")
        self.refused(closed, "pairs[0].apart.pieces[0].proof: no conflict closes off the term", two)
        # all pairs: the colliding ones listed in the certificate's order
        cert["claim"].update(collide=True, all_pairs=True)
        cert["pairs"] = [
            {"objects": ["square", "slab"], "collide": True, "witness": ["5/4", "1/5", "0", "1/2"]},
            apart,
            {"objects": ["slab", "twin"], "collide": True, "witness": ["2", "0", "0", "1/10"]}]
        self.accepted(cert, "verified: colliding pairs (regularised): square/slab, slab/twin; "
                            "1 other pair apart\n", scene)
        del cert["pairs"][2]
        self.refused(cert, "pairs: no PAIR for slab/twin", scene)
        cert["pairs"].append({"objects": ["twin", "slab"], "collide": True, "witness": ["2", "0", "0", "0"]})
        self.refused(cert, "pairs[2].witness[3]: t = 0 is not strictly inside (0, 1)", scene)

    def test_a_robmod_motion_in_a_turning_scene(self):
        # the slab comes towards the square at speed 1 until t = 1/20: 6/5 - x becomes
        # 6/5 - t - x, then 23/20 - x (c(t) = D(t), q = (1, 0, 0, 0), s8.2)
        scene = square_scene("1/16", "vel -1 0 0 until 1/20 rest")
        first = dict(t=["0", "1/20"], **conflict(lits=(L1, L2, [["-5"], ["0"], ["0"], ["6", "-5"]])))
        second = dict(t=["1/20", "1/16"], **conflict(
            lits=(L1, L2, [["-20"], ["0"], ["0"], ["23"]]), lams=LAMBDA[:2] + [["1/4", "0", "1/2", "0", "1/4"]]))
        for sem in ("regularised", "closed"):
            self.accepted(turning_certificate([first, second], until="1/16", semantics=sem),
                          "verified: no collision in [0, 1/16] ({}): 1 pair apart\n".format(sem), scene)
        whole = dict(first, t=["0", "1/16"])
        self.refused(turning_certificate([whole], until="1/16"),
                     "pairs[0].apart.pieces[0].t: a breakpoint of slab at t = 1/20 lies inside", scene)

    def test_invalid_pose_motions_make_the_scene_unreadable(self):
        def scene_with(motion):
            scene = square_scene("1/10")
            scene["objects"][0]["motion"] = motion
            return scene
        for motion, where in (
                ({"poses": []}, "objects[0].motion.poses"),
                ({"poses": [{"t": 0}], "speed": 1}, "objects[0].motion"),
                ({"poses": [{"translate": [0, 0, 0]}]}, "objects[0].motion.poses[0]"),
                ({"poses": [{"t": 0}, {"t": 0}]}, "objects[0].motion.poses[1].t"),
                ({"poses": [{"t": 0, "rotate": [0, 0, 0, 0]}]}, "objects[0].motion.poses[0].rotate"),
                ({"poses": [{"t": 0, "rotate": [1, 0, 0, 1]}, {"t": 1, "rotate": [-2, 0, 0, -2]}]},
                 "objects[0].motion.poses[1].rotate"),
                ({"poses": [{"t": 0, "spin": 1}]}, "objects[0].motion.poses[0]"),
                ({"poses": [{"t": k} for k in range(10001)]}, "objects[0].motion.poses"),
                (7, "objects[0].motion")):
            with self.subTest(motion=str(motion)[:60]):
                self.refused(example_86(), where + ":", scene=scene_with(motion), code=2)
        # 10,000 poses are fine (every pose time a breakpoint: one piece between two of them)
        many = scene_with({"poses": [{"t": str(Fraction(k, 100000)), "rotate": [1, 0, 0, str(Fraction(k, 100000))]}
                                     for k in range(10000)]})
        cert = turning_certificate([dict(t=["0", "1/100000"], **conflict())], until="1/100000", tH="1/100000")
        many["time"] = [0, "1/100000"]
        self.accepted(cert, "verified: no collision in [0, 1/100000] (regularised): 1 pair apart\n", many)
        many["time"] = [0, "1/50000"]
        cert = turning_certificate([dict(t=["0", "1/50000"], **conflict())], until="1/50000")
        self.refused(cert, "pieces[0].t: a breakpoint of square at t = 1/100000 lies inside", scene=many)

    def test_every_pose_time_is_a_breakpoint_in_a_turning_scene(self):
        # s8.2: the slab at rest by two equal poses still has breakpoints at their times
        scene = square_scene("1/10")
        scene["objects"][1]["motion"] = {"poses": [{"t": "1/20"}, {"t": "1/16", "translate": [0, 0, 0]}]}
        self.refused(example_86(), "pieces[0].t: a breakpoint of slab at t = 1/20 lies inside", scene=scene)
        cuts = ["0", "1/20", "1/16", "1/10"]
        cert = turning_certificate([dict(t=[cuts[k], cuts[k + 1]], **conflict()) for k in range(3)])
        self.accepted(cert, NO_COLLISION.format("regularised"), scene=scene)


# Earliest times of turning scenes (s8.4). In the worked example the square's corner (1, -1)
# is at N(q(t)) (1, -1, 0) / |q(t)|^2 = (1 + 2t - t^2, t^2 + 2t - 1, 0) / (1 + t^2) and crosses
# x = 6/5 where 11 t^2 - 10 t + 1 = g(t) = 0, at t* ~ 0.1144. The witness path is the corner pulled
# in by the factor 1 - a(t), a = -g/10 > 0 on (t*, 1/8] and 0 at t*: W(t) = (1 + g/10) corner(t),
# written over w = 10 (1 + t^2):
#   x = (11 - 10t + 11t^2)(1 + 2t - t^2),  y = (11 - 10t + 11t^2)(t^2 + 2t - 1),  z = 0.
# W(t) = R(q(t)) p(t) with p = (1 - a)(1, -1, 0) strictly inside the block for 0 < a < 2, so each of
# the square's literals at W(t) is L = 10 |q|^4 (its atom at p), up to the coprime form's positive
# factor: x - 1 and -y - 1 give -10 a (1 + t^2)^2 = g (1 + t^2)^2 < 0, the others a - 2 or -1 times
# 10 (1 + t^2)^2. The
# slab's 6/5 - x gives L = -5x + 6w = 5 g (1 - t)^2 < 0 on (t*, 1/8]; its other literals stay
# negative (x < 3 w, |y| < w, z = 0). Every L is zero at t* or of one sign: none has a root in (t*, 1/8).
PATH = {"x": ["11", "12", "-20", "32", "-11"], "y": ["-11", "32", "-20", "12", "11"], "z": ["0"],
        "w": ["10", "0", "10"], "to": "1/8"}
T_LATE = {"poly": ["100000000000000000100000000000000000011", "-1000000000000000000220000000000000000000",
                   "1100000000000000000000000000000000000000"], "between": ["1/10", "1/8"]}    # t* + 1e-19
T_EARLY = {"poly": ["99999999999999999900000000000000000011", "-999999999999999999780000000000000000000",
                    "1100000000000000000000000000000000000000"], "between": ["1/10", "1/8"]}   # t* - 1e-19
T_OTHER = {"poly": ["1", "-10", "11"], "between": ["3/4", "1"]}                                   # (5 + sqrt 14)/11
CONTACT = ["6/5", {"at_t": ["-1", "11/5"]}, "0"]     # the corner at t*: y = (32 t* - 12)/(10 t* + 10) = 11 t*/5 - 1
T_TEXT = "root of [1, -10, 11] in (1/10, 1/8)"
EARLIEST = "verified: earliest collision ({}): square and slab at t* = " + T_TEXT
SLAB_ABOVE = [["0"], ["0"], ["1"], ["-1"]]            # z - 1 of the slab
SQUARE_ABOVE = [["0"], ["0"], ["1", "0", "1"], ["-1", "0", "-1"]]   # z - 1 of the square
POST_BELOW = [["0"], ["0"], ["-1"], ["2"]]            # 2 - z of a post [2, 3]^3 above both


def earliest_pair(tstar=TSTAR, path=None, semantics="regularised", point_time=None, inside_time=None,
                  open_end=None):
    """The square/slab PAIR proved by an earliest time: the 8.6 conflict on [0, t*] and the
    witness path (regularised) or the touch at t* (closed)."""
    if semantics == "regularised":
        e = {"t": tstar, "path": dict(PATH, **(path or {}))}
    else:
        pt, it = point_time or tstar, inside_time or tstar
        e = {"t": tstar, "point": CONTACT + [pt], "inside": [["0", "0", "0", it], ["2", "0", "0", it]]}
    apart = {"until": tstar, "pieces": [dict(t=["0", tstar], **conflict())]}
    if open_end is not None:
        apart["open_end"] = open_end
    return {"objects": ["square", "slab"], "collide": True, "earliest": e, "apart": apart}


def earliest_certificate(pairs=None, semantics="regularised", all_pairs=False, earliest=True, **kw):
    return {"format": "clash4d-certificate/turning-1", "semantics": semantics, "time": ["0", "1"],
            "claim": {"collide": True, "earliest": earliest, "all_pairs": all_pairs},
            "pairs": pairs or [earliest_pair(semantics=semantics, **kw)]}


def exact(p):
    return [Fraction(c) for c in p]


class TurningEarliest(TurningCase):
    """s8.4: earliest times of turning scenes, written by hand from the worked example (8.6)."""

    def path_polys(self, path=PATH):
        return [exact(path[k]) for k in "xyzw"]

    def test_the_path_by_hand_numerically_and_exactly(self):
        # numerically first: W(t) is right of x = 6/5, and about the corner, just after t*
        x, y, z, w = self.path_polys()
        ev = lambda p, t: sum(float(c) * t ** i for i, c in enumerate(p))
        tstar = (5 - 14 ** 0.5) / 11
        for t in (tstar + 1e-6, 0.115, 0.12, 0.125):
            X, Y = ev(x, t) / ev(w, t), ev(y, t) / ev(w, t)
            self.assertTrue(6 / 5 < X < 3 and -1 < Y < 1, (t, X, Y))
            c, s = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)            # the turn by 2 atan t
            u, v = c * X + s * Y, -s * X + c * Y                              # W in the block's frame
            self.assertTrue(-1 < u < 1 and -1 < v < 1, (t, u, v))
        # exactly: the literals at W(t) are the polynomials of the comment above
        g = [1, -10, 11]
        P = clash4d_verify
        l1 = P.p_add(P.p_add(P.p_mul(exact(L1[0]), x), P.p_mul(exact(L1[1]), y)), P.p_mul(exact(L1[3]), w))
        self.assertEqual(l1, P.p_mul(g, [1, 0, 2, 0, 1]))                    # g (1 + t^2)^2
        l3 = P.p_add(P.p_scale(x, -5), P.p_scale(w, 6))
        self.assertEqual(l3, P.p_mul(g, [5, -10, 5]))                        # 5 g (1 - t)^2

    def test_the_regularised_earliest_is_accepted(self):
        self.accepted(earliest_certificate(), EARLIEST.format("regularised") + "\n", SQUARE_SCENE)
        (self.dir / "cert.json").write_text(json.dumps(earliest_certificate()))
        rc, out, err = run_cli(SQUARE_SCENE, self.dir / "cert.json")
        self.assertEqual((rc, out), (0, EARLIEST.format("regularised") + "\n"), err)
        # the same PAIR under a claim that is not earliest: a collision just after t* (s8.5)
        self.accepted(earliest_certificate(earliest=False), "verified: collision (regularised): square and "
                      "slab at t* = root of [1, -10, 11] in (1/10, 1/8)\n", SQUARE_SCENE)
        # open_end changes nothing in regularised semantics
        self.accepted(earliest_certificate(open_end=True), EARLIEST.format("regularised") + "\n", SQUARE_SCENE)

    def test_t_star_moved_fails(self):
        # to the other root (~0.795): the path's T1 = 1/8 is before it
        self.refused(earliest_certificate(tstar=T_OTHER), "pairs[0].earliest.path.to: T1 = 1/8 is not after "
                     "t* = root of [1, -10, 11] in (3/4, 1)", SQUARE_SCENE)
        # by 1e-19 later: the path holds, the apart's e sum is negative on (t*, t* + 1e-19]
        err = self.refused(earliest_certificate(tstar=T_LATE), "pairs[0].apart.pieces[0].proof.conflicts[0]: "
                           "sum lambda_i e_i = [1, -10, 12, -10, 11] is not >= 0", SQUARE_SCENE)
        self.assertIn("the literals are not in conflict", err)
        # by 1e-19 earlier: the apart holds, the square's literals at W(t) vanish at t* inside (t*, T1)
        err = self.refused(earliest_certificate(tstar=T_EARLY), "pairs[0].earliest.path: the literal "
                           "[[0, 2], [-1, 0, 1], [0], [-1, 0, -1]] of square at W(t), [1, -10, 13, -20, 23, -10, 11], "
                           "has a root in (t*, T1) = (root of [99999999999999999900000000000000000011, ", SQUARE_SCENE)
        # the apart's until not t*
        cert = earliest_certificate()
        cert["pairs"][0]["apart"] = {"until": "1/10", "pieces": [dict(t=["0", "1/10"], **conflict())]}
        self.refused(cert, "pairs[0].apart.until: 1/10 is not t* = " + T_TEXT, SQUARE_SCENE)
        # t* at tH, and past it
        scene = square_scene("1/10")
        cert = earliest_certificate(tstar="1/10")
        cert["time"] = ["0", "1/10"]
        self.refused(cert, "pairs[0].earliest.t: 1/10 is outside [0, 1/10)", scene)

    def test_the_path_end_fails_before_t_star_at_t_h_or_algebraic(self):
        for to, where in (("1/10", "T1 = 1/10 is not after t* = " + T_TEXT),
                          ("0", "T1 = 0 is not after t*"),
                          ("1", "T1 = 1 is not before tH = 1"),
                          (TSTAR, "T1 must be a rational number (a string), not a TIME object")):
            with self.subTest(to=to):
                self.refused(earliest_certificate(path={"to": to}), "pairs[0].earliest.path.to: " + where,
                             SQUARE_SCENE)
        # past the second root the corner is back inside x < 6/5: a literal crosses zero
        err = self.refused(earliest_certificate(path={"to": "9/10"}), "pairs[0].earliest.path: the literal ",
                           SQUARE_SCENE)
        self.assertIn("has a root in (t*, T1)", err)

    def test_a_path_coefficient_changed_fails(self):
        # x - 1/20: the slab's 6/5 - x at W(t) becomes L + 1/4, positive at t*, -1225/4096 + 1/4 at 1/8
        err = self.refused(earliest_certificate(path={"x": ["219/20", "12", "-20", "32", "-11"]}),
                           "pairs[0].earliest.path: the literal [[-5], [0], [0], [6]] of slab at W(t)", SQUARE_SCENE)
        self.assertIn("has a root in (t*, T1) = (" + T_TEXT + ", 1/8)", err)
        # a point inside the square but not the slab: no literal changes sign, W(T1) is outside
        still = {"x": ["0"], "y": ["0"], "z": ["0"], "w": ["1"]}
        self.refused(earliest_certificate(path=still),
                     "pairs[0].earliest.path: W(T1) at T1 = 1/8 is not inside slab with strict signs", SQUARE_SCENE)
        # x - 245/4096: the slab's 6/5 - x at W(t) is L + 1225/4096, zero at T1 (W(T1) on the face x = 6/5)
        face = {"x": ["44811/4096", "12", "-20", "32", "-11"]}
        self.refused(earliest_certificate(path=face), "pairs[0].earliest.path: the literal [[-5], [0], [0], [6]] "
                     "of slab is zero at W(T1), T1 = 1/8", SQUARE_SCENE)

    def test_w_not_positive_fails(self):
        # the same points with every polynomial negated: w < 0
        neg = {k: [str(-Fraction(c)) for c in PATH[k]] for k in "xyzw"}
        self.refused(earliest_certificate(path=neg), "pairs[0].earliest.path.w: [-10, 0, -10] is not > 0 on (",
                     SQUARE_SCENE)
        # the same points with every polynomial times (t - 3/25): w changes sign at 3/25 in (t*, 1/8)
        P = clash4d_verify
        times = {k: [str(c) for c in P.p_mul(exact(PATH[k]), [Fraction(-3, 25), 1]) or [0]] for k in "xyzw"}
        self.refused(earliest_certificate(path=times), "pairs[0].earliest.path.w: [-6/5, 10, -6/5, 10] is not > 0",
                     SQUARE_SCENE)
        # times (t + 1) instead: still positive, the same points
        plus = {k: [str(c) for c in P.p_mul(exact(PATH[k]), [1, 1]) or [0]] for k in "xyzw"}
        self.accepted(earliest_certificate(path=plus), EARLIEST.format("regularised") + "\n", SQUARE_SCENE)

    def test_a_breakpoint_inside_the_path_fails(self):
        # the slab at rest by one pose at 3/25 in (t*, 1/8), then at T1 = 1/8 itself
        for at, where in (("3/25", "a breakpoint of slab at t = 3/25 lies between t* = " + T_TEXT + " and T1 = 1/8"),
                          ("1/8", "a breakpoint of slab at t = 1/8 is T1")):
            with self.subTest(at=at):
                scene = square_scene(1, {"poses": [{"t": at}]})
                self.refused(earliest_certificate(), "pairs[0].earliest.path.to: " + where, scene)
        # a breakpoint before t* cuts the apart, not the path
        scene = square_scene(1, {"poses": [{"t": "1/9"}]})
        self.refused(earliest_certificate(), "pairs[0].apart.pieces[0].t: a breakpoint of slab at t = 1/9 lies inside",
                     scene)
        cert = earliest_certificate()
        cert["pairs"][0]["apart"]["pieces"] = [dict(t=["0", "1/9"], **conflict()), dict(t=["1/9", TSTAR], **conflict())]
        self.accepted(cert, EARLIEST.format("regularised") + "\n", scene)
        # a breakpoint of the square after T1 does not matter
        scene = square_scene(1)
        scene["objects"][0]["motion"]["poses"].insert(1, {"t": "1/2", "rotate": [1, 0, 0, "1/2"]})
        self.accepted(earliest_certificate(), EARLIEST.format("regularised") + "\n", scene)

    def test_keys_and_types_of_the_earliest_forms(self):
        cert = earliest_certificate(path={"v": ["0"]})
        self.refused(cert, "pairs[0].earliest.path.v: unknown key", SQUARE_SCENE)
        cert = earliest_certificate()
        cert["pairs"][0]["earliest"]["point"] = CONTACT + [TSTAR]
        self.refused(cert, "pairs[0].earliest.point: unknown key", SQUARE_SCENE)
        cert = earliest_certificate()
        del cert["pairs"][0]["earliest"]["path"]["w"]
        self.refused(cert, 'pairs[0].earliest.path: missing key "w"', SQUARE_SCENE, code=2)
        self.refused(earliest_certificate(path={"x": "11"}), "pairs[0].earliest.path.x: expected a polynomial",
                     SQUARE_SCENE, code=2)
        self.refused(earliest_certificate(path={"to": ["1/8"]}), "pairs[0].earliest.path.to: expected a number",
                     SQUARE_SCENE, code=2)
        self.refused(earliest_certificate(path={"z": []}), "pairs[0].earliest.path.z: expected a polynomial",
                     SQUARE_SCENE, code=2)
        cert = earliest_certificate()
        del cert["pairs"][0]["apart"]
        self.refused(cert, "pairs[0]: a colliding PAIR holds one of witness, touch, or earliest with apart",
                     SQUARE_SCENE)
        # the closed form in regularised semantics and the regularised one in closed
        cert = earliest_certificate(semantics="closed")
        cert["semantics"] = "regularised"
        self.refused(cert, 'pairs[0].earliest: missing key "path"', SQUARE_SCENE, code=2)
        cert = earliest_certificate()
        cert["semantics"] = "closed"
        self.refused(cert, 'pairs[0].earliest: missing key "inside"', SQUARE_SCENE, code=2)

    def test_the_closed_earliest_is_accepted(self):
        line = EARLIEST.format("closed") + ", contact (6/5, [-1, 11/5](t), 0, " + T_TEXT + ")\n"
        self.accepted(earliest_certificate(semantics="closed", open_end=True), line, SQUARE_SCENE)
        # the same touch at t* in another spelling of the time
        spelled = {"poly": ["2", "-20", "22"], "between": ["1/10", "3/25"]}
        cert = earliest_certificate(semantics="closed", open_end=True, point_time=spelled, inside_time=spelled)
        self.accepted(cert, line.replace(T_TEXT + ")\n", "root of [2, -20, 22] in (1/10, 3/25))\n"), SQUARE_SCENE)
        # open_end false would be stronger: the e sum is 0 at t*, not > 0 on [0, t*]
        err = self.refused(earliest_certificate(semantics="closed", open_end=False),
                           "pairs[0].apart.pieces[0].proof.conflicts[0]: sum lambda_i e_i = [1, -10, 12, -10, 11] "
                           "is not > 0 on [0, " + T_TEXT + "]", SQUARE_SCENE)

    def test_the_closed_earliest_tampered_fails(self):
        closed = lambda **kw: earliest_certificate(semantics="closed", open_end=True, **kw)
        # the contact's time not t*, a witness at another time
        self.refused(closed(point_time="1/8"), "pairs[0].earliest.point[3]: 1/8 is not t = " + T_TEXT, SQUARE_SCENE)
        self.refused(closed(inside_time=T_OTHER), "pairs[0].earliest.inside[0][3]: root of [1, -10, 11] in (3/4, 1) "
                     "is not the point's time", SQUARE_SCENE)
        # t* 1e-19 early (the contact with it): the corner is not yet at x = 6/5, the point is outside the square
        err = self.refused(closed(tstar=T_EARLY), "pairs[0].earliest.inside[0]: the literal ", SQUARE_SCENE)
        self.assertIn("of square has sign 1", err)
        # 1e-19 late: the touch holds there, the apart fails
        self.refused(closed(tstar=T_LATE), "pairs[0].apart.pieces[0].proof.conflicts[0]: sum lambda_i e_i = ",
                     SQUARE_SCENE)
        # at the other root, past tH of a scene over [0, 1/2]
        cert = closed(tstar=T_OTHER)
        cert["time"] = ["0", "1/2"]
        self.refused(cert, "pairs[0].earliest.t: root of [1, -10, 11] in (3/4, 1) is outside [0, 1/2]",
                     square_scene("1/2"))
        # the contact moved off the slab's face
        cert = closed()
        cert["pairs"][0]["earliest"]["point"][0] = "11/10"
        self.refused(cert, "pairs[0].earliest.inside[1]: the literal [[-5], [0], [0], [6]] of slab", SQUARE_SCENE)

    def post_scene(self, z):
        """The square, the slab and a static post [2, 3] x [-1, 1] x z."""
        scene = square_scene(1)
        scene["objects"].append({"name": "post", "shape": {"block": {"min": [2, -1, z[0]], "max": [3, 1, z[1]]}}})
        return scene

    def test_rule_4_other_pairs_apart_until_t_star_or_later(self):
        scene = self.post_scene([2, 3])                   # above both: apart by z
        def others(until_sq, until_sl="1"):
            return [{"objects": ["square", "post"], "collide": False, "apart": {"until": until_sq, "pieces": [
                        dict(t=["0", until_sq], **conflict(lits=(SQUARE_ABOVE, POST_BELOW),
                                                           lams=(["1"], ["1", "0", "1"])))]}},
                    {"objects": ["slab", "post"], "collide": False, "apart": {"until": until_sl, "pieces": [
                        dict(t=["0", until_sl], **conflict(lits=(SLAB_ABOVE, POST_BELOW), lams=(["1"], ["1"])))]}}]
        line = EARLIEST.format("regularised") + "\n"
        for until in ("1", TSTAR, "143/1250"):            # tH, t* itself, 0.1144 > t*
            with self.subTest(until=until):
                self.accepted(earliest_certificate([earliest_pair()] + others(until)), line, scene)
        self.accepted(earliest_certificate([earliest_pair()] + others(TSTAR, T_LATE)), line, scene)
        self.refused(earliest_certificate([earliest_pair()] + others("1143/10000")),   # 0.1143 < t*
                     "pairs[1].apart.until: 1143/10000 is before t* = " + T_TEXT, scene)
        self.refused(earliest_certificate([earliest_pair()] + others("1", T_EARLY)),
                     "pairs[2].apart.until: root of [99999999999999999900000000000000000011, ", scene)
        self.refused(earliest_certificate([earliest_pair()] + others("1")[:1]), "pairs: no PAIR for slab/post", scene)
        # with all_pairs every other pair is apart until tH
        self.refused(earliest_certificate([earliest_pair()] + others(TSTAR), all_pairs=True),
                     "pairs[1].apart.until: " + T_TEXT + " is not tH = 1", scene)
        self.accepted(earliest_certificate([earliest_pair()] + others("1"), all_pairs=True),
                      "verified: colliding pairs (regularised): square/slab at t* = " + T_TEXT +
                      "; 2 other pairs apart\n", scene)

    def test_two_colliding_pairs(self):
        scene = self.post_scene([-1, 1])                  # overlapping the slab from the start
        # square/post apart: the 8.6 conflict with 2 - x, e sum (1 + t^2)(3 t^2 - 2 t + 1) > 0
        apart = {"objects": ["square", "post"], "collide": False, "apart": {"until": "1", "pieces": [
            dict(t=["0", "1"], **conflict(lits=(L1, L2, [["-1"], ["0"], ["0"], ["2"]]),
                                          lams=(["1", "0", "-1"], ["0", "2"], ["1", "0", "2", "0", "1"])))]}}
        # slab/post collide from t* = tL = 0: a still point, the apart of no pieces
        still = {"objects": ["slab", "post"], "collide": True, "apart": {"until": "0", "pieces": []},
                 "earliest": {"t": "0", "path": {"x": ["5"], "y": ["0"], "z": ["0"], "w": ["2"], "to": "1/2"}}}
        cert = earliest_certificate([earliest_pair(), apart, still], all_pairs=True)
        self.accepted(cert, "verified: colliding pairs (regularised): square/slab at t* = " + T_TEXT +
                      ", slab/post at t* = 0; 1 other pair apart\n", scene)
        self.refused(earliest_certificate([earliest_pair(), apart, still]),
                     "pairs: 2 PAIRs collide; an earliest claim names one", scene)
        # under all_pairs without earliest: the pairs named only
        cert = earliest_certificate([earliest_pair(), apart, still], all_pairs=True, earliest=False)
        self.accepted(cert, "verified: colliding pairs (regularised): square/slab, slab/post; 1 other pair apart\n",
                      scene)
        # an earliest claim needs an earliest proof of every colliding pair
        witness = {"objects": ["slab", "post"], "collide": True, "witness": ["5/2", "0", "0", "1/2"]}
        self.refused(earliest_certificate([earliest_pair(), apart, witness], all_pairs=True),
                     "pairs[2]: the claim is earliest, but this pair has no earliest proof", scene)


@unittest.skipUnless(BINARY, "CLASH4D_BINARY is not set")
class PosesWithoutRotation(unittest.TestCase):
    """A pose motion without rotation is a piecewise-linear translation: /1 certificates
    written by `clash4d check --certificate` verify with the same claim line."""

    SCENE = {"format": "clash4d-scene/1", "time": [0, 4], "objects": [
        {"name": "a", "shape": {"block": {"min": [0, 0, 0], "max": [1, 1, 1]}},
         "motion": {"poses": [{"t": 1, "translate": [0, 0, 0]},
                              {"t": 2, "translate": ["3/2", 0, 0], "rotate": [2, 0, 0, 0]},
                              {"t": 3, "translate": ["3/2", 2, 0]}]}},
        {"name": "b", "shape": {"block": {"min": [2, 0, 0], "max": [3, 1, 1]}}},
        {"name": "c", "shape": {"block": {"min": [5, 0, 0], "max": [6, 1, 1]}},
         "motion": {"poses": [{"t": "1/2", "translate": [-1, 0, 0]}]}}]}

    def test_a_translation_by_poses_verifies_as_clash4d_verify_does(self):
        with tempfile.TemporaryDirectory() as d:
            scene, cert = pathlib.Path(d) / "scene.json", pathlib.Path(d) / "cert.json"
            scene.write_text(json.dumps(self.SCENE))
            for mode in MODES + [["--semantics", "closed", "--all-pairs"]]:
                with self.subTest(mode=" ".join(mode)):
                    p = subprocess.run([BINARY, "check", str(scene), *mode, "--certificate", str(cert)],
                                       capture_output=True, text=True, timeout=600)
                    self.assertIn(p.returncode, (0, 1), p.stderr)
                    self.assertEqual(json.loads(cert.read_text())["format"], "clash4d-certificate/1")
                    cpp = subprocess.run([BINARY, "verify", str(scene), str(cert)],
                                         capture_output=True, text=True, timeout=600)
                    self.assertEqual(cpp.returncode, 0, cpp.stderr)
                    rc, out, err = run_inprocess(scene, cert)
                    self.assertEqual((rc, err), (0, ""))
                    self.assertEqual(out, cpp.stdout)


class Polynomials(unittest.TestCase):
    """The exact polynomial layer of s8.1 (coefficients constant term first)."""

    def setUp(self):
        self.v = clash4d_verify

    def test_sturm_counts_distinct_roots_in_open_intervals(self):
        v, F = self.v, Fraction
        q = [1, -10, 11]                                  # roots (5 -+ sqrt 14)/11 ~ 0.114, 0.795
        self.assertEqual(v.roots_open(q, 0, 1), 2)
        self.assertEqual(v.roots_open(q, F(1, 10), F(1, 8)), 1)
        self.assertEqual(v.roots_open(q, 0, F(1, 10)), 0)
        self.assertEqual(v.roots_open(v.p_mul(q, q), 0, 1), 2)           # distinct roots
        cubic = [0, -1, 0, 1]                             # t^3 - t: roots -1, 0, 1 at and inside ends
        self.assertEqual(v.roots_open(cubic, -1, 1), 1)
        self.assertEqual(v.roots_open(cubic, 0, 1), 0)
        self.assertEqual(v.roots_open(cubic, F(-3, 2), 2), 3)
        self.assertEqual(v.roots_open([1, 0, 1], -10, 10), 0)

    def test_yun_and_the_odd_part(self):
        v, F = self.v, Fraction
        q = [1, -10, 11]
        p = v.p_mul(v.p_mul(q, q), [F(-1, 2), 1])          # (11t^2 - 10t + 1)^2 (t - 1/2)
        self.assertEqual(v.p_yun(p), [[F(-1, 2), 1], v.p_monic(q)])
        self.assertEqual(v.p_odd_part(p), [F(-1, 2), 1])
        self.assertEqual(v.p_odd_part(v.p_mul(q, q)), [1])

    def test_positivity_with_a_double_root(self):
        v, F = self.v, Fraction
        q = [1, -10, 11]
        q2 = v.p_mul(q, q)
        self.assertTrue(v.nonneg_on(q2, 0, 1))
        self.assertFalse(v.nonneg_on(v.p_mul(q2, [F(-1, 2), 1]), 0, 1))
        self.assertFalse(v.positive_on(q2, 0, 1))                         # zero inside
        self.assertTrue(v.nonneg_on([], 0, 1))                            # the zero polynomial
        self.assertFalse(v.nonneg_on([-1], 0, 1))
        tstar = v.Algebraic([1, -10, 11], F(1, 10), F(1, 8))
        self.assertTrue(v.positive_on(q, 0, tstar, open_end=True))        # [0, t*)
        self.assertFalse(v.positive_on(q, 0, tstar))                      # q(t*) = 0
        self.assertTrue(v.nonneg_on(q, 0, tstar))
        self.assertFalse(v.nonneg_on(q, 0, F(1, 8)))
        # a TIME given with a double root: (11t^2 - 10t + 1)^2 in (1/10, 1/8)
        double = v.Algebraic(v.p_mul(q, q), F(1, 10), F(1, 8))
        self.assertEqual(v.cmp_time(double, tstar), 0)
        self.assertEqual(v.roots_between(q, 0, double), 0)
        self.assertEqual(v.roots_between(q, double, 1), 1)
        self.assertEqual(v.roots_between(q, F(1, 20), 1), 2)

    def test_signs_at_algebraic_numbers(self):
        v, F = self.v, Fraction
        r2 = v.Algebraic([-2, 0, 1], 1, 2)                # sqrt 2
        self.assertEqual(v.sign_at([-2, 0, 1], r2), 0)
        self.assertEqual(v.sign_at(v.p_mul([-2, 0, 1], [3, 1]), r2), 0)
        self.assertEqual(v.sign_at([F(-141, 100), 1], r2), 1)
        self.assertEqual(v.sign_at([F(-142, 100), 1], r2), -1)
        self.assertEqual(v.sign_at([-3, 0, 0, 0, 1], r2), 1)                # 4 - 3
        self.assertEqual(v.sign_at([-5, 0, 0, 0, 0, 0, 1], r2), 1)          # 8 - 5
        self.assertEqual(v.sign_at([-9, 0, 0, 0, 0, 0, 1], r2), -1)         # 8 - 9
        self.assertEqual(v.sign_at([], r2), 0)
        self.assertEqual(v.sign_at([1, -10, 11], v.Algebraic([1, -10, 11], F(3, 4), 1)), 0)
        self.assertEqual(v.sign_at([-1, 11], v.Algebraic([1, -10, 11], F(1, 10), F(1, 8))), 1)

    def test_one_number_given_by_two_polynomials(self):
        v, F = self.v, Fraction
        a = v.Algebraic([-2, 0, 1], 1, 2)
        b = v.Algebraic(v.p_mul([-2, 0, 1], [5, 1]), F(7, 5), F(3, 2))     # (t^2 - 2)(t + 5)
        self.assertEqual(v.cmp_time(a, b), 0)
        self.assertEqual(v.cmp_time(b, a), 0)
        c = v.Algebraic([-3, 0, 1], 1, 2)                  # sqrt 3
        self.assertEqual(v.cmp_time(a, c), -1)
        self.assertEqual(v.cmp_time(c, b), 1)
        self.assertEqual(v.cmp_time(a, F(141, 100)), 1)
        self.assertEqual(v.cmp_time(F(3, 2), a), 1)
        # a degree-one poly is a rational: the refinement meets it at a midpoint
        half = v.Algebraic([-1, 2], 0, 1)
        self.assertEqual(v.cmp_time(half, F(1, 2)), 0)
        self.assertEqual(v.cmp_time(v.Algebraic([-1, 2], 0, 1), v.Algebraic([-1, 0, 4], 0, 1)), 0)


if __name__ == "__main__":
    unittest.main()
