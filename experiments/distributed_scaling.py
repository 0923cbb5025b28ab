#!/usr/bin/env python3
"""The tiled build on dask.distributed against the single build.

    make python
    PYTHONPATH=build/python /usr/bin/python3 experiments/distributed_scaling.py [--count N] [--full]
        [--packing P] [--cells C] [--cell-tiles 2x2,4x4,8x8] [--workers W] [--tiles 2x1,2x2,4x4,8x8] [--full-tiles 4x4] [--out DIR]

N random ellipses (`ellvor.generate("ellipses", N, seed=1)`, default N = 10^5; --full adds 10^6, in the
--full-tiles tilings) and a dense packing of P sites (`ellvor.generate("packing", P, seed=1,
packing_fraction=0.6)`, default P = 10^5; 0: none):
  - the single build, `ellvor.build(sites)`, in a child process: its wall time (insertions only, and the
    whole call) and the child's peak resident memory;
  - per tile count, `ellvor.distributed.build(sites, tiles, client)` on a fresh `ellvor.distributed.local_cluster(W)` of W worker
    processes (default 2, one thread each): wall time of the call (client work, shipping, tiles, hull),
    speed-up against the single build's whole call, peak resident memory of each worker process,
    halo overhead (halo sites / owned sites over all tiles), hull candidates, retry rounds and patches.
Checks that every tiled graph equals the single one. Then a table "on paper": 10^8 sites on 64 workers,
predicted from the measured per-site costs and halo fractions (see the results file for the model).
Then the cells of C random ellipses in a box (default C = 300; 0: none): `ellvor.build(sites).cells(box=...,
rings=False)` in this process against `ellvor.distributed.cells(...)` on W workers in the --cell-tiles
tilings (default 2x2,4x4,8x8; wall time, speed-up, where each cell was proven), checked equal (visibility, neighbours,
overlapping area intervals).
With --out DIR, writes DIR/distributed.md.
"""
import argparse
import json
import math
import os
import pathlib
import platform
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from python_build import machine, source_state  # noqa: E402  (the same machine and source lines)

import ellvor  # noqa: E402
import ellvor.distributed as ed  # noqa: E402

SINGLE = """
import json, sys, time, ellvor
from ellvor.distributed import _rss_mb
sites = ellvor.read_sites(sys.argv[1])
before = _rss_mb()   # the interpreter, ellvor and the sites
start, cpu = time.perf_counter(), time.process_time()
d = ellvor.build(sites)
wall, cpu = time.perf_counter() - start, time.process_time() - cpu
arrays = [d.faces, d.edges, d.hull, d.hidden]
print(json.dumps({"insertions": d.stats["seconds"], "wall": wall, "cpu": cpu, "faces": len(d.faces),
                  "before_mb": before, "peak_mb": _rss_mb()}))
"""


def single_build(path):
    out = subprocess.run([sys.executable, "-c", SINGLE, str(path)], check=True, capture_output=True, text=True,
                         env=dict(os.environ)).stdout
    return json.loads(out)


def same_cells(a, b):
    """Cells a and b agree: visibility, each cell's neighbour cycle (up to its start), overlapping areas."""
    if not (np.array_equal(a.visible, b.visible) and np.array_equal(a.indptr, b.indptr)):
        return False
    for k in range(len(a)):
        x = a.indices[a.indptr[k]:a.indptr[k + 1]].tolist()
        y = b.indices[b.indptr[k]:b.indptr[k + 1]].tolist()
        if x and not any(y[r:] + y[:r] == x for r in range(len(y))):
            return False
    return bool(np.all((a.area_lo <= b.area_hi) & (b.area_lo <= a.area_hi)))


def cells_rows(count, workers, tilings):
    from distributed import Client
    sites = ellvor.generate("ellipses", count, seed=1)
    box = (-110, -110, 110, 110)   # the generator's centers and sites lie in [-100, 100]^2
    start, cpu = time.perf_counter(), time.process_time()
    single = ellvor.build(sites).cells(box=box, rings=False)
    single_wall, single_cpu = time.perf_counter() - start, time.process_time() - cpu
    print(f"[distributed] cells n={count} single: {single_wall:.2f} s", file=sys.stderr)
    rows = []
    for tiles in tilings:
        with ed.local_cluster(workers) as cluster, Client(cluster) as client:
            client.run(lambda: __import__("ellvor.distributed"))
            start, cpu = time.perf_counter(), time.process_time()
            c = ed.cells(sites, box=box, rings=False, tiles=tiles, client=client)
            wall, client_cpu = time.perf_counter() - start, time.process_time() - cpu
        rows.append({"n": count, "tiles": f"{tiles[0]}x{tiles[1]}",
                     "count": len(c.tiles), "single_wall": single_wall, "single_cpu": single_cpu, "wall": wall,
                     "client_cpu": client_cpu, "tile_cpu": sum(t["cpu_seconds"] for t in c.tiles),
                     "held": sum(t["sites"] for t in c.tiles), "retries": sum(t["retries"] for t in c.tiles),
                     "in_tiles": sum(t["cells"] for t in c.tiles), "whole": c.stats["whole_set_cells"],
                     "rounds": c.stats["rounds"], "same": same_cells(single, c)})
        print(f"[distributed] cells n={count} {rows[-1]['tiles']}: {wall:.2f} s, same={rows[-1]['same']}",
              file=sys.stderr)
    return rows


