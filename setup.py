"""Builds clips_assist._core with this project's CMake for the interpreter
running setup.py (pip), and puts the data the library reads (language
corpora, domain packs, the paper's tables, the example dataset) in the
package, as clips_assist/data. Metadata: pyproject.toml.

Environment: CLIPS_PIP_BUILD_DIR (the CMake build folder, default
build-pip-<SOABI> beside build/: at the same depth, so ccache (with
CCACHE_BASEDIR above the checkout, as the Makefile sets) serves the objects
`make build` compiled), CLIPS_PIP_JOBS (parallel jobs, default 2)."""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
VERSION = re.search(r"project\(clips VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)
# What the installed package carries under clips_assist/data (as share/clips-assist).
DATA = ["language", "paper", "domains", "schema", "examples/doors-keys-gems"]


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        tag = sysconfig.get_config_var("SOABI") or f"py{sys.version_info[0]}{sys.version_info[1]}"
        build = pathlib.Path(os.environ.get("CLIPS_PIP_BUILD_DIR", ROOT / f"build-pip-{tag}"))
        build.mkdir(parents=True, exist_ok=True)
        jobs = os.environ.get("CLIPS_PIP_JOBS", "2")
        args = [f"-DPython3_EXECUTABLE={sys.executable}", "-DCMAKE_BUILD_TYPE=Release", "-DCLIPS_BUILD_TESTS=OFF",
                "-DCLIPS_BUILD_BENCH=OFF", "-DCLIPS_SOURCE_DATA=OFF"]
        try:  # pybind11 from pip (an isolated build) rather than Debian's pybind11-dev
            import pybind11
            args.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
        except ImportError:
            pass
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), *args], check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "clips_assist_python", "-j", jobs], check=True)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = build / "python" / "clips_assist" / f"_core{suffix}"
        if not built.exists():
            raise RuntimeError(f"CMake did not build {built}")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)
        # The data, beside the module (the library looks in <module dir>/data).
        data = target.parent / "data"
        if data.exists():
            shutil.rmtree(data)
        for part in DATA:
            shutil.copytree(ROOT / "data" / part, data / part, ignore=shutil.ignore_patterns("*.py", "__pycache__"))


setup(version=VERSION, ext_modules=[Extension("clips_assist._core", sources=[])], cmdclass={"build_ext": CMakeBuild},
      # setuptools' own staging, out of the CMake build folder build/.
      options={"build": {"build_base": "build-pip-setuptools"}})
