#!/usr/bin/env python3
"""scripts/check-layering.py on small source trees written here: a clean tree
passes; folders that use each other fail, whether their libraries declare
each other (which the per-include check alone lets through) or a folder sits
on two layers through a subfolder that is a library of its own (as
src/language did with language/commands below src/domains)."""
import pathlib
import subprocess
import sys
import tempfile

script = pathlib.Path(sys.argv[1])


def run(cmake, files):
    with tempfile.TemporaryDirectory() as d:
        root = pathlib.Path(d)
        (root / "CMakeLists.txt").write_text(cmake + "target_link_libraries(clips PRIVATE clips_top)\n")
        for name, includes in files.items():
            f = root / "src" / name
            f.parent.mkdir(parents=True, exist_ok=True)
            f.write_text("".join(f'#include "{i}"\n' for i in includes))
        r = subprocess.run([sys.executable, str(script), str(root)], capture_output=True, text=True)
        return r.returncode, r.stdout


failures = []


def expect(what, ok, out):
    if not ok:
        failures.append(f"{what}:\n{out}")


layers = ("clips_module(clips_base base)\nclips_module(clips_mid mid clips_base)\n"
          "clips_module(clips_top top clips_mid)\n")
rc, out = run(layers, {"base/a.hpp": [], "mid/b.hpp": ["base/a.hpp"], "top/c.hpp": ["mid/b.hpp"],
                       "app/main.cpp": ["top/c.hpp"]})
expect("a clean tree passes", rc == 0 and "0 folder cycles" in out, out)

# Two libraries that declare each other: every include is allowed, the cycle is not.
mutual = "clips_module(clips_a a clips_b)\nclips_module(clips_b b clips_a)\nclips_module(clips_top top clips_a)\n"
rc, out = run(mutual, {"a/x.hpp": ["b/y.hpp"], "b/y.hpp": ["a/x.hpp"], "top/t.hpp": ["a/x.hpp"]})
expect("libraries that use each other fail", rc == 1 and "folders in a cycle: a -> b -> a" in out
       and "src/a/x.hpp:1 includes b/y.hpp" in out and "0 includes across the layering" in out, out)

# lang/words is a library below packs; lang itself is above data, which uses packs.
two_layers = ("clips_module(clips_words lang/words)\nclips_module(clips_packs packs clips_words)\n"
              "clips_module(clips_data data clips_packs)\nclips_module(clips_lang lang clips_data)\n"
              "clips_module(clips_top top clips_lang)\n")
rc, out = run(two_layers, {"lang/words/w.hpp": [], "packs/p.hpp": ["lang/words/w.hpp"], "data/d.hpp": ["packs/p.hpp"],
                           "lang/l.hpp": ["data/d.hpp", "lang/words/w.hpp"], "top/t.hpp": ["lang/l.hpp"]})
expect("a folder on two layers fails", rc == 1 and "folders in a cycle: data -> packs -> lang -> data" in out, out)

for f in failures:
    print("FAILED:", f)
print(f"check_layering_test: {3 - len(failures)} of 3 cases as expected")
sys.exit(1 if failures else 0)
