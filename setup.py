"""Builds the Python package pgm: the extension pgm._core by CMake (the same target as
`cmake --build build --target pgm_python`), the pure-Python files from python/pgm, and the task
and scenario files the package needs at run time, in pgm/tasks.

PGM_CMAKE_BUILD_DIR names a build tree to configure and build in (default: build/python-package);
an existing tree is configured again and reused, so a second install compiles nothing.
PGM_CMAKE_ARGS adds arguments to the configure step (e.g. "-DPGM_BUILD_BULLET=OFF").
"""

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

SOURCE_DIR = Path(__file__).resolve().parent


def project_version():
    """The C++ project's version, from the top-level CMakeLists.txt: one number for both."""
    text = (SOURCE_DIR / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(pgm VERSION ([0-9.]+)", text)
    if not match:
        raise RuntimeError("CMakeLists.txt: no 'project(pgm VERSION x.y.z' line")
    return match.group(1)


class CMakeExtension(Extension):
    def __init__(self, name, target):
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    """Configures the project for this interpreter and builds the module's target alone."""

    def build_extension(self, ext):
        build_dir = Path(os.environ.get("PGM_CMAKE_BUILD_DIR", SOURCE_DIR / "build" / "python-package")).resolve()
        configure = [
            "cmake",
            "-S", str(SOURCE_DIR),
            "-B", str(build_dir),
            "-G", "Ninja",
            "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython3_EXECUTABLE={sys.executable}",
            "-DPGM_BUILD_PYTHON=ON",
            "-DPGM_BUILD_TESTS=OFF",
            "-DPGM_BUILD_BENCH=OFF",
            "-DPGM_INSTALL=OFF",
            *shlex.split(os.environ.get("PGM_CMAKE_ARGS", "")),
        ]
        # Configuring again is quick, and names this interpreter even in a tree made for another.
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", ext.target], check=True)
        built = sorted((build_dir / "python" / "pgm").glob("_core*.so"))
        if not built:
            raise RuntimeError(f"CMake built no pgm/_core*.so in {build_dir}")
        destination = Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], destination)


class BuildWithTasks(build_py):
    """The Python files, and the tasks and scenarios copied into pgm/tasks."""

    def run(self):
        super().run()
        tasks = Path(self.build_lib) / "pgm" / "tasks"
        shutil.rmtree(tasks, ignore_errors=True)
        shutil.copytree(SOURCE_DIR / "tasks", tasks, ignore=shutil.ignore_patterns("*.md"))


# setuptools' own files go beside CMake's, not into the source tree.
SETUPTOOLS_DIR = SOURCE_DIR / "build" / "setuptools"
SETUPTOOLS_DIR.mkdir(parents=True, exist_ok=True)

setup(
    version=project_version(),
    options={"build": {"build_base": str(SETUPTOOLS_DIR)}, "egg_info": {"egg_base": str(SETUPTOOLS_DIR)}},
    packages=["pgm"],
    package_dir={"pgm": "python/pgm"},
    package_data={"pgm": ["py.typed", "*.pyi"]},
    ext_modules=[CMakeExtension("pgm._core", target="pgm_python")],
    cmdclass={"build_ext": CMakeBuild, "build_py": BuildWithTasks},
    zip_safe=False,
)
