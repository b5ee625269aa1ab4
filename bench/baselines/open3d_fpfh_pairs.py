#!/usr/bin/python3
"""Open3D FPFH + RANSAC + point-to-plane ICP on every pair of eval_objects' sets, scored like the tensor method.

The pairs, their order (model, scene) and their overlap come from the tensor method's per-pair CSV
(doc/results/objects_pairs.csv, written by bench/eval_objects); each pair is registered with the pipeline of
Open3D's global registration tutorial (voxel downsampling, normals, FPFH,
registration_ransac_based_on_feature_matching, then point-to-plane ICP), its lengths scaled by the pair's d_res,
and scored as bench/eval/pair_evaluation.cpp scores the tensor method: the ground truth maps the scene into the
model's frame, T = P_model^-1 P_scene; rotation error = angle of R_est R_true^T; translation error
= |t_est - t_true| / d_res; correct within 5 degrees and 20 d_res.

d_res of a view is the project's own (PreparedScan::resolution, the mean edge length of the view's range-grid
mesh M_i): pcl_tensor_register reports it for a view registered to itself; a pair's d_res is the mean of its
two views' (pairResolution in bench/eval). See bench/baselines/README.md.

Run with the system interpreter, which Debian's python3-open3d installs into (scripts/setup_baselines.sh):
    /usr/bin/python3 bench/baselines/open3d_fpfh_pairs.py --out DIR [--objects a,b] [--max-pairs N]
"""
import os

# Single-threaded, like the tensor pipeline's times: OpenMP reads this when Open3D loads.
os.environ["OMP_NUM_THREADS"] = "1"

import argparse
import csv
import json
import math
import subprocess
import sys
import time

import numpy as np
import open3d as o3d

REG = o3d.pipelines.registration

REAL_SETS = {
    "bunny": "stanford/bunny/bun.conf",
    "dragon_stand": "stanford/dragon_stand/dragonStandRight.conf",
}
# Rendered sets: eval_objects --meshes renders meshes/*.ply (sorted), bun_zipper, dragon_vrip_res3 and the example.
EXTRA_MESHES = {
    "bun_zipper": "stanford/bunny/bun_zipper.ply",
    "dragon_vrip_res3": "stanford/dragon_recon/dragon_vrip_res3.ply",
    "example": None,  # pcl_tensor_views' built-in object
}
RING, STEP, NOISE = 12, 30, 0.3  # eval_objects' defaults (bench/EVAL.md, eval_objects)

# Correct within (bench/eval pair_evaluation: kMaxRotationErrorDeg, kMaxTranslationErrorResolutions).
MAX_ROTATION_DEG = 5.0
MAX_TRANSLATION_RES = 20.0

# Open3D tutorial lengths, in leaves; the leaf in d_res like the PCL FPFH baseline (bench/EVAL.md).
LEAF_RES = 2.5
NORMAL_RADIUS_LEAVES, NORMAL_MAX_NN = 2.0, 30
FPFH_RADIUS_LEAVES, FPFH_MAX_NN = 5.0, 100
RANSAC_DISTANCE_LEAVES = 1.5
RANSAC_MAX_ITERATIONS, RANSAC_CONFIDENCE, RANSAC_N = 100000, 0.999, 3
EDGE_LENGTH_CHECK = 0.9
MUTUAL_FILTER = True  # as the tutorial calls it
ICP_DISTANCE_LEAVES = 1.0
SEED = 2006

COLUMNS = ["object", "model", "scene", "overlap", "registered", "correct", "rotation_error_deg",
           "translation_error_res", "fitness", "inlier_rmse", "time_ms"]


# ---------------------------------------------------------------------------------------------- input


