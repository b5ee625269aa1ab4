#!/usr/bin/env python3
"""Scale benchmark of pcl_tensor_model on many unordered views (issue 25).

Renders synthetic sets of N views of one mesh (the 26-view set, rings at 0 and +-60 degrees and the
poles, plus N - 26 views from random directions, all shuffled), runs pcl_tensor_model on each as a
user would (one process, every core, --json), and reports wall time, peak memory, the pairs fully
registered and the pose errors against the rendered ground truth. The real Stanford sets run
shuffled too. With --cache it also times a re-run and a run with one view added: all views registered
again (with the cache), and the model extended (--keep-poses: the old views keep their poses).

    python3 bench/scale/scale_benchmark.py --bin build/apps --sizes 26,52,104,208 --real --cache
"""
import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED = os.path.normpath(os.path.join(HERE, "..", "..", "..", "shared", "data"))


def quaternion_matrix(qx, qy, qz, qw):
    n = math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw)
    x, y, z, w = qx / n, qy / n, qz / n, qw / n
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def load_conf(path):
    """bmesh lines -> {file: 4x4 pose view -> world}; p_world = R(q)^T p + t (the Stanford convention)."""
    poses = {}
    with open(path) as f:
        for line in f:
            parts = line.split()
            if len(parts) == 9 and parts[0] == "bmesh":
                t = np.array([float(v) for v in parts[2:5]])
                q = [float(v) for v in parts[5:9]]
                pose = np.eye(4)
                pose[:3, :3] = quaternion_matrix(*q).T
                pose[:3, 3] = t
                poses[os.path.basename(parts[1])] = pose
    return poses


def look_at_centre(poses):
    """The point closest to every sensor's optical axis (+z of each view frame), least squares."""
    a = np.zeros((3, 3))
    b = np.zeros(3)
    for p in poses.values():
        d = p[:3, 2] / np.linalg.norm(p[:3, 2])
        m = np.eye(3) - np.outer(d, d)
        a += m
        b += m @ p[:3, 3]
    return np.linalg.solve(a, b)


def pose_errors(truth, estimate, reference, centre, resolution):
    """Each estimated view's rotation error (degrees) and the error at the object's centre (d_res),
    with the estimate's frame put on the truth by the reference view."""
    errors = {}
    for name, e in estimate.items():
        world = truth[reference] @ e
        r = world[:3, :3].T @ truth[name][:3, :3]
        angle = math.degrees(math.acos(max(-1.0, min(1.0, (np.trace(r) - 1.0) / 2.0))))
        p = np.linalg.solve(truth[name], np.append(centre, 1.0))
        errors[name] = (angle, np.linalg.norm((world @ p)[:3] - centre) / resolution)
    return errors


def run_timed(cmd):
    """Wall time (s), peak memory (MB) and stdout of a command, through /usr/bin/time."""
    timed = ["/usr/bin/time", "-f", "%e %M"] + cmd
    proc = subprocess.run(timed, capture_output=True, text=True)
    last = proc.stderr.strip().splitlines()[-1].split()
    return float(last[0]), float(last[1]) / 1024.0, proc.stdout, proc.returncode, proc.stderr


def run_model(bin_dir, views, out_dir, extra=(), name="model"):
    model = os.path.join(out_dir, name + ".ply")
    cmd = [os.path.join(bin_dir, "pcl_tensor_model")] + views + ["-o", model, "--json"] + list(extra)
    wall, peak, out, code, err = run_timed(cmd)
    if code not in (0, 3):
        sys.exit("pcl_tensor_model failed (%d): %s" % (code, err[-2000:]))
    report = json.loads(out)
    return wall, peak, report, os.path.join(out_dir, name + ".conf")


def score(report, truth, estimate_conf, centre):
    names = [os.path.basename(v["file"]) for v in report["views"]]
    reference = names[report["reference"]]
    estimate = load_conf(estimate_conf)
    errors = pose_errors(truth, estimate, reference, centre, report["resolution"])
    worst_r = max(e[0] for e in errors.values()) if errors else float("nan")
    worst_t = max(e[1] for e in errors.values()) if errors else float("nan")
    within = sum(1 for e in errors.values() if e[0] <= 0.5 and e[1] <= 2.0)
    return worst_r, worst_t, within


def row(label, n, wall, peak, report, worst_r, worst_t, within):
    pairs = len(report["pairs_registered"])
    all_pairs = n * (n - 1) // 2
    t = report["timings_ms"]
    return {"set": label, "views": n, "registered": report["registered"], "components": report["components"],
            "within_0.5deg_2dres": within, "worst_rotation_deg": round(worst_r, 3), "worst_centre_dres": round(worst_t, 2),
            "wall_s": round(wall, 2), "peak_mb": round(peak), "mb_per_view": round(peak / n, 2),
            "pairs_registered": pairs, "pairs_fraction": round(pairs / all_pairs, 4),
            "ranking_s": round(t["ranking"] / 1000, 2), "pairwise_s": round(t["pairwise"] / 1000, 2),
            "global_s": round(t["global"] / 1000, 2)}


