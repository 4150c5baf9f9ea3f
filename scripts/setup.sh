#!/usr/bin/env bash
# Installs every Debian 12 package the build and tests need. Idempotent: a quick
# no-op when all are present. Runs apt-get update before installing; uses sudo when
# not root.
set -euo pipefail

PACKAGES=(
  g++ cmake make pkg-config git
  libbullet-dev
  liborocos-kdl-dev liburdfdom-dev libtinyxml-dev  # the robot model (URDF) and its kinematics (KDL)
  libeigen3-dev
  libopencv-dev
  libyaml-cpp-dev
  libsqlite3-dev sqlite3
  libosmesa6-dev
  libcli11-dev
  libspdlog-dev libfmt-dev
  libgtest-dev libgmock-dev
  libbenchmark-dev
  clang-format
  clang-14 libclang-rt-14-dev  # scripts/fuzz: clang with libFuzzer and the sanitizer runtimes
  slurm-wlm munge iproute2  # the sweep tests' single-node Slurm (tests/support/local_slurm.sh)
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi

echo "setup: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
