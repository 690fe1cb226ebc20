"""The Python package measured side by side with the library it wraps and with Python's own
XML parser, in one run, as docs/python.md reports it:

    python python/bench/load.py SCENE.xml [--wheel WHEEL] [--runs N]

SCENE.xml is the benchmark scene (bench/generate 10000 SCENE.xml writes the 10 000-body
one, about 9.7 MB). Times are medians of N rounds (default 7) in this process, the loads
interleaved within each round: the library's own load (the extension's load of the path,
the records left in the library), box2scene.load (the same load and the Scene over it),
box2scene.load with every record tuple then made, scene.arrays(), and
xml.etree.ElementTree.parse of the same file. Peak memory is the highest resident set
(VmHWM) of a fresh process doing one of these loads, less that process's before it (its
interpreter and imports). With --wheel: the wheel's size, its extension's size and the time
pip takes to install it (no dependencies, from the file) into a fresh virtual environment.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
import venv
import zipfile
from typing import Callable, Dict, List

LOADS = {
    "library load (extension, records in Rust)": "box2scene._native.load_path(path, {})",
    "box2scene.load": "box2scene.load(path)",
    "box2scene.load + every record tuple": "touch(box2scene.load(path))",
    "box2scene.load + arrays()": "box2scene.load(path).arrays()",
    "xml.etree.ElementTree.parse": "xml.etree.ElementTree.parse(path)",
}

# VmHWM, not getrusage: a child's ru_maxrss starts at its parent's on Linux.
PRELUDE = """
import sys, xml.etree.ElementTree
import box2scene, box2scene._native
path = sys.argv[1]
def touch(scene):
    for name in ("shapes", "fixtures", "bodies", "joints", "vertices", "fixture_ids", "user_data", "diagnostics"):
        getattr(scene, name)
    return scene
def peak_kb():
    with open("/proc/self/status") as f:
        return next(int(line.split()[1]) for line in f if line.startswith("VmHWM:"))
before = peak_kb()
kept = {load}
print(peak_kb() - before)
"""


def medians_ms(runs_of: Dict[str, Callable[[], object]], rounds: int) -> Dict[str, float]:
    """The median time of each, the runs interleaved within each round (each going first in
    turn), so that a busy machine slows all of them alike."""
    times: Dict[str, List[float]] = {name: [] for name in runs_of}
    names = list(runs_of)
    for r in range(rounds):
        for name in names[r % len(names) :] + names[: r % len(names)]:
            start = time.perf_counter()
            runs_of[name]()
            times[name].append(time.perf_counter() - start)
    return {name: 1000 * statistics.median(t) for name, t in times.items()}


def peak_mb(load: str, path: str) -> float:
    out = subprocess.run([sys.executable, "-c", PRELUDE.format(load=load), path], capture_output=True, text=True, check=True)
    return int(out.stdout) / 1024


def wheel_rows(wheel: str) -> List[str]:
    with zipfile.ZipFile(wheel) as z:
        extension = next(i for i in z.infolist() if i.filename.endswith(".so"))
    with tempfile.TemporaryDirectory() as env:
        venv.create(env, with_pip=True)
        start = time.perf_counter()
        subprocess.run([os.path.join(env, "bin", "python"), "-m", "pip", "install", "--quiet", "--no-deps", "--no-index", wheel], check=True)
        install = time.perf_counter() - start
    return [
        f"| wheel | {os.path.getsize(wheel) / 1e6:.2f} MB |",
        f"| extension (`_native.abi3.so`) | {extension.file_size / 1e6:.2f} MB |",
        f"| `pip install` of the wheel into a fresh environment | {install:.2f} s |",
    ]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene")
    parser.add_argument("--wheel")
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args()
    import xml.etree.ElementTree  # noqa: F401 (the loads below name it)

    import box2scene
    import box2scene._native

    def touch(scene: box2scene.Scene) -> box2scene.Scene:
        for name in ("shapes", "fixtures", "bodies", "joints", "vertices", "fixture_ids", "user_data", "diagnostics"):
            getattr(scene, name)
        return scene

    path = args.scene
    names = {"box2scene": box2scene, "xml": xml, "touch": touch, "path": path}
    print(f"{os.path.basename(path)}: {os.path.getsize(path) / 1e6:.1f} MB, Python {sys.version.split()[0]}, {os.cpu_count()} cores\n")
    print("| load | median time | over the library's | peak memory |")
    print("|---|---|---|---|")
    runs_of = {name: (lambda load=load: eval(load, names)) for name, load in LOADS.items()}
    medians = medians_ms(runs_of, args.runs)
    library = next(iter(medians.values()))
    for name, load in LOADS.items():
        ms = medians[name]
        print(f"| {name} | {ms:.1f} ms | {ms / library:.2f}x | {peak_mb(load, path):.1f} MB |")
    if args.wheel:
        print("\n| the wheel | |\n|---|---|")
        print("\n".join(wheel_rows(args.wheel)))


if __name__ == "__main__":
    main()
