"""The PEP 517 build backend of clips-assist: pip builds the wheel with it.

It needs nothing from PyPI (``requires = []``): no setuptools, no wheel, no
scikit-build-core. CMake (with the Debian packages scripts/install-deps.sh
names, pybind11-dev among them) compiles only the Python module,
clips_assist._core, for the interpreter running pip; the standard library's
zipfile writes the wheel, which carries the package, the stubs and the data
the library reads (clips_assist/data). Any CPython 3.9 or later works: pyenv,
conda, Debian's, a venv of any of them.

Environment: CLIPS_PIP_BUILD_DIR (the CMake build folder; default
build-pip-<SOABI>-<interpreter> in the source tree, kept so a second build is
quick, and at the depth of build/ so that ccache shares objects with it), CLIPS_PIP_JOBS
(parallel compile jobs; default: every core). `pip install -v` shows every
compile step; without -v a line per tenth of the build goes to the terminal.

Run as a script, ``python3 clips_backend.py dist-info DIR`` writes the
package's dist-info folder (METADATA, top_level.txt) into DIR: the Debian
package installs it beside the module.
"""
import base64
import hashlib
import io
import os
import pathlib
import re
import subprocess
import sys
import sysconfig
import tarfile
import time
import zipfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
NAME = "clips-assist"
PACKAGE = "clips_assist"
# What the installed package carries under clips_assist/data (as share/clips-assist does).
DATA = ["language", "paper", "domains", "schema", "examples/doors-keys-gems"]
SUMMARY = "Goal inference from a human's actions and instructions, and assistance (CLIPS, AAMAS 2024)"
CLASSIFIERS = [
    "Programming Language :: C++",
    "Programming Language :: Python :: 3",
    "License :: OSI Approved :: MIT License",
    "Operating System :: POSIX :: Linux",
    "Topic :: Scientific/Engineering :: Artificial Intelligence",
]
URLS = [("Paper", "https://arxiv.org/abs/2402.17930"),
        ("Reference implementation", "https://github.com/probcomp/CLIPS.jl")]


def version():
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    return re.search(r"project\(clips VERSION ([0-9.]+)", text).group(1)


def dist_info_name():
    return f"{PACKAGE}-{version()}.dist-info"


def metadata():
    lines = ["Metadata-Version: 2.1", f"Name: {NAME}", f"Version: {version()}", f"Summary: {SUMMARY}",
             "Author: The clips-assist authors", "License: MIT", "Requires-Python: >=3.9"]
    lines += [f"Classifier: {c}" for c in CLASSIFIERS]
    lines += [f"Project-URL: {label}, {url}" for label, url in URLS]
    lines.append("Description-Content-Type: text/markdown")
    return "\n".join(lines) + "\n\n" + (ROOT / "README.md").read_text(encoding="utf-8")


def write_dist_info(folder):
    """METADATA and top_level.txt in folder/<name>.dist-info; returns that folder's name."""
    out = pathlib.Path(folder) / dist_info_name()
    out.mkdir(parents=True, exist_ok=True)
    (out / "METADATA").write_text(metadata(), encoding="utf-8")
    (out / "top_level.txt").write_text(PACKAGE + "\n", encoding="utf-8")
    return out.name


def wheel_tag():
    if sys.implementation.name != "cpython":
        raise RuntimeError(f"clips-assist builds for CPython only, not {sys.implementation.name}")
    soabi = sysconfig.get_config_var("SOABI") or ""
    # "cpython-311-x86_64-linux-gnu" -> cp311 ("313t" for a free-threaded 3.13).
    abi = "cp" + (soabi.split("-")[1] if soabi.startswith("cpython-") else f"{sys.version_info[0]}{sys.version_info[1]}")
    python = f"cp{sys.version_info[0]}{sys.version_info[1]}"
    platform = re.sub(r"[^A-Za-z0-9]", "_", sysconfig.get_platform())
    return f"{python}-{abi}-{platform}"


def say(line, tty):
    print(line, file=sys.stderr, flush=True)
    if tty is not None:
        tty.write(line + "\n")
        tty.flush()


def open_tty():
    """The terminal, when there is one: pip shows a hook's output only with -v."""
    if os.environ.get("CLIPS_PIP_QUIET"):
        return None
    try:
        return open("/dev/tty", "w")
    except OSError:
        return None


