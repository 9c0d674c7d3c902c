"""setuptools' half of pyproject.toml: builds the C++ extension hapstab._core with CMake.

    HAPSTAB_BUILD_DIR=DIR   reuse the CMake build folder DIR (e.g. build, already configured by
                            scripts/test or cmake -S . -B build): only hapstab_python is built there,
                            so an up-to-date folder costs the link of one module, not the library.
    (unset)                 configure a folder of its own under setuptools' build_temp (Release,
                            no tests, no benchmarks) and build the library and the module: minutes.
    HAPSTAB_JOBS=N          parallel compile jobs (default: the CPU count).

The extension must be built for the interpreter that installs it (CMake uses /usr/bin/python3
unless Python3_EXECUTABLE is given: a fresh folder is configured with this interpreter); a
module built for another Python is refused by name. An interpreter that cannot build offline (no
`wheel` or no `numpy` where --no-build-isolation --no-index looks: a pyenv or conda python3 first
on PATH) is named at once with the command that works (README, "Python"), before setuptools
would stop with a bare "invalid command 'bdist_wheel'".
"""
import importlib.machinery
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Optional

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent


def check_interpreter() -> None:
    """Stops with a message naming this interpreter when it lacks what an offline build needs."""
    import importlib.util
    missing = [m for m in ("wheel", "numpy") if importlib.util.find_spec(m) is None]
    if not missing:
        return
    debian = "/usr/bin/python3"
    sys.exit(f"hapstab: this Python ({sys.executable}, {sys.version.split()[0]}) has no {' and no '.join(missing)}, so "
             "pip cannot build and install hapstab offline (--no-build-isolation --no-index uses what this interpreter "
             "already has). hapstab builds with Debian's Python and its packages (scripts/install-deps: "
             "python3-wheel, python3-numpy, pybind11-dev); a python3 first on PATH may be another one (pyenv, conda). "
             f"Use Debian's, by its full name:\n  {debian} -m venv --system-site-packages venv\n"
             "  HAPSTAB_BUILD_DIR=build venv/bin/pip install --no-build-isolation --no-index .")


def given_build_dir() -> Optional[Path]:
    """HAPSTAB_BUILD_DIR as a folder (relative: to the top of the tree), None when unset; stops
    with one line saying what to run when it is not a configured CMake build folder (README's pip
    block copied onto a fresh clone, before any build)."""
    given = os.environ.get("HAPSTAB_BUILD_DIR")
    if not given:
        return None
    build = Path(given) if os.path.isabs(given) else SOURCE / given
    if not (build / "CMakeCache.txt").is_file():
        sys.exit(f"hapstab: HAPSTAB_BUILD_DIR={given}: {build} is not a configured CMake build folder yet: run "
                 f"`cmake -S . -B {given} -DCMAKE_BUILD_TYPE=Release` first (pip then builds the module there, "
                 "minutes the first time), or leave HAPSTAB_BUILD_DIR out")
    return build


def version() -> str:
    m = re.search(r"project\(hapstab VERSION (\S+)", (SOURCE / "CMakeLists.txt").read_text(encoding="utf-8"))
    if not m:
        raise RuntimeError("setup.py: no project(hapstab VERSION ...) in CMakeLists.txt")
    return m.group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        build = given_build_dir()
        jobs = os.environ.get("HAPSTAB_JOBS", str(os.cpu_count() or 1))
        if build is None:
            build = Path(self.build_temp).resolve() / "cmake"
            # a new folder with Ninja when it is installed, as scripts/generator-env says why
            env = dict(os.environ)
            if not env.get("CMAKE_GENERATOR") and shutil.which("ninja"):
                env["CMAKE_GENERATOR"] = "Ninja"
            subprocess.check_call(["cmake", "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                                   "-DHAPSTAB_TESTS=OFF", "-DHAPSTAB_BENCH=OFF", "-DHAPSTAB_PYTHON=ON",
                                   f"-DPython3_EXECUTABLE={sys.executable}"], env=env)
        cache = (build / "CMakeCache.txt").read_text(encoding="utf-8", errors="replace")
        if not re.search(r"^HAPSTAB_PYTHON:BOOL=ON$", cache, re.M):
            raise RuntimeError(f"{build}: the Python module is off there (HAPSTAB_PYTHON=OFF, or pybind11 was not "
                               "found: Debian pybind11-dev python3-dev)")
        subprocess.check_call(["cmake", "--build", str(build), "--target", "hapstab_python", "-j", jobs])
        package = build / "python" / "hapstab"
        suffix = importlib.machinery.EXTENSION_SUFFIXES[0]
        built = package / f"_core{suffix}"
        if not built.is_file():
            found = ", ".join(p.name for p in package.glob("_core*")) or "nothing"
            raise RuntimeError(f"{package}: no _core{suffix} for this Python ({sys.executable}); found {found}. "
                               "Configure the build folder with -DPython3_EXECUTABLE=<this python>.")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


check_interpreter()
given_build_dir()
(SOURCE / "build-pip").mkdir(exist_ok=True)
setup(
    version=version(),
    ext_modules=[Extension("hapstab._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own folders, apart from CMake's build/ (in-tree builds are pip's default)
    options={"build": {"build_base": "build-pip"}, "egg_info": {"egg_base": "build-pip"}},
)
