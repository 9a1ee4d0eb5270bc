#!/usr/bin/env python3
"""Every #include "dir/..." under src/ stays inside the layering CMakeLists.txt declares.

Each clips_module(NAME DIR DEPS...) line makes src/DIR a library that may use
DEPS and what they use in turn. A library links only what it lists, but a
header-only use of a higher layer would pass the linker unnoticed; this check
reads the includes themselves. src/app (the clips executable) may use the
libraries its target_link_libraries line names.

It also checks the folders as a graph: no two folders under src/ may use
each other, directly or round a cycle. It does so twice: with each library
a node (a subfolder that is a library of its own, such as domains/dkg, is
its own node), and with each top-level folder a node (domains/dkg counts as
domains), so that a folder never sits on two layers, as language/ did when
its subfolders were below domains/ and the rest above data/.

Exit 1 listing each include that crosses the layering and each cycle (with
one include for each of its arrows); 0 when there is none.
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

# ---- the folder graph ----------------------------------------------------------------
# Every source file under src/, also in folders that are no library (serve/http),
# belongs to its longest library folder, else to its top-level folder.
def node_of(path, top_level):
    name = module_of(path)
    folder = dir_of[name] if name else path.split("/")[0]
    return folder.split("/")[0] if top_level else folder


src = root / "src"
src_folders = {p.name for p in src.iterdir() if p.is_dir()}
includes = []  # (file, line, from folder path, included path)
for f in sorted(src.rglob("*.[ch]pp")):
    rel = f.relative_to(src).as_posix()
    for n, line in enumerate(f.read_text(encoding="utf-8").splitlines(), 1):
        m = re.match(r'\s*#include "([^"]+)"', line)
        if m and m.group(1).split("/")[0] in src_folders:
            includes.append((f.relative_to(root).as_posix(), n, rel, m.group(1)))


def cycles(top_level):
    """The graph's strongly connected components of more than one node, each
    as a cycle through all of its nodes, with one include per arrow."""
    edges = {}
    for file, n, rel, inc in includes:
        a, b = node_of(rel, top_level), node_of(inc, top_level)
        if a != b:
            edges.setdefault(a, {}).setdefault(b, f"{file}:{n} includes {inc}")
    # Tarjan's algorithm, iteratively.
    index, low, on_stack, stack, comps = {}, {}, set(), [], []
    for start in sorted(set(edges) | {b for e in edges.values() for b in e}):
        if start in index:
            continue
        work = [(start, iter(sorted(edges.get(start, {}))))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            v, it = work[-1]
            w = next(it, None)
            if w is None:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[v])
                if low[v] == index[v]:
                    comp = []
                    while True:
                        x = stack.pop()
                        on_stack.discard(x)
                        comp.append(x)
                        if x == v:
                            break
                    if len(comp) > 1:
                        comps.append(sorted(comp))
            elif w not in index:
                index[w] = low[w] = len(index)
                stack.append(w)
                on_stack.add(w)
                work.append((w, iter(sorted(edges.get(w, {})))))
            elif w in on_stack:
                low[v] = min(low[v], index[w])
    found = []
    for comp in comps:
        # A shortest way from the component's first node back to itself.
        first, members = comp[0], set(comp)
        prev, queue = {first: None}, [first]
        back = None
        for v in queue:
            for w in sorted(edges.get(v, {})):
                if w == first and back is None:
                    back = v
                if w in members and w not in prev:
                    prev[w] = v
                    queue.append(w)
        path = [back]
        while prev[path[-1]] is not None:
            path.append(prev[path[-1]])
        path.reverse()
        path.append(first)
        arrows = [f"  {a} -> {b}: {edges[a][b]}" for a, b in zip(path, path[1:])]
        found.append(f"folders in a cycle: {' -> '.join(path)}\n" + "\n".join(arrows))
    return found


loops = cycles(top_level=False) + [c for c in cycles(top_level=True)]
for b in bad + loops:
    print(b)
print(f"check-layering: {len(dir_of)} libraries, {len(bad)} includes across the layering, "
      f"{len(loops)} folder cycles")
sys.exit(1 if bad or loops else 0)
