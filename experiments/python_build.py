#!/usr/bin/env python3
"""Building from Python against the CLI, and the cost of the arrays.

    make python
    PYTHONPATH=build/python /usr/bin/python3 experiments/python_build.py [--count N] [--reps R] [--out DIR]

Generates N random ellipses (`ellvor generate ellipses --count N --seed 1 --bits 8
--box 100`, default N = 10^4) into a file and builds its graph R times (default 5)
each way, alternating which goes first: `build/ellvor build FILE` in a child
process, and `ellvor.build(FILE)` in this one. Per build it takes
  - the build's own time, as both report it: the wall time of the insertions
    (`built in X s`, `Diagram.stats["seconds"]`, the same clock around the same call);
  - CPU time of the whole command: the child's (getrusage) against this process's
    for `ellvor.build(FILE)` and freeing the diagram (both read the file, build and
    free; the child also starts and prints its summary).
The Python build must be within 5% of the CLI (medians). Then the time to get each
array of the diagram, per element: NumPy arrays filled in C++, no Python loop. With
--out DIR, writes DIR/python.md. `make bench` runs it with --count 3000 --reps 3.
"""
import argparse
import os
import pathlib
import platform
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import ellvor

ROOT = pathlib.Path(__file__).resolve().parents[1]
CLI = os.environ.get("ELLVOR_BINARY", str(ROOT / "build" / "ellvor"))


def machine():
    model = "unknown"
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    with open("/proc/meminfo") as f:
        mem_kb = int(f.readline().split()[1])
    distro = "unknown"
    if os.path.exists("/etc/os-release"):
        with open("/etc/os-release") as f:
            fields = dict(line.rstrip("\n").split("=", 1) for line in f if "=" in line)
            distro = fields.get("PRETTY_NAME", distro).strip('"')
    return f"{model}, {os.cpu_count()} logical CPUs, {mem_kb / 2**20:.0f} GiB, {distro}"


def source_state():
    def git(*args):
        return subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True, text=True).stdout.strip()
    head = git("rev-parse", "--short", "HEAD") or "unknown"
    return head + (" (uncommitted changes)" if git("status", "--porcelain", "--untracked-files=no") else "")


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_cli(path):
    before = child_cpu()
    out = subprocess.run([CLI, "build", str(path)], check=True, capture_output=True, text=True).stdout
    cpu = child_cpu() - before
    build = float(re.search(r"built in ([0-9.eE+-]+) s", out).group(1))
    return build, cpu


def run_python(path):
    start = time.process_time()
    d = ellvor.build(path)
    build = d.stats["seconds"]
    del d
    return build, time.process_time() - start


def array_costs(path):
    """Seconds to get each array of a fresh diagram (first access: made in C++),
    and its number of elements."""
    d = ellvor.build(path)
    rows = []
    for name in ("hidden", "edges", "faces", "hull", "ridge_points", "vertices"):
        start = time.perf_counter()
        a = getattr(d, name)
        rows.append((name, a.shape, time.perf_counter() - start))
    # For scale: the same edges through a Python loop over elements.
    edges = d.edges.tolist()
    start = time.perf_counter()
    np.array([(int(i), int(j)) for i, j in edges], dtype=np.int64)
    loop = time.perf_counter() - start
    return rows, loop


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--count", type=int, default=10000)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--out", type=pathlib.Path)
    args = ap.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        path = pathlib.Path(tmp) / f"ellipses-{args.count}.ell"
        gen = ["generate", "ellipses", "--count", str(args.count), "--seed", "1", "--bits", "8", "--box", "100"]
        subprocess.run([CLI, *gen, "-o", str(path)], check=True)
        load_before = os.getloadavg()[0]
        runs = {"cli": [], "python": []}
        for rep in range(args.reps):
            order = ("cli", "python") if rep % 2 == 0 else ("python", "cli")
            for who in order:
                runs[who].append(run_cli(path) if who == "cli" else run_python(path))
                print(f"[python_build] rep {rep + 1} {who}: build {runs[who][-1][0]:.3f} s, "
                      f"CPU {runs[who][-1][1]:.3f} s", file=sys.stderr)
        load_after = os.getloadavg()[0]
        arrays, loop = array_costs(path)

    med = {who: [statistics.median(r[k] for r in rows) for k in (0, 1)] for who, rows in runs.items()}
    ratio_build = med["python"][0] / med["cli"][0]
    ratio_cpu = med["python"][1] / med["cli"][1]
    met = ratio_build <= 1.05 and ratio_cpu <= 1.05
    command = "PYTHONPATH=build/python /usr/bin/python3 experiments/python_build.py " + " ".join(sys.argv[1:])
    md = ["# Building from Python against the CLI", "",
          f"{args.count} random ellipses (`ellvor generate {' '.join(gen[1:])}`), built {args.reps} times each "
          "way, alternating which goes first: `build/ellvor build FILE` (a child process) and "
          "`ellvor.build(FILE)` (the module, in the measuring process). *Build* is the wall time of the "
          "insertions as both report it (the same clock around the same call: `built in X s`, "
          "`Diagram.stats[\"seconds\"]`); *CPU* is the CPU time of the whole command: the child's (reading, "
          "building, printing, freeing, plus process start) against `ellvor.build(FILE)` and freeing the diagram "
          "in this process (reading, building, freeing). Medians.", "",
          f"- Machine: {machine()}; Python {platform.python_version()}",
          f"- Load average before / after: {load_before:.2f} / {load_after:.2f}",
          f"- Source: git {source_state()}",
          f"- Command: `make python && {command}`", "",
          "| | build (s), median | build, runs | CPU (s), median | CPU, runs |", "|---|---|---|---|---|"]
    for who, label in (("cli", "CLI `ellvor build`"), ("python", "Python `ellvor.build`")):
        rows = runs[who]
        md.append(f"| {label} | {med[who][0]:.3f} | {', '.join(f'{r[0]:.3f}' for r in rows)} | {med[who][1]:.3f} | "
                  f"{', '.join(f'{r[1]:.3f}' for r in rows)} |")
    md += ["", f"Python / CLI: build {ratio_build:.3f}, CPU {ratio_cpu:.3f} — within 5%: {'met' if met else 'MISSED'}.",
           "", "## Arrays", "",
           "Time to get each array of a fresh diagram of the same set (first access: the array is filled in C++ "
           "and handed to NumPy; no Python loop over its elements), against a Python loop that makes the "
           "edge array from a list of pairs.", "",
           "| array | shape | time (ms) | ns per element |", "|---|---|---|---|"]
    for name, shape, seconds in arrays:
        elements = int(np.prod(shape))
        per_element = f"{1e9 * seconds / elements:.1f}" if elements else "-"
        md.append(f"| `{name}` | {shape} | {1e3 * seconds:.3f} | {per_element} |")
    edges_elements = max(1, 2 * arrays[1][1][0])
    md.append(f"| Python loop, edges | {arrays[1][1]} | {1e3 * loop:.3f} | {1e9 * loop / edges_elements:.1f} |")
    md.append("")
    md.append("The times include making the lists in C++: `edges` and `hull` are the graph's sorted lists, "
              "`ridge_points` (with `ridge_vertices`) numbers the faces and sorts the ridges, and `vertices` "
              "certifies the Voronoi circle of every face (Arb, 53 bits) on first use, as `build --json` does.")
    text = "\n".join(md) + "\n"
    print(text)
    if args.out:
        (args.out / "python.md").write_text(text)
        print(f"[python_build] wrote {args.out / 'python.md'}", file=sys.stderr)
    return 0 if met else 1


if __name__ == "__main__":
    sys.exit(main())
