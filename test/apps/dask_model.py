#!/usr/bin/env python3
"""scripts/pcl_tensor_dask.py on a LocalCluster of 2 workers must give the poses of one pcl_tensor_model
run on the same 12 views with the same options: every view registered in both, rotations within 0.05
degrees and translations within 0.05 d_res of each other. A job that fails must stop the driver with
the tool's message. Prints "SKIPPED [no dask.distributed]" when this python3 lacks dask.distributed.

    python3 dask_model.py --bin BUILD/apps --driver scripts/pcl_tensor_dask.py --out DIR
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys

MAX_DEGREES = 0.05
MAX_RESOLUTIONS = 0.05
OPTIONS = ["--viewpoint", "0,0,0", "--loop"]


def quaternion_matrix(x, y, z, w):
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def load_conf(path):
    """Stanford .conf poses by view name: (rotation, translation)."""
    poses = {}
    with open(path) as f:
        for line in f:
            fields = line.split()
            if fields and fields[0] == "bmesh":
                values = [float(v) for v in fields[2:9]]
                poses[fields[1]] = (quaternion_matrix(*values[3:7]), values[0:3])
    return poses


def degrees_between(a, b):
    """The angle of a^T b: how far two rotations are apart."""
    trace = sum(a[k][i] * b[k][i] for i in range(3) for k in range(3))
    return math.degrees(math.acos(max(-1.0, min(1.0, (trace - 1.0) / 2.0))))


def run(command, expected=(0,), **kwargs):
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kwargs)
    if done.returncode not in expected:
        sys.exit(f"exit code {done.returncode}, expected {expected}: {' '.join(command)}\n"
                 f"stdout:\n{done.stdout}\nstderr:\n{done.stderr}")
    return done


def compare(single_conf, dask_conf, resolution, names):
    single, dask = load_conf(single_conf), load_conf(dask_conf)
    for poses, run_name in ((single, "pcl_tensor_model"), (dask, "the driver")):
        missing = sorted(set(names) - set(poses))
        if missing:
            sys.exit(f"{run_name} did not register {missing}")
    worst_degrees = worst_resolutions = 0.0
    for name in names:
        (r1, t1), (r2, t2) = single[name], dask[name]
        degrees = degrees_between(r1, r2)
        resolutions = math.dist(t1, t2) / resolution
        print(f"{name}: {degrees:.2e} degrees, {resolutions:.2e} d_res apart")
        if degrees > MAX_DEGREES or resolutions > MAX_RESOLUTIONS:
            sys.exit(f"{name}: the poses differ by {degrees:.4f} degrees and {resolutions:.4f} d_res "
                     f"(at most {MAX_DEGREES} and {MAX_RESOLUTIONS})")
        worst_degrees, worst_resolutions = max(worst_degrees, degrees), max(worst_resolutions, resolutions)
    print(f"all {len(names)} views registered in both runs; poses at most {worst_degrees:.2e} degrees "
          f"and {worst_resolutions:.2e} d_res apart")


def check_results_files(cache):
    """The pair results the jobs wrote: one chunk's registrations per file, each line a JSON object."""
    folders = [os.path.join(cache, d) for d in os.listdir(cache) if d.startswith("pairs-")]
    results = [os.path.join(f, r) for f in folders for r in os.listdir(f) if r.endswith(".jsonl")]
    lines = [json.loads(line) for r in results for line in open(r) if line.strip()]
    registered = sum(line["report"]["status"] == "registered" for line in lines)
    if not lines or not registered:
        sys.exit(f"expected pair results in {folders}, found {len(lines)} ({registered} registered)")
    print(f"{len(lines)} pair results in {len(results)} files, {registered} registered")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", required=True)
    parser.add_argument("--driver", required=True)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    try:
        import dask.distributed  # noqa: F401
    except ImportError:
        print(f"SKIPPED [no dask.distributed] for {sys.executable} (Debian: python3-distributed)")
        return 0
    shutil.rmtree(args.out, ignore_errors=True)
    views_dir, single_dir, dask_dir = (os.path.join(args.out, d) for d in ("views", "single", "dask"))
    os.makedirs(single_dir)
    os.makedirs(dask_dir)
    tool = lambda name: os.path.join(args.bin, name)  # noqa: E731
    run([tool("pcl_tensor_views"), "example", "-o", views_dir, "--ring", "12", "--size", "300", "300"])
    names = [f"view_{i:02d}.ply" for i in range(12)]
    views = [os.path.join(views_dir, n) for n in names]

    single = run([tool("pcl_tensor_model")] + views + OPTIONS + ["--cache", os.path.join(single_dir, "cache"),
                                                                   "-o", os.path.join(single_dir, "model.ply"), "--json"])
    resolution = json.loads(single.stdout)["resolution"]
    dask_cache = os.path.join(dask_dir, "cache")
    driver = run([sys.executable, args.driver] + views + OPTIONS + ["--cache", dask_cache, "--workers", "2",
                                                                      "--bin", args.bin, "-o", os.path.join(dask_dir, "model.ply")])
    print(driver.stdout)
    check_results_files(dask_cache)
    compare(os.path.join(single_dir, "model.conf"), os.path.join(dask_dir, "model.conf"), resolution, names)

    # A job that fails (a view that does not exist) stops the driver, which says which and why.
    failed = run([sys.executable, args.driver, views[0], os.path.join(views_dir, "missing.ply"), "--cache", dask_cache,
                  "--workers", "2", "--bin", args.bin, "-o", os.path.join(dask_dir, "failed.ply")] + OPTIONS, expected=(2,))
    if "missing.ply" not in failed.stderr or "pcl_tensor_prepare" not in failed.stderr:
        sys.exit(f"the driver's message does not name the failing job and its view:\n{failed.stderr}")
    print("a failing job stops the driver with its tool's message")
    return 0


if __name__ == "__main__":
    sys.exit(main())
