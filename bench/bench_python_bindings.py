#!/usr/bin/env python3
"""The Python bindings' overhead against pcl_tensor_register on one pair, measured in the same run.

Alternates, RUNS times: the app as a whole process (--json), the bindings' register() in this process
on the same files, and a fresh `python3 -c` process that imports pcl_tensor and registers. Prints the
medians and the ratios to the app.

    PYTHONPATH=build/python python3 bench/bench_python_bindings.py [--runs 7] [MODEL SCENE]
    (default pair: ../shared/data/stanford/bunny/bun000.ply and bun045.ply)
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

import numpy as np

import pcl_tensor

HERE = os.path.dirname(os.path.abspath(__file__))
BUNNY = os.path.join(HERE, "..", "..", "shared", "data", "stanford", "bunny")


def timed(fn):
    start = time.perf_counter()
    value = fn()
    return time.perf_counter() - start, value


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("model", nargs="?", default=os.path.join(BUNNY, "bun000.ply"))
    parser.add_argument("scene", nargs="?", default=os.path.join(BUNNY, "bun045.ply"))
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--app", default=os.path.join(HERE, "..", "build", "apps", "pcl_tensor_register"))
    args = parser.parse_args()

    app_s, call_s, process_s = [], [], []
    script = f"import pcl_tensor; pcl_tensor.register({args.model!r}, {args.scene!r})"
    for _ in range(args.runs):
        t, run = timed(lambda: subprocess.run([args.app, args.model, args.scene, "--json"],
                                              capture_output=True, text=True))
        app_s.append(t)
        app_report = json.loads(run.stdout)
        t, result = timed(lambda: pcl_tensor.register(args.model, args.scene))
        call_s.append(t)
        t, _ = timed(lambda: subprocess.run([sys.executable, "-c", script], check=True))
        process_s.append(t)
        same = np.array_equal(result.transform, np.array(app_report["transform"]).reshape(4, 4))

    app = statistics.median(app_s)
    print(f"pair: {os.path.basename(args.model)} <- {os.path.basename(args.scene)}, {args.runs} runs, "
          f"registered: {result.registered}, same transform as the app: {same}")
    print(f"{'':40s} {'median ms':>10s} {'vs app':>8s}")
    print(f"{'pcl_tensor_register (whole process)':40s} {app * 1000:10.1f} {1.0:8.2f}")
    for name, times in (("pcl_tensor.register() in-process", call_s),
                        ("python3 -c 'import; register' process", process_s)):
        m = statistics.median(times)
        print(f"{name:40s} {m * 1000:10.1f} {m / app:8.2f}")
    print(f"the app's own registration time (report, median): "
          f"{app_report['timings_ms']['registration']:.1f} ms; the bindings' (last run): "
          f"{result.report['timings_ms']['registration']:.1f} ms")


if __name__ == "__main__":
    main()
