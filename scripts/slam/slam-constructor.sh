# shellcheck shell=bash
# slam-constructor (OSLL): the framework whose tinySLAM and vinySLAM the paper's authors wrote.
# Sourced by scripts/install-slam.sh, which reads these variables.
# shellcheck disable=SC2034
# Header-only: src/core, src/utils, src/slams and the properties files in config/ go to OUT as they
# are (ROS is only needed by src/ros, which is not installed).
slam_name=slam-constructor
slam_tarball=slam-constructor-d70196c.tar.gz
slam_sha256=b6fccfcaee0c3dd009638b63c6e2625dcb971d21d726a138ed29583fc1686948
slam_upstream=https://github.com/OSLL/slam-constructor
slam_commit=d70196c00609ee35e808cc066d700c1c5e2e81b7
slam_license=MIT
slam_packages=()

slam_build() {
  local src=$1 out=$2
  mkdir -p "$out/src"
  cp -r "$src/src/core" "$src/src/utils" "$src/src/slams" "$out/src/"
  cp -r "$src/config" "$out/"
  cp "$src/package.xml" "$out/"
  [[ -f "$src/LICENSE" ]] && cp "$src/LICENSE" "$out/"
  return 0
}