def read_ply_xyz(path):
    """The vertex x, y, z of a PLY file (ascii or binary), as float64 (n, 3); other elements ignored."""
    with open(path, "rb") as f:
        if f.readline().strip() != b"ply":
            raise ValueError(path + ": not a PLY file")
        fmt, elements = None, []
        while True:
            line = f.readline()
            if not line:
                raise ValueError(path + ": header has no end_header")
            words = line.decode("ascii", "replace").split()
            if not words:
                continue
            if words[0] == "format":
                fmt = words[1]
            elif words[0] == "element":
                elements.append([words[1], int(words[2]), []])
            elif words[0] == "property":
                elements[-1][2].append(words[1:])
            elif words[0] == "end_header":
                break
        if elements[0][0] != "vertex":
            raise ValueError(path + ": the first element is not vertex")
        name, count, props = elements[0]
        names = [p[-1] for p in props]
        if any(p[0] == "list" for p in props):
            raise ValueError(path + ": list property in vertex")
        cols = [names.index(c) for c in ("x", "y", "z")]
        if fmt == "ascii":
            rows = [f.readline().split() for _ in range(count)]
            data = np.array([[float(r[c]) for c in cols] for r in rows], dtype=np.float64)
        else:
            types = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
                     "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
                     "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}
            endian = "<" if fmt == "binary_little_endian" else ">"
            dtype = np.dtype([(p[-1], endian + types[p[0]]) for p in props])
            raw = np.frombuffer(f.read(dtype.itemsize * count), dtype=dtype, count=count)
            data = np.stack([raw["x"], raw["y"], raw["z"]], axis=1).astype(np.float64)
    return data[np.isfinite(data).all(axis=1)]


def quat_matrix(qx, qy, qz, qw):
    """The standard rotation matrix R(q) of a unit quaternion q = (qx, qy, qz, qw)."""
    n = math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw)
    x, y, z, w = qx / n, qy / n, qz / n, qw / n
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def read_conf(path):
    """bmesh lines of a Stanford .conf: [(file, P)], P the 4x4 view-to-world pose, p_world = R(q)^T p + t."""
    entries = []
    with open(path) as f:
        for line in f:
            w = line.split()
            if len(w) == 9 and w[0] == "bmesh":
                t = np.array([float(v) for v in w[2:5]])
                P = np.eye(4)
                P[:3, :3] = quat_matrix(*[float(v) for v in w[5:9]]).T
                P[:3, 3] = t
                entries.append((w[1], P))
    return entries


def stem(name):
    return os.path.splitext(os.path.basename(name))[0]


class View:
    def __init__(self, name, path, pose, sensor):
        self.name, self.path, self.pose = name, path, pose
        # "origin": a perspective sensor at the view frame's origin (the rendered views);
        # "+z": an orthographic sensor on the +z side (the Stanford scans, in the Cyberware's frame).
        self.sensor = sensor
        self.points = None
        self.d_res = None


def render_views(bin_dir, mesh, out_dir):
    """pcl_tensor_views' ring of eval_objects (12 views, 30 degrees, 0.3 d_res noise) into out_dir, unless there."""
    if os.path.exists(os.path.join(out_dir, "views.conf")):
        return
    cmd = [os.path.join(bin_dir, "pcl_tensor_views"), mesh if mesh else "example", "-o", out_dir,
           "--ring", str(RING), "--step", str(STEP), "--noise", str(NOISE)]
    print("  render:", " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, env=dict(os.environ, OMP_NUM_THREADS="1"))


def load_set(obj, args):
    """The views of one set by CSV name (bun000, view0, ...)."""
    views = {}
    if obj in REAL_SETS:
        conf = os.path.join(args.data, REAL_SETS[obj])
        for f, P in read_conf(conf):
            views[stem(f)] = View(stem(f), os.path.join(os.path.dirname(conf), f), P, "+z")
        return views
    if obj in EXTRA_MESHES:
        mesh = EXTRA_MESHES[obj] and os.path.join(args.data, EXTRA_MESHES[obj])
    else:
        mesh = os.path.join(args.data, "meshes", obj + ".ply")
    if mesh and not os.path.exists(mesh):
        raise FileNotFoundError(mesh)
    out_dir = os.path.join(args.views, obj)
    render_views(args.bin, mesh, out_dir)
    for f, P in read_conf(os.path.join(out_dir, "views.conf")):
        # pcl_tensor_views writes view_00.ply ...; eval_objects names them view0 ...
        views["view%d" % int(stem(f).split("_")[-1])] = View(stem(f), os.path.join(out_dir, f), P, "origin")
    return views


def view_resolutions(obj, views, args, cache):
    """Each view's d_res as the project computes it, from pcl_tensor_register (cached in cache[obj])."""
    known = cache.setdefault(obj, {})
    for name, v in views.items():
        if name not in known:
            cmd = [os.path.join(args.bin, "pcl_tensor_register"), v.path, v.path, "--json", "-j", "1",
                   "--max-hypotheses", "1"]
            for attempt in range(5):
                if os.path.exists(cmd[0]):
                    break
                time.sleep(60)  # being relinked
            p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                               env=dict(os.environ, OMP_NUM_THREADS="1"))
            if p.returncode not in (0, 3):
                raise RuntimeError("%s failed (%d)" % (" ".join(cmd), p.returncode))
            known[name] = float(json.loads(p.stdout)["resolution"])
        v.d_res = known[name]


