#!/usr/bin/env python3
"""The installed Python package, as a user's Python finds it.

    python3 tests/python/test_install.py CMAKE BUILD_DIR PYTHON_INSTALL_DIR FIXTURES

Runs `cmake --install BUILD_DIR --component python --prefix TMP` (the
package and libclash4d), then a fresh interpreter in isolated mode (-I: no
PYTHONPATH, no user site, not the current folder) that adds only
TMP/PYTHON_INSTALL_DIR as a site directory (what that prefix's Python has on
its path), imports clash4d from there and checks a fixture. Run by ctest as
test_python_install.
"""
import pathlib
import subprocess
import sys
import tempfile

CHILD = r"""
import site, sys
from fractions import Fraction
site.addsitedir(sys.argv[1])
import clash4d
assert clash4d.__file__.startswith(sys.argv[1]), clash4d.__file__   # the installed copy, not the build tree's
# a's face x = 1 + t meets b's x = 5 - t at t* = 2, x = 3 (the fixture's name says t = 2).
r = clash4d.check(sys.argv[2] + "/contact/clear_collision_head_on.json", earliest=True)
assert isinstance(r, clash4d.Answer) and r.collide and r.objects == ("a", "b"), r
assert r.t == 2 and isinstance(r.t, Fraction), r.t
assert r.earliest.x == 3 and r.earliest.t == 2 and len(r.earliest) == 4, r.earliest
print("installed clash4d %s at %s: %r" % (clash4d.__version__, clash4d.__file__, r))
"""


def main(argv):
    cmake, build, pydir, fixtures = argv[1:5]
    with tempfile.TemporaryDirectory() as tmp:
        prefix = pathlib.Path(tmp) / "prefix"
        subprocess.run([cmake, "--install", build, "--component", "python", "--prefix", str(prefix)],
                       check=True, stdout=subprocess.DEVNULL)
        site_dir = prefix / pydir
        if not (site_dir / "clash4d" / "__init__.py").is_file():
            print("test_install: no clash4d/__init__.py under %s" % site_dir, file=sys.stderr)
            return 1
        return subprocess.run([sys.executable, "-I", "-c", CHILD, str(site_dir), fixtures], cwd=tmp).returncode


if __name__ == "__main__":
    sys.exit(main(sys.argv))
