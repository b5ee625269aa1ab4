#!/bin/sh
# Install the Python baselines' dependencies (bench/baselines/): Open3D 0.16 and numpy from Debian 12's
# own packages. Run as root (or it uses sudo) on Debian 12 (bookworm).
# Debian's python3-open3d installs into the system interpreter, /usr/bin/python3: run the baselines with
# it (a pyenv or venv python3 earlier on PATH does not see the package).
set -eu
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends python3-open3d python3-numpy > /dev/null
/usr/bin/python3 -c 'import open3d, numpy; print("pcl_tensor baselines: open3d", open3d.__version__, "numpy", numpy.__version__, "for /usr/bin/python3")'