# ------------------------------------------------------------------------------------------ Open3D


def preprocess(points, sensor, leaf):
    """The tutorial's preprocess_point_cloud: voxel downsampling, normals, FPFH; normals toward the sensor."""
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    down = pcd.voxel_down_sample(leaf)
    down.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=NORMAL_RADIUS_LEAVES * leaf,
                                                               max_nn=NORMAL_MAX_NN))
    if sensor == "origin":
        down.orient_normals_towards_camera_location(np.zeros(3))
    else:
        down.orient_normals_to_align_with_direction(np.array([0.0, 0.0, 1.0]))
    fpfh = REG.compute_fpfh_feature(down, o3d.geometry.KDTreeSearchParamHybrid(radius=FPFH_RADIUS_LEAVES * leaf,
                                                                                max_nn=FPFH_MAX_NN))
    return down, fpfh


def register_pair(model, scene, d_res):
    """Scene into model's frame: RANSAC on FPFH matches, then point-to-plane ICP. Returns (ransac, icp result)."""
    leaf = LEAF_RES * d_res
    o3d.utility.random.seed(SEED)
    model_down, model_fpfh = preprocess(model.points, model.sensor, leaf)
    scene_down, scene_fpfh = preprocess(scene.points, scene.sensor, leaf)
    distance = RANSAC_DISTANCE_LEAVES * leaf
    ransac = REG.registration_ransac_based_on_feature_matching(
        scene_down, model_down, scene_fpfh, model_fpfh, MUTUAL_FILTER, distance,
        REG.TransformationEstimationPointToPoint(False), RANSAC_N,
        [REG.CorrespondenceCheckerBasedOnEdgeLength(EDGE_LENGTH_CHECK),
         REG.CorrespondenceCheckerBasedOnDistance(distance)],
        REG.RANSACConvergenceCriteria(RANSAC_MAX_ITERATIONS, RANSAC_CONFIDENCE))
    icp = REG.registration_icp(scene_down, model_down, ICP_DISTANCE_LEAVES * leaf, ransac.transformation,
                               REG.TransformationEstimationPointToPlane())
    return ransac, icp


# ----------------------------------------------------------------------------------------- scoring


def rotation_error_deg(R, R_true):
    """registration_error.cpp's rotationErrorDeg: the angle of R R_true^T, by atan2 of its skew part."""
    rd = R @ R_true.T
    skew = np.array([rd[2, 1] - rd[1, 2], rd[0, 2] - rd[2, 0], rd[1, 0] - rd[0, 1]])
    return math.degrees(math.atan2(0.5 * np.linalg.norm(skew), 0.5 * (np.trace(rd) - 1.0)))


def score(T, model, scene, d_res):
    truth = np.linalg.inv(model.pose) @ scene.pose
    rot = rotation_error_deg(T[:3, :3], truth[:3, :3])
    trans = float(np.linalg.norm(T[:3, 3] - truth[:3, 3])) / d_res
    return rot, trans, rot <= MAX_ROTATION_DEG and trans <= MAX_TRANSLATION_RES


# ----------------------------------------------------------------------------------------- summary


def band(overlap):
    return 0 if overlap >= 0.5 else 1 if overlap >= 0.3 else 2 if overlap >= 0.1 else 3