def synthetic(args, n, out):
    folder = os.path.join(out, "scale_%d" % n)
    shutil.rmtree(folder, ignore_errors=True)
    cmd = [os.path.join(args.bin, "pcl_tensor_views"), args.mesh, "-o", folder, "--size", str(args.image), str(args.image),
           "--random", str(n - 26), "--shuffle", "--noise", "0.3", "--seed", str(args.seed)]
    subprocess.run(cmd, check=True, capture_output=True)
    truth = load_conf(os.path.join(folder, "views.conf"))
    views = sorted(os.path.join(folder, f) for f in truth)
    return folder, views, truth, look_at_centre(truth)


def real(name, out):
    base = os.path.join(SHARED, "stanford", name)
    conf = {"bunny": "bun.conf", "dragon_stand": "dragonStandRight.conf"}[name]
    truth = load_conf(os.path.join(base, conf))
    views = [os.path.join(base, f) for f in truth]
    random.Random(5).shuffle(views)
    folder = os.path.join(out, "real_" + name)
    os.makedirs(folder, exist_ok=True)
    return folder, views, truth, np.zeros(3)  # Stanford frames lie on the object: the error at their origin


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default="build/apps", help="folder of the pcl_tensor tools")
    ap.add_argument("--mesh", default=os.path.join(SHARED, "meshes", "beast.ply"))
    ap.add_argument("--sizes", default="26,52,104,208")
    ap.add_argument("--image", type=int, default=300)
    ap.add_argument("--seed", type=int, default=2006)
    ap.add_argument("--real", action="store_true", help="also the Stanford bunny and dragon_stand, shuffled")
    ap.add_argument("--cache", action="store_true", help="also a re-run and one view added, with --cache (largest size below 200)")
    ap.add_argument("--out", default="bench_results/scale")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    sets = [("synthetic", int(n)) for n in args.sizes.split(",")]
    if args.real:
        sets += [("bunny", 0), ("dragon_stand", 0)]
    for kind, n in sets:
        folder, views, truth, centre = synthetic(args, n, args.out) if kind == "synthetic" else real(kind, args.out)
        wall, peak, report, conf = run_model(args.bin, views, folder)
        rows.append(row(kind, len(views), wall, peak, report, *score(report, truth, conf, centre)))
        print(json.dumps(rows[-1]), flush=True)
    if args.cache:
        cache_runs(args, rows)
    write_outputs(args, rows)


def cache_runs(args, rows):
    n = max(r["views"] for r in rows if r["set"] == "synthetic" and r["views"] < 200)
    folder, views, truth, centre = synthetic(args, n, args.out)
    cache = os.path.join(folder, "cache")
    first, _, _, first_conf = run_model(args.bin, views[:-1], folder, ["--cache", cache])
    again, _, _, _ = run_model(args.bin, views[:-1], folder, ["--cache", cache])
    extended, _, extended_report, extended_conf = run_model(args.bin, views, folder,
                                                            ["--cache", cache, "--keep-poses", first_conf], "extended")
    added, _, report, conf = run_model(args.bin, views, folder, ["--cache", cache])
    stages = lambda r: {k: round(v / 1000.0, 2) for k, v in r["timings_ms"].items()}
    record = {"set": "cache", "views": n, "first_run_s": round(first, 2), "re_run_s": round(again, 2),
              "re_run_ratio": round(again / first, 3), "one_view_added_s": round(added, 2),
              "registered_after_adding": report["registered"],
              "pairs_scored_after_adding": report["candidate_pairs_scored"], "candidate_pairs": report["candidate_pairs"],
              "one_view_added_stages_s": stages(report),
              "one_view_added_extending_s": round(extended, 2), "extending_ratio": round(extended / first, 3),
              "registered_extending": extended_report["registered"],
              "within_0.5deg_2dres_extending": score(extended_report, truth, extended_conf, centre)[2],
              "one_view_added_extending_stages_s": stages(extended_report)}
    rows.append(record)
    print(json.dumps(record), flush=True)


def write_outputs(args, rows):
    with open(os.path.join(args.out, "scale.json"), "w") as f:
        json.dump(rows, f, indent=1)
    with open(os.path.join(args.out, "scale.dat"), "w") as f:
        f.write("# views wall_s peak_mb pairs_registered\n")
        for r in rows:
            if r["set"] == "synthetic":
                f.write("%d %g %g %d\n" % (r["views"], r["wall_s"], r["peak_mb"], r["pairs_registered"]))
    synthetic_rows = [r for r in rows if r["set"] == "synthetic"]
    plot = os.path.join(HERE, "scale.gp")
    if shutil.which("gnuplot") and len(synthetic_rows) > 1:
        # The N log N curve through the second-largest set, to be read against the largest.
        anchor = sorted(synthetic_rows, key=lambda r: r["views"])[-2]
        subprocess.run(["gnuplot", "-e", "out='%s'; n0=%d; t0=%g" % (args.out, anchor["views"], anchor["wall_s"]), plot],
                       check=False)


if __name__ == "__main__":
    main()
