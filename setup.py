"""Builds the Python package clash4d with CMake (pyproject.toml; README.md,
"Use it from Python"): configures the project (or reuses CLASH4D_BUILD_DIR),
builds only the target clash4d_python, installs its component "python" into
a staging folder and takes clash4d/_core*.so from there (its RPATH has
$ORIGIN) with libclash4d beside it. Nothing is downloaded.

Environment: CLASH4D_BUILD_DIR, a configured CMake build folder to reuse
(e.g. build: then only what changed is compiled; it must be configured with
an interpreter of this Python's version); CLASH4D_JOBS, cmake --build's -j
(default 1); CLASH4D_CMAKE_ARGS, more arguments for a fresh configure.
"""
import importlib.util
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def version():
    """The project's version, from CMakeLists.txt's project(... VERSION x.y.z)."""
    m = re.search(r"project\(clash4d VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text())
    if not m:
        sys.exit("setup.py: no project(clash4d VERSION ...) in CMakeLists.txt")
    return m.group(1)


def run(command):
    print("setup.py:", " ".join(map(str, command)), flush=True)
    subprocess.run([str(c) for c in command], check=True)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        temp = pathlib.Path(self.build_temp).resolve()
        given = os.environ.get("CLASH4D_BUILD_DIR")
        build = (ROOT / given).resolve() if given else temp / "cmake"
        if not (build / "CMakeCache.txt").is_file():
            if given:
                sys.exit("setup.py: CLASH4D_BUILD_DIR=%s is not a configured CMake build folder" % given)
            run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DCLASH4D_TESTS=OFF",
                 "-DCLASH4D_BENCH=OFF", "-DPython_EXECUTABLE=" + sys.executable]
                + shlex.split(os.environ.get("CLASH4D_CMAKE_ARGS", "")))
        run(["cmake", "--build", build, "-j", os.environ.get("CLASH4D_JOBS", "1"), "--target", "clash4d_python"])
        stage = temp / "stage"
        shutil.rmtree(stage, ignore_errors=True)
        run(["cmake", "--install", build, "--component", "python", "--prefix", stage])
        cores = sorted(stage.glob("**/clash4d/_core*"))
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        if len(cores) != 1 or not cores[0].name.endswith(suffix):
            sys.exit("setup.py: the build made %s, not clash4d/_core%s: was %s configured with another Python "
                     "(its Python_EXECUTABLE)?" % ([c.name for c in cores] or "no module", suffix, build))
        out = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        out.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(cores[0], out)
        # libclash4d.so.X.Y beside _core (found by its RPATH $ORIGIN).
        library = pathlib.Path((build / "python" / "libclash4d-path.txt").read_text().strip())
        shutil.copyfile(library, out.parent / library.name)


# setuptools before 70 makes wheels with the package wheel; without it pip
# fails with "invalid command 'bdist_wheel'": say what is missing first.
if importlib.util.find_spec("wheel") is None:
    print("setup.py: this Python (%s) has no package wheel, which pip install needs here "
          "(Debian: apt-get install python3-wheel; offline, pip install --no-build-isolation "
          "uses this Python's own setuptools and wheel)" % sys.executable, file=sys.stderr)

setup(
    version=version(),
    packages=["clash4d"],
    package_dir={"clash4d": "bindings/python/clash4d"},
    ext_modules=[Extension("clash4d._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # Not setuptools' default build/: that is the CMake build folder by convention.
    options={"build": {"build_base": "build-pip"}},
    zip_safe=False,
)
