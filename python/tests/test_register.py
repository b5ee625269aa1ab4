"""pcl_tensor.register on synthetic views with exact ground truth (the built-in object, 30 degrees apart)."""
import json
import subprocess

import numpy as np
import pytest

import pcl_tensor
from conftest import app, rotation_deg

SENSOR_AT_ORIGIN = (0.0, 0.0, 0.0)  # the renderer puts each view's sensor at its frame's origin


def pose_errors(result, truth):
    delta = np.linalg.inv(truth) @ result.transform
    return rotation_deg(delta), np.linalg.norm(result.transform[:3, 3] - truth[:3, 3]) / result.report["resolution"]


def test_adjacent_files_register_within_half_a_degree_and_one_resolution(ring_views):
    result = pcl_tensor.register(ring_views.path(0), ring_views.path(1), SENSOR_AT_ORIGIN, SENSOR_AT_ORIGIN)
    assert result.registered and bool(result) and not result.ambiguous
    assert result.transform.shape == (4, 4) and result.transform.dtype == np.float64
    rotation, translation = pose_errors(result, ring_views.truth(0, 1))
    assert rotation < 0.5
    assert translation < 1.0


def test_adjacent_arrays_register_within_half_a_degree_and_one_resolution(ring_views):
    model, _ = pcl_tensor.load_scan(ring_views.path(3))
    scene, _ = pcl_tensor.load_scan(ring_views.path(4))
    assert model.dtype == np.float64 and model.ndim == 2 and model.shape[1] == 3
    assert np.isfinite(model).all()
    result = pcl_tensor.register(model, scene, model_viewpoint=SENSOR_AT_ORIGIN, scene_viewpoint=SENSOR_AT_ORIGIN)
    assert result.registered
    rotation, translation = pose_errors(result, ring_views.truth(3, 4))
    assert rotation < 0.5
    assert translation < 1.0


def test_float32_arrays_and_viewpoint_objects_are_taken(ring_views):
    model, _ = pcl_tensor.load_scan(ring_views.path(3))
    scene, _ = pcl_tensor.load_scan(ring_views.path(4))
    as_float64 = pcl_tensor.register(model, scene, SENSOR_AT_ORIGIN, SENSOR_AT_ORIGIN)
    centroid = lambda points: points.mean(axis=0)
    result = pcl_tensor.register(model.astype(np.float32), scene.astype(np.float32),
                                 pcl_tensor.Viewpoint.looking_at(SENSOR_AT_ORIGIN, centroid(model)),
                                 pcl_tensor.Viewpoint.looking_at(SENSOR_AT_ORIGIN, centroid(scene)))
    # The points are floats in C++ either way, so both calls see the same scans and sensors.
    assert result.registered
    assert np.array_equal(result.transform, as_float64.transform)


def test_opposite_views_are_not_registered(ring_views):
    result = pcl_tensor.register(ring_views.path(0), ring_views.path(6), SENSOR_AT_ORIGIN, SENSOR_AT_ORIGIN)
    assert not result.registered and not bool(result)
    assert np.array_equal(result.transform, np.eye(4))
    assert result.report["status"] == "not_registered"
    assert result.report["hypotheses_tried"] > 0


def test_report_has_the_fields_and_transform_of_the_app(ring_views):
    run = subprocess.run([app("pcl_tensor_register"), ring_views.path(0), ring_views.path(1), "--json",
                          "--viewpoint", "0,0,0"], capture_output=True, text=True, check=True)
    expected = json.loads(run.stdout)
    result = pcl_tensor.register(ring_views.path(0), ring_views.path(1), SENSOR_AT_ORIGIN, SENSOR_AT_ORIGIN)
    assert set(result.report) == set(expected)
    assert set(result.report["timings_ms"]) == set(expected["timings_ms"])
    assert np.array_equal(result.transform, np.array(expected["transform"]).reshape(4, 4))
    assert result.report["winning_match"] == expected["winning_match"]


def test_keyword_parameters_mirror_the_parameter_struct(ring_views):
    defaults = pcl_tensor.RegistrationParams()
    assert defaults.grid_size == 10 and defaults.overlap_threshold == pytest.approx(0.5)
    assert defaults.fallback_overlap_threshold == pytest.approx(0.4) and defaults.fallback_correlation_threshold == pytest.approx(0.4)
    assert defaults.preparation.target_faces == 1000
    assert defaults.order == pcl_tensor.MatchOrder.BEST_FIRST
    assert "max_hypotheses" in pcl_tensor.RegistrationParams._fields
    # A cap of one hypothesis tries at most one; a nested struct is set from a dict.
    result = pcl_tensor.register(ring_views.path(0), ring_views.path(6), SENSOR_AT_ORIGIN, SENSOR_AT_ORIGIN,
                                 max_hypotheses=1, ambiguity_checks=0, verification=dict(sample_points=500),
                                 preparation={"target_faces": 800})
    assert result.report["hypotheses_tried"] <= 1
    assert not result.registered
