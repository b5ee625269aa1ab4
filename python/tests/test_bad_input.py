"""Bad input raises the documented Python exception; nothing crashes."""
import numpy as np
import pytest

import pcl_tensor

GOOD = np.random.default_rng(3).normal(size=(500, 3))


@pytest.mark.parametrize("points", [
    np.zeros((10, 2)),                       # two coordinates
    np.zeros((10, 4)),                       # four
    np.zeros(30),                            # flat
    np.zeros((2, 3, 4, 3)),                  # four dimensions
    np.zeros((0, 3)),                        # empty
    np.full((100, 3), np.nan),               # NaN only
    np.array([[0.0, 0, 0], [1, 1, 1], [np.nan, 0, 0], [np.inf, 1, 2]]),  # two finite points
    np.arange(300).reshape(100, 3),          # integers
    np.zeros((100, 3), dtype=np.complex128),
    np.array([["a", "b", "c"]] * 5),         # strings
])
def test_bad_arrays_raise_value_error(points):
    with pytest.raises(ValueError):
        pcl_tensor.register(points, GOOD)
    with pytest.raises(ValueError):
        pcl_tensor.register(GOOD, points)


def test_missing_and_malformed_files_raise_os_error(tmp_path):
    with pytest.raises(OSError):
        pcl_tensor.load_scan(tmp_path / "missing.ply")
    with pytest.raises(OSError):
        pcl_tensor.register(str(tmp_path / "missing.ply"), GOOD)
    bad = tmp_path / "bad.ply"
    bad.write_bytes(b"ply\nformat ascii 1.0\nelement vertex 99999999\nproperty float x\nend_header\n1 2\n")
    with pytest.raises(OSError):
        pcl_tensor.load_scan(bad)
    with pytest.raises(OSError):
        pcl_tensor.build_model([str(bad), GOOD])


def test_unknown_parameters_and_wrong_types_raise_type_error():
    with pytest.raises(TypeError, match="no parameter 'grid'"):
        pcl_tensor.register(GOOD, GOOD, grid=10)
    with pytest.raises(TypeError):
        pcl_tensor.register(GOOD, GOOD, grid_size="ten")
    with pytest.raises(TypeError):
        pcl_tensor.register(GOOD, GOOD, preparation=dict(faces=10))
    with pytest.raises(TypeError):
        pcl_tensor.build_model([GOOD, GOOD], pairwise=dict(grid=3))


@pytest.mark.parametrize("params", [
    dict(grid_size=0), dict(overlap_threshold=1.5), dict(fallback_overlap_threshold=-0.1), dict(max_hypotheses=-1),
    dict(preparation=dict(target_faces=2)),
    dict(verification=dict(sample_points=0)), dict(object_dimensions=(1.0, -1.0, 1.0)),
])
def test_out_of_range_parameters_raise_value_error(params):
    with pytest.raises(ValueError):
        pcl_tensor.register(GOOD, GOOD, **params)


@pytest.mark.parametrize("params", [
    dict(global_=dict(max_distance=-1.0)), dict(min_overlap=2.0), dict(max_references=-1),
    dict(global_verification=dict(checked_dimensions=5)), dict(integration=dict(voxel_size=-1.0)),
])
def test_bad_model_parameters_are_refused_before_any_view_is_read(params):
    # The views do not exist: a parameter error, not an OSError, shows the parameters came first.
    with pytest.raises(ValueError):
        pcl_tensor.build_model(["/nonexistent/a.ply", "/nonexistent/b.ply"], **params)


def test_bad_viewpoints_raise_value_error():
    with pytest.raises(ValueError):
        pcl_tensor.register(GOOD, GOOD, model_viewpoint=(1.0, 2.0))
    with pytest.raises(ValueError):
        pcl_tensor.register(GOOD, GOOD, model_viewpoint=(np.nan, 0.0, 0.0))
    with pytest.raises(ValueError):
        pcl_tensor.Viewpoint(np.ones((4, 4)))
    with pytest.raises(ValueError):
        pcl_tensor.Viewpoint(np.eye(4), model="fisheye")
    with pytest.raises(ValueError):
        pcl_tensor.build_model([GOOD, GOOD], viewpoints=[None])


def test_bad_view_lists_raise_value_error():
    with pytest.raises(ValueError):
        pcl_tensor.build_model([GOOD])
    with pytest.raises(ValueError):
        pcl_tensor.build_model("view.ply")
