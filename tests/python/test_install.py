#!/usr/bin/env python3
"""The installed Python package, as a user's Python finds it.

    python3 tests/python/test_install.py CMAKE BUILD_DIR PYTHON_INSTALL_DIR FIXTURES
    python3 tests/python/test_install.py --pip SOURCE_DIR BUILD_DIR FIXTURES

The first runs `cmake --install BUILD_DIR --component python --prefix TMP`
(the package and libclash4d), then a fresh interpreter in isolated mode (-I:
no PYTHONPATH, no user site, not the current folder) that adds only
TMP/PYTHON_INSTALL_DIR as a site directory (what that prefix's Python has on
its path), imports clash4d from there and checks a fixture (ctest:
test_python_install). The second runs `pip install --no-build-isolation
--no-index --target TMP SOURCE_DIR` with CLASH4D_BUILD_DIR=BUILD_DIR (setup.py
then builds only what changed there) under the first interpreter of this
one's version that has pip, setuptools and wheel (this one, else
/usr/bin/python3), and the same check on TMP; exit 77 (skipped) when there is
none (ctest: test_python_pip).
"""
import os
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


SKIP = 77
# Found, not imported (pip's import before setuptools' trips its distutils hack).
HAS_PIP = ("import importlib.util as u, sys; sys.exit(sys.version_info[:2] != (%d, %d) or "
           "not all(u.find_spec(m) for m in ('pip', 'setuptools', 'wheel')))" % sys.version_info[:2])


def import_check(python, site_dir, fixtures, cwd):
    return subprocess.run([python, "-I", "-c", CHILD, str(site_dir), fixtures], cwd=cwd).returncode


def cmake_install(cmake, build, pydir, fixtures):
    with tempfile.TemporaryDirectory() as tmp:
        prefix = pathlib.Path(tmp) / "prefix"
        subprocess.run([cmake, "--install", build, "--component", "python", "--prefix", str(prefix)],
                       check=True, stdout=subprocess.DEVNULL)
        site_dir = prefix / pydir
        if not (site_dir / "clash4d" / "__init__.py").is_file():
            print("test_install: no clash4d/__init__.py under %s" % site_dir, file=sys.stderr)
            return 1
        return import_check(sys.executable, site_dir, fixtures, tmp)


def pip_install(source, build, fixtures):
    pythons = [p for p in (sys.executable, "/usr/bin/python3")
               if os.path.exists(p) and subprocess.run([p, "-I", "-c", HAS_PIP], capture_output=True).returncode == 0]
    if not pythons:
        print("test_install: no Python %d.%d with pip, setuptools and wheel: skipped" % sys.version_info[:2])
        return SKIP
    env = dict(os.environ, CLASH4D_BUILD_DIR=build)
    env.pop("PYTHONPATH", None)
    with tempfile.TemporaryDirectory() as tmp:
        site_dir = pathlib.Path(tmp) / "site"
        subprocess.run([pythons[0], "-m", "pip", "install", "--no-build-isolation", "--no-index", "--no-cache-dir",
                        "--quiet", "--target", str(site_dir), source], check=True, env=env)
        return import_check(pythons[0], site_dir, fixtures, tmp)


def main(argv):
    if argv[1] == "--pip":
        return pip_install(*argv[2:5])
    return cmake_install(*argv[1:5])


if __name__ == "__main__":
    sys.exit(main(sys.argv))
