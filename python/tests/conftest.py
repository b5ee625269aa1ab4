"""Shared fixtures: synthetic views with exact ground truth, made by the project's own renderer."""
import os
import subprocess

import numpy as np
import pytest

APPS = os.environ.get("PCL_TENSOR_APPS", "")
SHARED_DATA = os.environ.get("PCL_TENSOR_SHARED_DATA", "")


def app(name):
    path = os.path.join(APPS, name)
    if not os.access(path, os.X_OK):
        pytest.skip(f"SKIPPED: the app {name} is not built (PCL_TENSOR_APPS={APPS!r})")
    return path


def shared_file(*parts):
    """A file of ../shared/data; the test is skipped, saying so, when it is absent."""
    path = os.path.join(SHARED_DATA, *parts)
    if not os.path.isfile(path):
        pytest.skip(f"SKIPPED: {os.path.join(*parts)} is absent from ../shared/data")
    return path


def quaternion_matrix(qx, qy, qz, qw):
    """R(q) of a unit quaternion (x, y, z, w)."""
    return np.array([
        [1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
        [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
        [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]])


def load_conf(path):
    """Stanford .conf poses, scan -> world: p_world = R(q)^T p + t."""
    poses = {}
    with open(path) as f:
        for line in f:
            fields = line.split()
            if not fields or fields[0] != "bmesh":
                continue
            t = np.array([float(v) for v in fields[2:5]])
            q = [float(v) for v in fields[5:9]]
            pose = np.eye(4)
            pose[:3, :3] = quaternion_matrix(*q).T
            pose[:3, 3] = t
            poses[fields[1]] = pose
    return poses


def rotation_deg(transform):
    r = transform[:3, :3]
    return np.degrees(np.arccos(np.clip((np.trace(r) - 1.0) / 2.0, -1.0, 1.0)))


class Views:
    """A ring of 12 range images of the built-in object, 30 degrees apart, with their true poses."""

    def __init__(self, folder):
        self.folder = folder
        self.poses = load_conf(os.path.join(folder, "views.conf"))

    def path(self, i):
        return os.path.join(self.folder, f"view_{i:02d}.ply")

    def truth(self, model, scene):
        """The transform taking view `scene` into view `model`'s frame."""
        return np.linalg.inv(self.poses[f"view_{model:02d}.ply"]) @ self.poses[f"view_{scene:02d}.ply"]


@pytest.fixture(scope="session")
def ring_views(tmp_path_factory):
    folder = str(tmp_path_factory.mktemp("ring"))
    subprocess.run([app("pcl_tensor_views"), "example", "-o", folder, "--ring", "12", "--size", "300", "300"],
                   check=True, stdout=subprocess.DEVNULL)
    return Views(folder)
