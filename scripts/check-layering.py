#!/usr/bin/env python3
"""Every #include "dir/..." under src/ stays inside the layering CMakeLists.txt declares.

Each clips_module(NAME DIR DEPS...) line makes src/DIR a library that may use
DEPS and what they use in turn. A library links only what it lists, but a
header-only use of a higher layer would pass the linker unnoticed; this check
reads the includes themselves. src/app (the clips executable) may use the
libraries its target_link_libraries line names. Exit 1 listing each include
that crosses the layering; 0 when there is none.
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[1])
cmake = (root / "CMakeLists.txt").read_text(encoding="utf-8")

deps, dir_of = {}, {}
for name, folder, rest in re.findall(r"^clips_module\((\w+)\s+([\w/]+)\s*([^)]*)\)", cmake, re.M):
    dir_of[name] = folder
    deps[name] = [d for d in rest.split() if d.startswith("clips_")]
app = re.search(r"^target_link_libraries\(clips PRIVATE ([^)]*)\)", cmake, re.M)
if not dir_of or not app:
    sys.exit("check-layering: CMakeLists.txt has no clips_module lines or no clips target")
dir_of["clips_app"] = "app"
deps["clips_app"] = [d for d in app.group(1).split() if d.startswith("clips_")]


def closure(name, seen=None):
    seen = set() if seen is None else seen
    for d in deps.get(name, []):
        if d not in seen:
            seen.add(d)
            closure(d, seen)
    return seen


# An include path belongs to the module with the longest folder it starts with.
folders = sorted(dir_of.items(), key=lambda kv: -len(kv[1]))


def module_of(path):
    for name, folder in folders:
        if path.startswith(folder + "/"):
            return name
    return None


bad = []
for name, folder in dir_of.items():
    allowed = closure(name) | {name}
    for f in sorted((root / "src" / folder).glob("*.[ch]pp")):
        for n, line in enumerate(f.read_text(encoding="utf-8").splitlines(), 1):
            m = re.match(r'\s*#include "([^"]+)"', line)
            if not m:
                continue
            used = module_of(m.group(1))
            if used is not None and used not in allowed:
                bad.append(f"{f.relative_to(root)}:{n}: {folder} includes {m.group(1)} "
                           f"({dir_of[used]}), which it does not depend on")
for b in bad:
    print(b)
print(f"check-layering: {len(dir_of)} libraries, {len(bad)} includes across the layering")
sys.exit(1 if bad else 0)
