"""pcl_tensor.build_model: the whole job, as pcl_tensor_model does it."""
import numpy as np

import pcl_tensor
from conftest import rotation_deg


def test_a_ring_of_views_becomes_one_model_with_the_true_poses(ring_views):
    paths = [ring_views.path(i) for i in range(12)]
    model = pcl_tensor.build_model(paths, loop=True, viewpoints=[(0.0, 0.0, 0.0)] * 12)
    assert model.status == ["registered"] * 12
    assert model.names == paths
    assert model.report["registered"] == 12
    resolution = model.report["resolution"]
    for i, pose in enumerate(model.poses):
        truth = ring_views.truth(0, i)  # the common frame is view 0's
        assert rotation_deg(np.linalg.inv(truth) @ pose) < 0.5
        assert np.linalg.norm(pose[:3, 3] - truth[:3, 3]) < 2.0 * resolution
    assert model.vertices.shape[1] == 3 and len(model.vertices) > 1000
    assert model.normals.shape == model.vertices.shape
    assert np.allclose(np.linalg.norm(model.normals, axis=1), 1.0, atol=1e-3)
    assert model.faces.shape[1] == 3 and model.faces.min() >= 0 and model.faces.max() < len(model.vertices)
    assert model.report["mesh"]["triangles"] == len(model.faces)


def test_a_view_of_another_object_is_left_out(ring_views, tmp_path):
    other = np.random.default_rng(11).normal(scale=0.05, size=(3000, 3))
    model = pcl_tensor.build_model([ring_views.path(0), other, ring_views.path(1)],
                                   viewpoints=[(0.0, 0.0, 0.0), None, (0.0, 0.0, 0.0)])
    assert model.status == ["registered", "not_registered", "registered"]
    assert model.poses[1] is None
    assert model.names[1] == "view 1"


def test_views_of_known_poses_keep_them_and_new_views_join_them(ring_views):
    paths = [ring_views.path(i) for i in range(4)]
    known = [ring_views.truth(0, i) for i in range(3)] + [None]
    model = pcl_tensor.build_model(paths, viewpoints=[(0.0, 0.0, 0.0)] * 4, known_poses=known)
    assert model.status == ["registered"] * 4
    for i in range(3):
        assert np.array_equal(model.poses[i], known[i]), "a known pose moved"
    truth = ring_views.truth(0, 3)
    assert rotation_deg(np.linalg.inv(truth) @ model.poses[3]) < 0.5
    assert np.linalg.norm(model.poses[3][:3, 3] - truth[:3, 3]) < 2.0 * model.report["resolution"]
    assert [v["pose_kept"] for v in model.report["views"]] == [True, True, True, False]
