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
        rc, _, err = self.tampered(self.APART, [], lambda d: d.update(extra=1))
        self.assertEqual(rc, 1, err)
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


if __name__ == "__main__":
    unittest.main()