def median(values):
    """eval_objects' median: the upper middle element."""
    v = sorted(values)
    return v[len(v) // 2] if v else float("nan")


def summarize(rows):
    """correct/total per band (>= 0.5, 0.3-0.5, 0.1-0.3), wrong (any overlap), wrong under 0.1, median s."""
    total, correct = [0] * 4, [0] * 4
    wrong = wrong_low = 0
    for r in rows:
        b = band(float(r["overlap"]))
        total[b] += 1
        correct[b] += int(r["correct"])
        if int(r["registered"]) and not int(r["correct"]):
            wrong += 1
            wrong_low += b == 3
    return {"bands": ["%d/%d" % (correct[b], total[b]) for b in range(3)], "lt0.1": total[3],
            "wrong": wrong, "wrong_lt0.1": wrong_low,
            "median_s": median([float(r["time_ms"]) for r in rows]) / 1000.0, "pairs": len(rows)}


def summary_rows(objects, done, tensor_rows):
    """Per object: (name, Open3D summary, tensor summary over the same pairs)."""
    table, all_o3d, all_tensor = [], [], []
    for obj in objects:
        rows = [r for r in done if r["object"] == obj]
        if rows:
            keys = {(r["model"], r["scene"]) for r in rows}
            tensor = [r for r in tensor_rows if r["object"] == obj and (r["model"], r["scene"]) in keys]
            table.append((obj, summarize(rows), summarize(tensor)))
            all_o3d += rows
            all_tensor += tensor
    if len(table) > 1:
        table.append(("all", summarize(all_o3d), summarize(all_tensor)))
    return table


def write_markdown(path, table, command):
    """The summary as a markdown table, one row per object, with the command and Open3D's version."""
    cells = lambda s: [*s["bands"], str(s["wrong"]), str(s["wrong_lt0.1"]), "%.2f" % s["median_s"]]
    with open(path, "w") as f:
        f.write("# Open3D FPFH + RANSAC + ICP beside the tensor method, pair by pair\n\n")
        f.write("The pairs of `objects_pairs.csv` (eval_objects: every pair of each set, model first), registered by "
                "`bench/baselines/open3d_fpfh_pairs.py` (Open3D %s) and scored as the tensor method is: correct within "
                "%g deg and %g d_res of the ground truth; columns per overlap band are correct/pairs; **wrong** = a pose "
                "reported (Open3D: RANSAC fitness > 0) that is not correct, at any overlap, and of those the pairs under "
                "0.1 overlap (column < 0.1: how many pairs are); s/pair = median wall time per pair, one thread, "
                "after loading. Per pair: `objects_open3d_pairs.csv`.\n\n" % (
                    o3d.__version__, MAX_ROTATION_DEG, MAX_TRANSLATION_RES))
        f.write("| object | pairs | < 0.1 | Open3D >= 0.5 | 0.3-0.5 | 0.1-0.3 | wrong | wrong < 0.1 | s/pair "
                "| tensor >= 0.5 | 0.3-0.5 | 0.1-0.3 | wrong | wrong < 0.1 | s/pair |\n")
        f.write("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n")
        for obj, o, t in table:
            f.write("| %s | %d | %d | %s | %s |\n" % (obj, o["pairs"], o["lt0.1"], " | ".join(cells(o)),
                                                      " | ".join(cells(t))))
        f.write("\nOpen3D parameters (lengths in leaves, leaf = %.1f d_res, d_res = the pair's mean of the two views' "
                "PreparedScan::resolution): voxel_down_sample(leaf); normals KDTreeSearchParamHybrid(%.0f leaves, max_nn "
                "%d), oriented toward the sensor; FPFH (%.0f leaves, max_nn %d); "
                "registration_ransac_based_on_feature_matching(mutual_filter=%s, %.1f leaves, PointToPoint, ransac_n=%d, "
                "[EdgeLength(%.1f), Distance(%.1f leaves)], RANSACConvergenceCriteria(%d, %g)); registration_icp "
                "point-to-plane, %.1f leaf, from the RANSAC pose, on the downsampled clouds; "
                "o3d.utility.random.seed(%d) before each pair; OMP_NUM_THREADS=1.\n\n" % (
                    LEAF_RES, NORMAL_RADIUS_LEAVES, NORMAL_MAX_NN, FPFH_RADIUS_LEAVES, FPFH_MAX_NN, MUTUAL_FILTER,
                    RANSAC_DISTANCE_LEAVES, RANSAC_N, EDGE_LENGTH_CHECK, RANSAC_DISTANCE_LEAVES,
                    RANSAC_MAX_ITERATIONS, RANSAC_CONFIDENCE, ICP_DISTANCE_LEAVES, SEED))
        f.write("Commands:\n\n```\n%s\n```\n" % command)


def print_summary(objects, done, tensor_rows, out=sys.stdout):
    head = "%-17s %5s | %-7s %-7s %-7s %5s %6s %7s | %-7s %-7s %-7s %5s %6s %7s" % (
        "object", "pairs", ">=0.5", "0.3-0.5", "0.1-0.3", "wrong", "<0.1", "s/pair",
        ">=0.5", "0.3-0.5", "0.1-0.3", "wrong", "<0.1", "s/pair")
    print("%-23s | %-47s | %s" % ("", "Open3D FPFH + RANSAC + ICP", "tensor method (objects_pairs.csv)"), file=out)
    print(head, file=out)
    for obj, o, t in summary_rows(objects, done, tensor_rows):
        print("%-17s %5d | %-7s %-7s %-7s %5d %6d %7.2f | %-7s %-7s %-7s %5d %6d %7.2f" % (
            obj, o["pairs"], *o["bands"], o["wrong"], o["wrong_lt0.1"], o["median_s"],
            *t["bands"], t["wrong"], t["wrong_lt0.1"], t["median_s"]), file=out)


# -------------------------------------------------------------------------------------------- main


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(os.path.dirname(here))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default="", help="output folder: open3d_pairs.csv, open3d_view_resolution.json")
    ap.add_argument("--objects", default="", help="comma-separated subset of the sets (default: every set of the CSV)")
    ap.add_argument("--max-pairs", type=int, default=0, help="the first N pairs of each set (default: all)")
    ap.add_argument("--data", default=os.path.normpath(os.path.join(root, "..", "shared", "data")),
                    help="the shared data folder (default: ../shared/data beside the repository)")
    ap.add_argument("--bin", default=os.path.join(root, "build", "apps"), help="pcl_tensor_views, pcl_tensor_register")
    ap.add_argument("--csv", default=os.path.join(root, "doc", "results", "objects_pairs.csv"),
                    help="the tensor method's per-pair CSV (eval_objects' objects_pairs.csv)")
    ap.add_argument("--views", default="/tmp/o3d_views", help="where the rendered views go, one folder per set")
    ap.add_argument("--resume", action="store_true", help="keep the pairs already in --out's CSV, run the others")
    ap.add_argument("--summarize", metavar="CSV", default="",
                    help="register nothing: print (and --markdown) the summary of an open3d_pairs.csv")
    ap.add_argument("--markdown", default="", help="also write the summary as a markdown table to this file")
    args = ap.parse_args()

    if not args.out and not args.summarize:
        ap.error("--out DIR is required (or --summarize CSV)")
    o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Error)
    with open(args.csv) as f:
        tensor_rows = list(csv.DictReader(f))
    objects = list(dict.fromkeys(r["object"] for r in tensor_rows))
    if args.objects:
        wanted = args.objects.split(",")
        unknown = [o for o in wanted if o not in objects]
        if unknown:
            sys.exit("unknown objects %s; the CSV has %s" % (unknown, ",".join(objects)))
        objects = [o for o in objects if o in wanted]

    if args.summarize:
        with open(args.summarize) as f:
            done = list(csv.DictReader(f))
        objects = [o for o in objects if any(r["object"] == o for r in done)]
        print_summary(objects, done, tensor_rows)
        if args.markdown:
            write_markdown(args.markdown, summary_rows(objects, done, tensor_rows), "/usr/bin/python3 " + " ".join(sys.argv))
        return

    os.makedirs(args.out, exist_ok=True)
    out_csv = os.path.join(args.out, "open3d_pairs.csv")
    done = []
    if args.resume and os.path.exists(out_csv):
        with open(out_csv) as f:
            done = list(csv.DictReader(f))
    finished = {(r["object"], r["model"], r["scene"]) for r in done}
    res_path = os.path.join(args.out, "open3d_view_resolution.json")
    res_cache = json.load(open(res_path)) if os.path.exists(res_path) else {}

    print("Open3D %s, OMP_NUM_THREADS=%s; leaf %.1f d_res, normals r %.0f leaves (max_nn %d), FPFH r %.0f leaves "
          "(max_nn %d), RANSAC %.1f leaves, mutual %s, n %d, %d iterations, confidence %.3f, edge %.1f; "
          "point-to-plane ICP %.1f leaf; seed %d" % (
              o3d.__version__, os.environ["OMP_NUM_THREADS"], LEAF_RES, NORMAL_RADIUS_LEAVES, NORMAL_MAX_NN,
              FPFH_RADIUS_LEAVES, FPFH_MAX_NN, RANSAC_DISTANCE_LEAVES, MUTUAL_FILTER, RANSAC_N,
              RANSAC_MAX_ITERATIONS, RANSAC_CONFIDENCE, EDGE_LENGTH_CHECK, ICP_DISTANCE_LEAVES, SEED), flush=True)

    new_file = not (args.resume and os.path.exists(out_csv))
    with open(out_csv, "w" if new_file else "a", newline="") as fout:
        writer = csv.DictWriter(fout, fieldnames=COLUMNS)
        if new_file:
            writer.writeheader()
        for obj in objects:
            pairs = [r for r in tensor_rows if r["object"] == obj]
            if args.max_pairs > 0:
                pairs = pairs[:args.max_pairs]
            todo = [r for r in pairs if (obj, r["model"], r["scene"]) not in finished]
            if not todo:
                continue
            print("%s: %d pairs" % (obj, len(todo)), flush=True)
            views = load_set(obj, args)
            needed = {r["model"] for r in todo} | {r["scene"] for r in todo}
            missing = needed - set(views)
            if missing:
                sys.exit("%s: views %s of the CSV not found" % (obj, sorted(missing)))
            for name in needed:
                views[name].points = read_ply_xyz(views[name].path)
            view_resolutions(obj, {n: views[n] for n in needed}, args, res_cache)
            with open(res_path, "w") as f:
                json.dump(res_cache, f, indent=1, sort_keys=True)
            for r in todo:
                model, scene = views[r["model"]], views[r["scene"]]
                d_res = 0.5 * (model.d_res + scene.d_res)  # pairResolution
                start = time.perf_counter()
                ransac, icp = register_pair(model, scene, d_res)
                time_ms = (time.perf_counter() - start) * 1000.0
                registered = ransac.fitness > 0.0
                rot = trans = float("nan")
                correct = False
                if registered:
                    rot, trans, correct = score(np.asarray(icp.transformation), model, scene, d_res)
                row = {"object": obj, "model": r["model"], "scene": r["scene"], "overlap": r["overlap"],
                       "registered": int(registered), "correct": int(correct),
                       "rotation_error_deg": "%.6g" % rot, "translation_error_res": "%.6g" % trans,
                       "fitness": "%.6g" % ransac.fitness, "inlier_rmse": "%.6g" % ransac.inlier_rmse,
                       "time_ms": "%.1f" % time_ms}
                writer.writerow(row)
                fout.flush()
                done.append(row)
                print("  %s %s <- %s overlap %.2f: %s (%.1f deg, %.1f d_res) fitness %.3f, %.0f ms" % (
                    obj, r["model"], r["scene"], float(r["overlap"]),
                    "correct" if correct else "WRONG" if registered else "refused", rot, trans, ransac.fitness,
                    time_ms), flush=True)
    print()
    print_summary(objects, done, tensor_rows)
    if args.markdown:
        write_markdown(args.markdown, summary_rows(objects, done, tensor_rows), "/usr/bin/python3 " + " ".join(sys.argv))


if __name__ == "__main__":
    main()
