#!/usr/bin/env python3
"""Which poses fit the scans better: the ground truth's or ours?

For each pair of neighbouring views (a turntable ring, in the .conf's order, closing the loop) or every pair
(--all-pairs), one view's points are put into the other's frame under each set of poses, and the RMS
point-to-plane distance (in d_res) of the points within 3 d_res of the other view is reported. A ground truth
that disagrees with our poses by half a degree while fitting the data worse is not the truer of the two.

    python3 bench/scale/truth_residuals.py ../shared/data/stanford/dragon_stand/dragonStandRight.conf model.conf

Needs python3-open3d (normals and nearest neighbours) and numpy.
"""
import argparse
import itertools
import os
import sys

import numpy as np
import open3d as o3d

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scale_benchmark as sb  # noqa: E402  (load_conf)


def load_ascii_ply_points(path):
    """The vertices of an ASCII PLY range scan (the raw Stanford scans)."""
    with open(path) as f:
        lines = f.read().split("\n")
    end = lines.index("end_header")
    count = int(next(l for l in lines[:end] if l.startswith("element vertex")).split()[2])
    return np.array([[float(x) for x in l.split()[:3]] for l in lines[end + 1:end + 1 + count]])


def cloud_with_normals(points):
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    cloud.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(12))
    return cloud


def rms_point_to_plane(target, target_tree, source_points, d_res, step=5):
    """RMS distance (d_res) of every step-th source point to the nearest target point's tangent plane,
    over those within 3 d_res; and how many there were."""
    points, normals = np.asarray(target.points), np.asarray(target.normals)
    residuals = []
    for p in source_points[::step]:
        _, index, d2 = target_tree.search_knn_vector_3d(p, 1)
        if d2[0] < (3.0 * d_res) ** 2:
            residuals.append(np.dot(p - points[index[0]], normals[index[0]]))
    if not residuals:
        return float("nan"), 0
    return float(np.sqrt(np.mean(np.square(residuals)))) / d_res, len(residuals)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("truth", help="ground-truth .conf (its scans lie beside it)")
    ap.add_argument("estimate", help="our poses, a .conf written by pcl_tensor_model")
    ap.add_argument("--resolution", type=float, default=0.0, help="d_res (default: the median spacing of the first scan)")
    ap.add_argument("--all-pairs", action="store_true", help="every pair, not neighbours on a ring")
    ap.add_argument("--min-points", type=int, default=500, help="pairs with fewer points in common are skipped")
    args = ap.parse_args()

    truth, estimate = sb.load_conf(args.truth), sb.load_conf(args.estimate)
    names = [n for n in truth if n in estimate]
    folder = os.path.dirname(os.path.abspath(args.truth))
    clouds = {n: cloud_with_normals(load_ascii_ply_points(os.path.join(folder, n))) for n in names}
    trees = {n: o3d.geometry.KDTreeFlann(c) for n, c in clouds.items()}
    d_res = args.resolution or float(np.median(clouds[names[0]].compute_nearest_neighbor_distance()))

    pairs = list(itertools.combinations(names, 2)) if args.all_pairs else \
        [(names[i], names[(i + 1) % len(names)]) for i in range(len(names))]
    rows = []
    for a, b in pairs:
        fits = []
        for poses in (truth, estimate):
            t = np.linalg.inv(poses[a]) @ poses[b]
            moved = (t[:3, :3] @ np.asarray(clouds[b].points).T).T + t[:3, 3]
            fits.append(rms_point_to_plane(clouds[a], trees[a], moved, d_res))
        if min(fits[0][1], fits[1][1]) < args.min_points:
            continue
        rows.append((fits[0][0], fits[1][0]))
        print("%s %s  truth %.3f  ours %.3f  (%d points)" % (a, b, fits[0][0], fits[1][0], fits[1][1]))
    if rows:
        t, e = np.array(rows).T
        print("median RMS point-to-plane, d_res %.6g: truth %.3f, ours %.3f; ours lower in %d of %d pairs"
              % (d_res, np.median(t), np.median(e), int(np.sum(e < t)), len(rows)))


if __name__ == "__main__":
    main()