def worker_rss_mb():
    return ed._rss_mb()


def tiled_build(sites, tiles, workers, single):
    from distributed import Client
    with ed.local_cluster(workers) as cluster, Client(cluster) as client:
        client.run(lambda: __import__("ellvor.distributed"))   # imports outside the timed call
        baseline = client.run(worker_rss_mb)
        start, cpu = time.perf_counter(), time.process_time()
        d = ed.build(sites, tiles=tiles, client=client)
        wall, client_cpu = time.perf_counter() - start, time.process_time() - cpu
    same = all(np.array_equal(getattr(d, k), single[k]) for k in ("faces", "edges", "hull", "hidden"))
    owned = sum(t["owned"] for t in d.tiles)
    halo = sum(t["halo_sites"] for t in d.tiles)
    return {"tiles": f"{tiles[0]}x{tiles[1]}", "wall": wall, "same": same, "client_cpu": client_cpu,
            "peak": max(t["rss_mb"] for t in d.tiles),
            "baseline": sorted(baseline.values()), "halo_fraction": halo / max(owned, 1),
            "held_per_tile": max(t["sites"] for t in d.tiles), "hull_candidates": d.stats["hull_candidates"],
            "rounds": d.stats["rounds"], "patches": sum(t["retries"] for t in d.tiles),
            "fallback": d.stats["fallback"], "tile_seconds": sum(t["cpu_seconds"] for t in d.tiles),
            "tile_build_seconds": sum(t["build_cpu_seconds"] for t in d.tiles),
            "tile_wall": sum(t["seconds"] for t in d.tiles),
            "held": sum(t["sites"] for t in d.tiles)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--count", type=int, default=100000)
    ap.add_argument("--full", action="store_true", help="also 10^6 sites")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--tiles", default="2x1,2x2,4x4,8x8")
    ap.add_argument("--full-tiles", default="4x4", help="the tilings at 10^6 sites")
    ap.add_argument("--packing", type=int, default=100000)
    ap.add_argument("--cells", type=int, default=300)
    ap.add_argument("--cell-tiles", default="2x2,4x4,8x8", help="the tilings of the cells")
    ap.add_argument("--out", type=pathlib.Path)
    args = ap.parse_args()

    def tilings_of(text):
        return [tuple(int(v) for v in t.split("x")) for t in text.split(",")]
    tilings = tilings_of(args.tiles)
    sets = [("random", args.count, tilings)]
    if args.packing:
        sets.append(("packing", args.packing, tilings))
    if args.full and args.count != 10 ** 6:
        sets.append(("random", 10 ** 6, tilings_of(args.full_tiles)))

    import tempfile
    rows, singles = [], {}
    load_before = os.getloadavg()
    with tempfile.TemporaryDirectory() as tmp:
        for kind, n, set_tilings in sets:
            start = time.perf_counter()
            if kind == "packing":
                sites = ellvor.generate("packing", n, seed=1, packing_fraction=0.6)
            else:
                sites = ellvor.generate("ellipses", n, seed=1)
            made = time.perf_counter() - start
            path = pathlib.Path(tmp) / f"{kind}-{n}.ell"
            sites.write(path)
            s = single_build(path)
            s["generated"] = made
            reference = ellvor.build(sites)   # the graph to compare with (same input, same build)
            ref = {k: getattr(reference, k) for k in ("faces", "edges", "hull", "hidden")}
            del reference
            singles[kind, n] = s
            print(f"[distributed] {kind} n={n} (made in {made:.1f} s) single: {s['wall']:.2f} s, "
                  f"peak {s['peak_mb']:.0f} MB", file=sys.stderr)
            for tiles in set_tilings:
                r = tiled_build(sites, tiles, args.workers, ref)
                r["n"], r["kind"] = n, kind
                rows.append(r)
                print(f"[distributed] {kind} n={n} {r['tiles']}: {r['wall']:.2f} s, same={r['same']}, "
                      f"halo {r['halo_fraction']:.3f}, worker peak {r['peak']:.0f} MB", file=sys.stderr)
    cell_rows = cells_rows(args.cells, args.workers, tilings_of(args.cell_tiles)) if args.cells else []
    load_after = os.getloadavg()

    # The model "on paper": a worker builds its tiles one after another (one thread), each in time
    # c_tile * held sites; held = owned (1 + f), with f the halo fraction, which scales as the tile's
    # perimeter over its area: f = k / sqrt(owned) (k fitted on the measured tilings); the hull
    # candidates' build runs on one worker beside them, its candidates a band along the hull:
    # candidates = h * sqrt(n) (h fitted). Memory per worker: the single build's bytes per site times the
    # held sites of one tile, plus the measured empty worker.
    big = max(n for kind, n, _ in sets if kind == "random")
    measured = [r for r in rows if r["n"] == big and r["kind"] == "random" and not r["fallback"]]
    c_tile = sum(r["tile_seconds"] for r in measured) / sum(r["held"] for r in measured)
    k = float(np.median([r["halo_fraction"] * math.sqrt(big / int(np.prod([int(v) for v in r["tiles"].split("x")])))
                         for r in measured]))
    h = float(np.median([r["hull_candidates"] / math.sqrt(big) for r in measured]))
    # The client's work (checking the sites, cutting them into tiles, sending them, assembling the faces)
    # runs in one process whatever the workers: c_client per site, serial.
    c_client = float(np.median([r["client_cpu"] / big for r in measured]))
    bytes_per_site = (singles["random", big]["peak_mb"] - singles["random", big]["before_mb"]) * 2 ** 20 / big
    empty_worker = measured[0]["baseline"][0]
    paper = []  # CPU costs: what a worker with a core of its own spends
    N, W = 10 ** 8, 64
    for per_worker in (1, 4, 16):
        T = W * per_worker
        owned = N / T
        f = k / math.sqrt(owned)
        held = owned * (1 + f)
        hull_sites = h * math.sqrt(N)
        seconds = max(per_worker * c_tile * held, c_tile * hull_sites)
        memory = empty_worker + bytes_per_site * max(held, hull_sites) / 2 ** 20
        paper.append((T, owned, f, seconds, c_client * N, memory, hull_sites))
    single_per_site = singles["random", big]["cpu"] / big

    lines = ["# The tiled build on dask.distributed (`experiments/distributed_scaling.py`)", "",
             f"Command: `PYTHONPATH=build/python /usr/bin/python3 experiments/distributed_scaling.py "
             f"{' '.join(sys.argv[1:])}`", "",
             f"Machine: {machine()}; Python {platform.python_version()}; source {source_state()}; "
             f"load average (1 min) {load_before[0]:.2f} before, {load_after[0]:.2f} after "
             "(other jobs share the cores: wall times and speed-ups are upper and lower bounds).", "",
             "Random ellipses, `ellvor.generate(\"ellipses\", N, seed=1)`" +
             ("".join(f", and a dense packing, `ellvor.generate(\"packing\", N, seed=1, packing_fraction=0.6)` "
                      f"({n} sites made in {s['generated']:.0f} s)" for (kind, n), s in singles.items()
                      if kind == "packing")) + ". Single: `ellvor.build` in a child "
             "process (wall and CPU time of the call; resident memory with the graph built). Tiled: "
             f"`ellvor.distributed.build(sites, tiles, client)` on a fresh `ellvor.distributed.local_cluster({args.workers})` (Dask's profiler off) of {args.workers} worker "
             "processes, one thread each (wall time of the call, shipping and client work included; the tiles' "
             "CPU time, of which their graphs' builds, and the client's; the largest resident memory of a worker with a tile's graph built, "
             "against the single build's (ratio), and an idle worker's for scale). Halo overhead: halo "
             "sites / owned sites over all tiles. Every tiled graph was checked equal to the single one.", "",
             "| sites | N | tiles | single wall (s) | single CPU (s) | tiled wall (s) | speed-up (wall) | tiles' CPU (s) "
             "| of which builds (s) | client CPU (s) | single RSS (MB) | largest worker RSS (MB) | ratio | idle worker (MB) | halo overhead "
             "| hull candidates | rounds | patches | same graph |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        s = singles[r["kind"], r["n"]]
        fallback = f" (fallback: {r['fallback']})" if r["fallback"] else ""
        lines.append(f"| {r['kind']} | {r['n']} | {r['tiles']} | {s['wall']:.2f} | {s['cpu']:.2f} | {r['wall']:.2f} | "
                     f"{s['wall'] / r['wall']:.2f} | {r['tile_seconds']:.2f} | {r['tile_build_seconds']:.2f} | "
                     f"{r['client_cpu']:.2f} | "
                     f"{s['peak_mb']:.0f} | {r['peak']:.0f} | {r['peak'] / s['peak_mb']:.2f} | {r['baseline'][0]:.0f} | "
                     f"{r['halo_fraction']:.3f} | {r['hull_candidates']} | {r['rounds']} | {r['patches']} | "
                     f"{'yes' if r['same'] else 'NO'}{fallback} |")
    lines += ["", "## On paper: 10^8 sites on 64 workers", "",
              f"From the N = {big} runs: tile build cost c = {c_tile * 1e6:.1f} µs of CPU per held site (sum of the "
              f"tiles' CPU seconds / sum of their sites; the single build: {single_per_site * 1e6:.1f} µs per site); halo "
              f"fraction f = k / sqrt(owned sites of a tile), k = {k:.2f} (median over the tilings); hull "
              f"candidates = h sqrt(N), h = {h:.2f}; {bytes_per_site:.0f} bytes per site (the single build's RSS with its "
              f"graph over its RSS before the build, per site) and {empty_worker:.0f} MB for an idle worker; the client "
              f"(it checks the sites, cuts them into tiles, sends them and assembles the faces, in one process) "
              f"c_client = {c_client * 1e6:.2f} µs of CPU per site (median client CPU / N), serial. A worker builds "
              "its tiles one after another; the hull candidates' graph is one task; the total is the workers' "
              "time plus the client's (an upper bound: part of the client's work overlaps the workers'). Not "
              "modelled: the network, and the per-site cost's growth with N (the walk and the grid; "
              "`build_scaling.md`).", "",
              "| tiles | owned sites a tile | halo fraction | predicted workers' time (s) | client (s) "
              "| predicted total (s) | predicted peak per worker (MB) | hull candidates |",
              "|---|---|---|---|---|---|---|---|"]
    for T, owned, f, seconds, client_seconds, memory, hull_sites in paper:
        lines.append(f"| {T} ({T // W} a worker) | {owned:.0f} | {f:.3f} | {seconds:.0f} | {client_seconds:.0f} | "
                     f"{seconds + client_seconds:.0f} | {memory:.0f} | {hull_sites:.0f} |")
    lines.append(f"\nThe single build of 10^8 sites at the measured rate: {single_per_site * N:.0f} s of CPU and "
                 f"{empty_worker + bytes_per_site * N / 2 ** 20:.0f} MB (above the 10^7-site input limit of "
                 "`sites/site_io.hpp`, which binds the CLI, not a tiled build's tiles).")
    if cell_rows:
        lines += ["", "## Cells", "",
                  f"{args.cells} random ellipses (`ellvor.generate(\"ellipses\", {args.cells}, seed=1)`) in the box "
                  "(-110, -110, 110, 110), T = 1e-9, no rings. Single: `ellvor.build(sites).cells(box=..., "
                  "rings=False)` in this process. Tiled: `ellvor.distributed.cells(sites, box=..., rings=False, tiles=..., "
                  f"client=...)` on a fresh `ellvor.distributed.local_cluster({args.workers})` (Dask's profiler off) of {args.workers} worker processes (wall time of the call; the "
                  "tiles' CPU time, patches and the whole-set task included; cells proven in tiles or patches, "
                  "and computed in one task of the whole set). Checked equal: visibility, neighbours, overlapping "
                  "area intervals.", "",
                  "| N | tiles | tasks | single wall (s) | single CPU (s) | tiled wall (s) | speed-up (wall) "
                  "| tiles' CPU (s) | client CPU (s) | held sites | patches | proven in tiles | whole-set cells "
                  "| rounds | same cells |", "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in cell_rows:
            lines.append(f"| {r['n']} | {r['tiles']} | {r['count']} | {r['single_wall']:.1f} | {r['single_cpu']:.1f} | "
                         f"{r['wall']:.1f} | {r['single_wall'] / r['wall']:.2f} | {r['tile_cpu']:.1f} | "
                         f"{r['client_cpu']:.2f} | {r['held']} | {r['retries']} | {r['in_tiles']} | {r['whole']} | "
                         f"{r['rounds']} | {'yes' if r['same'] else 'NO'} |")
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        args.out.mkdir(parents=True, exist_ok=True)
        (args.out / "distributed.md").write_text(text)


if __name__ == "__main__":
    main()
