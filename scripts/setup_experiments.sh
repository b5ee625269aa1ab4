#!/usr/bin/env bash
# What scripts/experiments.sh needs on top of scripts/setup.sh: gnuplot (PNG output, no X11) from Debian.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends gnuplot-nox > /dev/null
echo "pcl_tensor: experiment dependencies installed"
