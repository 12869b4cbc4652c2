# shellcheck shell=bash
# openslam_gmapping: GMapping (Grisetti, Stachniss, Burgard), the RBPF of the paper's roster.
# Sourced by scripts/install-slam.sh, which reads these variables.
# shellcheck disable=SC2034
# Built: the libraries the driver links (utils, sensor_*, scanmatcher, gridfastslam and what they
# need), static, into OUT/lib with the headers in OUT/include. gfs_nogui is not built: it busy-waits
# on its worker thread and needs a GCC 12 fix; slam/gmapping drives GridSlamProcessor directly.
slam_name=gmapping
slam_tarball=openslam_gmapping-5105476.tar.gz
slam_sha256=363fa1cdf40ae8e5ff4d983ad5294345f5fb40f144b5a199b561492f6870557d
slam_upstream=https://github.com/ros-perception/openslam_gmapping
slam_commit=5105476edb125bd3e05df3583b5817c486238dec
slam_license=BSD
slam_packages=()

slam_build() {
  local src=$1 out=$2
  # Its CMakeLists.txt is a catkin package file. Catkin is not needed to build the libraries: drop
  # find_package(catkin) and the catkin_package(...) block, and give the CATKIN_* folders on the
  # command line below. Nothing else changes.
  sed -i -e '/^find_package(catkin REQUIRED)/d' -e '/^catkin_package(/,/^)/d' "$src/CMakeLists.txt"
  cmake -S "$src" -B "$src/_build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_POSITION_INDEPENDENT_CODE=ON \
    -DCMAKE_INSTALL_PREFIX="$out" -DCATKIN_DEVEL_PREFIX="$src/_build/devel" \
    -DCATKIN_PACKAGE_LIB_DESTINATION=lib -DCATKIN_PACKAGE_BIN_DESTINATION=bin \
    -DCATKIN_GLOBAL_BIN_DESTINATION=bin -DCATKIN_GLOBAL_INCLUDE_DESTINATION=include >/dev/null
  cmake --build "$src/_build" -j "$(nproc)" --target utils sensor_base sensor_odometry sensor_range log configfile scanmatcher gridfastslam
  # install would also want the test programs; copy the libraries and headers it would install.
  mkdir -p "$out/lib" "$out/include"
  find "$src/_build" -maxdepth 1 -name 'lib*.a' -exec cp {} "$out/lib/" \;
  cp -r "$src/include/gmapping" "$out/include/"
  cp -r "$src/_build/devel/include/gmapping/." "$out/include/gmapping/"
  cp "$src/package.xml" "$out/"
}
