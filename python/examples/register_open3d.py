#!/usr/bin/env python3
"""Register two range scans loaded with Open3D, with pcl_tensor, and write the aligned clouds.

Prints the time pcl_tensor took next to Open3D's own FPFH + RANSAC on the same pair, and how far
apart the two answers are. pcl_tensor answers "not registered" (exit code 3) when it cannot verify a
pose; RANSAC always returns one.

    python3 register_open3d.py MODEL.ply SCENE.ply [-o OUT_DIR]
    # e.g. the raw Stanford bunny scans:
    python3 register_open3d.py ../shared/data/stanford/bunny/bun000.ply ../shared/data/stanford/bunny/bun045.ply
"""
import argparse
import os
import sys
import time

import numpy as np
import open3d as o3d

import pcl_tensor


def open3d_fpfh_ransac(model, scene, voxel):
    """Open3D's global registration tutorial: FPFH on a voxel-downsampled cloud, then RANSAC."""
    reg = o3d.pipelines.registration

    def features(cloud):
        down = cloud.voxel_down_sample(voxel)
        down.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=2 * voxel, max_nn=30))
        fpfh = reg.compute_fpfh_feature(down, o3d.geometry.KDTreeSearchParamHybrid(radius=5 * voxel, max_nn=100))
        return down, fpfh

    model_down, model_fpfh = features(model)
    scene_down, scene_fpfh = features(scene)
    distance = 1.5 * voxel
    result = reg.registration_ransac_based_on_feature_matching(
        scene_down, model_down, scene_fpfh, model_fpfh, True, distance,
        reg.TransformationEstimationPointToPoint(False), 3,
        [reg.CorrespondenceCheckerBasedOnEdgeLength(0.9), reg.CorrespondenceCheckerBasedOnDistance(distance)],
        reg.RANSACConvergenceCriteria(100000, 0.999))
    return result.transformation


def rotation_deg(transform):
    return np.degrees(np.arccos(np.clip((np.trace(transform[:3, :3]) - 1.0) / 2.0, -1.0, 1.0)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("model")
    parser.add_argument("scene")
    parser.add_argument("-o", "--out", default="out/open3d_example", help="folder for the aligned clouds")
    args = parser.parse_args()

    model = o3d.io.read_point_cloud(args.model)
    scene = o3d.io.read_point_cloud(args.scene)
    # Open3D keeps the points, not the sensor: take each scan's sensor from its file (a PCD's pose, the
    # pushbroom a PLY range grid fits, else +z).
    _, model_sensor = pcl_tensor.load_scan(args.model)
    _, scene_sensor = pcl_tensor.load_scan(args.scene)

    start = time.perf_counter()
    result = pcl_tensor.register(np.asarray(model.points), np.asarray(scene.points), model_sensor, scene_sensor)
    tensor_s = time.perf_counter() - start

    voxel = 2.5 * result.report["resolution"] if result.report["resolution"] > 0 else 0.002
    start = time.perf_counter()
    ransac = open3d_fpfh_ransac(model, scene, voxel)
    ransac_s = time.perf_counter() - start

    print(f"pcl_tensor:         {tensor_s * 1000:8.0f} ms  {'registered' if result.registered else 'NOT registered'}")
    print(f"Open3D FPFH+RANSAC: {ransac_s * 1000:8.0f} ms  (always returns a pose)")
    if not result.registered:
        print("pcl_tensor could not verify a pose" + (" (two distinct poses fit)" if result.ambiguous else ""))
        return 3
    delta = np.linalg.inv(result.transform) @ ransac
    print(f"the two poses differ by {rotation_deg(delta):.2f} deg and "
          f"{np.linalg.norm(delta[:3, 3]) / result.report['resolution']:.1f} d_res")
    print("transform (scene -> model):")
    print(np.array2string(result.transform, precision=6, suppress_small=True))

    os.makedirs(args.out, exist_ok=True)
    model.paint_uniform_color([0.2, 0.4, 0.9])
    aligned = o3d.geometry.PointCloud(scene).transform(result.transform)
    aligned.paint_uniform_color([0.9, 0.4, 0.2])
    o3d.io.write_point_cloud(os.path.join(args.out, "model.ply"), model)
    o3d.io.write_point_cloud(os.path.join(args.out, "scene_aligned.ply"), aligned)
    print(f"wrote {args.out}/model.ply and {args.out}/scene_aligned.ply")
    return 0


if __name__ == "__main__":
    sys.exit(main())