def run_cmake(args, tty, progress):
    """Runs cmake, its output to stderr; with `progress`, a line per tenth of the build on the terminal."""
    start = time.monotonic()
    shown = -10
    proc = subprocess.Popen(["cmake", *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            errors="replace", bufsize=1)
    tail = []
    for line in proc.stdout:
        sys.stderr.write(line)
        tail = (tail + [line])[-40:]
        m = re.match(r"\[\s*(\d+)%\]", line)
        if progress and m and int(m.group(1)) >= shown + 10 and tty is not None:
            shown = int(m.group(1)) // 10 * 10
            tty.write(f"clips-assist: compiling the Python module: {m.group(1)}% "
                      f"({time.monotonic() - start:.0f} s)\n")
            tty.flush()
    if proc.wait() != 0:
        raise RuntimeError(f"cmake {' '.join(args)} failed (exit {proc.returncode}); its last lines:\n" + "".join(tail))


def build_module():
    """Configures and builds clips_assist_python only; returns the CMake build folder."""
    tty = open_tty()
    # One folder per base interpreter: venvs of one Python share it, and
    # pyenv's 3.11 and Debian's 3.11 (the same SOABI) do not.
    soabi = sysconfig.get_config_var("SOABI") or f"py{sys.version_info[0]}{sys.version_info[1]}"
    base = hashlib.sha256(os.path.realpath(sys.base_prefix).encode()).hexdigest()[:8]
    build = pathlib.Path(os.environ.get("CLIPS_PIP_BUILD_DIR") or ROOT / f"build-pip-{soabi}-{base}")
    build.mkdir(parents=True, exist_ok=True)
    jobs = os.environ.get("CLIPS_PIP_JOBS") or str(os.cpu_count() or 2)
    env_note = "" if os.environ.get("CCACHE_BASEDIR") else " (ccache base: the folder above the source tree)"
    os.environ.setdefault("CCACHE_BASEDIR", str(ROOT.parent))
    say(f"clips-assist: building the Python module for {sys.executable} ({sys.version.split()[0]}) in {build}, "
        f"{jobs} jobs{env_note}; a first build takes a few minutes", tty)
    run_cmake(["-S", str(ROOT), "-B", str(build), f"-DPython3_EXECUTABLE={sys.executable}",
               "-DCMAKE_BUILD_TYPE=Release", "-DCLIPS_BUILD_TESTS=OFF", "-DCLIPS_BUILD_BENCH=OFF",
               "-DCLIPS_SOURCE_DATA=OFF"], tty, progress=False)
    run_cmake(["--build", str(build), "--target", "clips_assist_python", "-j", jobs], tty, progress=True)
    if tty is not None:
        tty.close()
    return build


def package_files(build):
    """(path in the wheel, file on disk) of the package: module, Python files, stubs, data."""
    built = build / "python" / PACKAGE
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    module = built / f"_core{suffix}"
    if not module.is_file():
        raise RuntimeError(f"CMake built no {module}")
    files = [(f"{PACKAGE}/{module.name}", module)]
    for f in sorted((ROOT / "python" / PACKAGE).iterdir()):
        if f.is_file() and (f.suffix in (".py", ".pyi") or f.name == "py.typed"):
            files.append((f"{PACKAGE}/{f.name}", f))
    for part in DATA:
        for f in sorted((ROOT / "data" / part).rglob("*")):
            if f.is_file() and f.suffix != ".py" and "__pycache__" not in f.parts:
                files.append((f"{PACKAGE}/data/{f.relative_to(ROOT / 'data').as_posix()}", f))
    return files


def record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def write_wheel(folder, files, tag):
    """The wheel of `files` (path in the wheel, bytes or a file) with its dist-info; returns its name."""
    dist = dist_info_name()
    wheel_meta = f"Wheel-Version: 1.0\nGenerator: clips_backend {version()}\nRoot-Is-Purelib: false\nTag: {tag}\n"
    entries = [(name, src.read_bytes() if isinstance(src, pathlib.Path) else src) for name, src in files]
    entries += [(f"{dist}/METADATA", metadata().encode()), (f"{dist}/WHEEL", wheel_meta.encode()),
                (f"{dist}/top_level.txt", (PACKAGE + "\n").encode()),
                (f"{dist}/LICENSE", (ROOT / "LICENSE").read_bytes())]
    record = "\n".join(record_line(n, d) for n, d in entries) + f"\n{dist}/RECORD,,\n"
    entries.append((f"{dist}/RECORD", record.encode()))
    name = f"{PACKAGE}-{version()}-{tag}.whl"
    with zipfile.ZipFile(pathlib.Path(folder) / name, "w", zipfile.ZIP_DEFLATED) as z:
        for n, d in entries:
            info = zipfile.ZipInfo(n, date_time=(2024, 1, 1, 0, 0, 0))
            info.external_attr = (0o755 if n.endswith(".so") else 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, d)
    return name


# ---- the PEP 517 hooks ------------------------------------------------------------------

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    return write_dist_info(metadata_directory)


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    build = build_module()
    return write_wheel(wheel_directory, package_files(build), wheel_tag())


def build_sdist(sdist_directory, config_settings=None):
    """The tracked files of the source tree (git ls-files; without git, every file outside build folders)."""
    base = f"{PACKAGE}-{version()}"
    try:
        names = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, check=True, capture_output=True).stdout
        paths = [p for p in names.decode().split("\0") if p and (ROOT / p).is_file()]
    except (OSError, subprocess.CalledProcessError):
        paths = [p.relative_to(ROOT).as_posix() for p in ROOT.rglob("*")
                 if p.is_file() and not p.relative_to(ROOT).parts[0].startswith(("build", ".git"))]
    name = f"{base}.tar.gz"
    with tarfile.open(pathlib.Path(sdist_directory) / name, "w:gz", format=tarfile.PAX_FORMAT) as tar:
        for p in sorted(paths):
            tar.add(ROOT / p, arcname=f"{base}/{p}", recursive=False)
        pkg_info = metadata().encode()
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        info.size = len(pkg_info)
        info.mtime = int(time.time())
        tar.addfile(info, io.BytesIO(pkg_info))
    return name


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "dist-info":
        write_dist_info(sys.argv[2])
    else:
        sys.exit("usage: clips_backend.py dist-info DIR")
