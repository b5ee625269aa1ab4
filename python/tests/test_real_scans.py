"""The raw Stanford bunny scans (../shared/data): the bindings give the app's transform bit for bit."""
import json
import subprocess

import numpy as np

import pcl_tensor
from conftest import app, shared_file


def test_bunny_pair_gives_the_app_transform_bit_for_bit():
    model = shared_file("stanford", "bunny", "bun000.ply")
    scene = shared_file("stanford", "bunny", "bun045.ply")
    run = subprocess.run([app("pcl_tensor_register"), model, scene, "--json"], capture_output=True, text=True, check=True)
    expected = json.loads(run.stdout)
    result = pcl_tensor.register(model, scene)
    assert result.registered and expected["status"] == "registered"
    assert np.array_equal(result.transform, np.array(expected["transform"]).reshape(4, 4))
    assert result.report["hypotheses_tried"] == expected["hypotheses_tried"]


def test_load_scan_gives_the_finite_points_and_the_fitted_pushbroom():
    points, viewpoint = pcl_tensor.load_scan(shared_file("stanford", "bunny", "bun045.ply"))
    assert points.shape == (40097, 3)  # the finite cells of its 512 x 400 grid
    assert np.isfinite(points).all()
    assert viewpoint.model == "pushbroom"
    assert viewpoint.sensor_pose.shape == (4, 4)
