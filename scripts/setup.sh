#!/usr/bin/env bash
# Installs exactly what pcl_tensor needs on Debian 12 (bookworm): the library, its Python module and
# its tests, clang for the fuzz targets included. Run as root (or with sudo).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  ca-certificates cmake g++ make \
  libpcl-dev libqhull-dev libmeshoptimizer-dev nlohmann-json3-dev \
  pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed \
  libgtest-dev googletest libbenchmark-dev \
  clang libclang-rt-14-dev > /dev/null
echo "pcl_tensor: build dependencies installed"
