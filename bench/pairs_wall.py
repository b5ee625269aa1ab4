#!/usr/bin/env python3
"""Whole-process time of pcl_tensor_register on every pair of the real Stanford sets (issue 23).

Each pair runs as a user runs it: one process per pair, `pcl_tensor_register MODEL SCENE --json -j 1`
pinned to one core with taskset, D from the pair. The wall time covers start-up, reading both scans,
preparing them, the tensors, matching and verification. Pairs are scored against the .conf poses
(correct: rotation <= 5 degrees and translation <= 20 d_res, Eqs. 11-12); a registration that is not
correct is a wrong pose. One process runs per core listed in --cores, each on its own share of the pairs.

With --against OTHER, every pair runs under both binaries, one after the other on the same core, in
alternating order: the two times of a pair see the same load, and the per-pair differences show what a
change saves. The report then also counts the pairs whose outcome and transform are the same.

    python3 bench/pairs_wall.py --bin build/apps/pcl_tensor_register
    python3 bench/pairs_wall.py --bin NEW --against OLD --csv pairs.csv
"""
import argparse
import csv
import itertools
import json
import math
import os
import statistics
import subprocess
import sys
import threading
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "scale"))
from scale_benchmark import load_conf  # noqa: E402  (the .conf reader the scale benchmark checks its poses with)
SHARED = os.path.normpath(os.path.join(HERE, "..", "..", "shared", "data"))
SETS = {"bunny": ("stanford/bunny", "bun.conf"), "dragon_stand": ("stanford/dragon_stand", "dragonStandRight.conf")}
MAX_ROTATION_DEG, MAX_TRANSLATION_RES = 5.0, 20.0


def pairs_of(data, max_pairs=0):
    """(set, model path, scene path, true model <- scene transform) for every pair of scans in a .conf,
    or its first max_pairs."""
    pairs = []
    for name, (folder, conf) in SETS.items():
        poses = load_conf(os.path.join(data, folder, conf))
        scans = sorted(f for f in poses if os.path.exists(os.path.join(data, folder, f)))
        combinations = list(itertools.combinations(scans, 2))
        for a, b in combinations[:max_pairs] if max_pairs > 0 else combinations:
            truth = np.linalg.inv(poses[a]) @ poses[b]
            pairs.append((name, os.path.join(data, folder, a), os.path.join(data, folder, b), truth))
    return pairs


def score(report, truth):
    """'correct', 'wrong' (registered, not correct), 'ambiguous' or 'refused'."""
    if report.get("status") != "registered":
        return "ambiguous" if report.get("ambiguous") else "refused"
    t = np.array(report["transform"], dtype=float).reshape(4, 4)
    d = t[:3, :3] @ truth[:3, :3].T
    rotation = math.degrees(math.acos(max(-1.0, min(1.0, (np.trace(d) - 1.0) / 2.0))))
    translation = np.linalg.norm(t[:3, 3] - truth[:3, 3]) / report["resolution"]
    return "correct" if rotation <= MAX_ROTATION_DEG and translation <= MAX_TRANSLATION_RES else "wrong"


def run(binary, model, scene, core):
    start = time.perf_counter()
    done = subprocess.run(["taskset", "-c", str(core), binary, model, scene, "--json", "-j", "1"],
                          capture_output=True, text=True)
    wall_ms = 1000.0 * (time.perf_counter() - start)
    lines = done.stdout.strip().splitlines()
    if not lines:
        sys.exit(f"{binary} {model} {scene}: no report (exit {done.returncode}): {done.stderr.strip()}")
    return json.loads(lines[-1]), wall_ms


def measure(pairs, binaries, cores):
    """[[(report, wall_ms)] in pair order] per binary; pair i runs on core i % len(cores)."""
    results = [[None] * len(pairs) for _ in binaries]

    def worker(slot):
        for i in range(slot, len(pairs), len(cores)):
            _, model, scene, _ = pairs[i]
            order = range(len(binaries)) if (i // len(cores)) % 2 == 0 else reversed(range(len(binaries)))
            for b in order:
                results[b][i] = run(binaries[b], model, scene, cores[slot])

    threads = [threading.Thread(target=worker, args=(s,)) for s in range(len(cores))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return results


def quartiles(values):
    v = sorted(values)
    return v[len(v) // 4], statistics.median(v), v[(3 * len(v)) // 4]


def summary(label, pairs, runs):
    outcomes = [score(r, p[3]) for p, (r, _) in zip(pairs, runs)]
    walls = [w for _, w in runs]
    print(f"{label}: {len(pairs)} pairs, " + ", ".join(f"{o} {outcomes.count(o)}" for o in
                                                        ("correct", "wrong", "ambiguous", "refused")))
    for group in ("all", "registered", "not registered"):
        sel = [w for w, (r, _) in zip(walls, runs) if group == "all" or (r["status"] == "registered") == (group == "registered")]
        if sel:
            q1, med, q3 = quartiles(sel)
            print(f"  {group:15s} {len(sel):4d} pairs  median {med:6.0f} ms (quartiles {q1:.0f}-{q3:.0f})  sum {sum(sel) / 1000:7.1f} s")
    return outcomes


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", default=os.path.join(HERE, "..", "build", "apps", "pcl_tensor_register"))
    parser.add_argument("--against", help="a second pcl_tensor_register: every pair runs under both")
    parser.add_argument("--data", default=SHARED, help="the shared data folder (default %(default)s)")
    parser.add_argument("--cores", default="0", help="cores to pin one process each to, e.g. 0,1 (default %(default)s)")
    parser.add_argument("--csv", help="write every pair's outcome and times here")
    parser.add_argument("--max-pairs", type=int, default=0, help="only the first N pairs of each set (default 0: all)")
    args = parser.parse_args()
    if not all(os.path.isdir(os.path.join(args.data, folder)) for folder, _ in SETS.values()):
        print(f"SKIPPED: the Stanford scans are not in {args.data}")
        return 0
    cores = [int(c) for c in args.cores.split(",")]
    binaries = [os.path.normpath(args.bin)] + ([os.path.normpath(args.against)] if args.against else [])
    pairs = pairs_of(args.data, args.max_pairs)
    results = measure(pairs, binaries, cores)
    outcomes = [summary(b, pairs, r) for b, r in zip(binaries, results)]
    if args.against:
        new, old = results
        same = sum(a[0]["status"] == b[0]["status"] and a[0]["transform"] == b[0]["transform"] for a, b in zip(new, old))
        q1, med, q3 = quartiles([b[1] - a[1] for a, b in zip(new, old)])
        print(f"same outcome and transform: {same} of {len(pairs)}; time saved per pair by --bin: median {med:.0f} ms "
              f"(quartiles {q1:.0f} to {q3:.0f})")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["set", "model", "scene", "binary", "status", "outcome", "wall_ms", "hypotheses_tried"] +
                         [f"{k}_ms" for k in ("load", "prepare", "tensors", "matching", "verification")])
            for b, runs, scored in zip(binaries, results, outcomes):
                for p, (r, w), o in zip(pairs, runs, scored):
                    out.writerow([p[0], os.path.basename(p[1]), os.path.basename(p[2]), b, r["status"], o, f"{w:.1f}",
                                  r.get("hypotheses_tried", 0)] + [f"{r['timings_ms'].get(k, 0.0):.1f}" for k in
                                                                  ("load", "prepare", "tensors", "matching", "verification")])
    return 0


if __name__ == "__main__":
    sys.exit(main())
