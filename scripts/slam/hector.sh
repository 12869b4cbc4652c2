# shellcheck shell=bash
# hector_slam: Hector SLAM's scan matcher and multi-resolution map, hector_slam_lib (header-only, Eigen).
# Sourced by scripts/install-slam.sh, which reads these variables.
# shellcheck disable=SC2034
# Installed: hector_mapping/include/hector_slam_lib into OUT/include, and the licence file.
slam_name=hector
slam_tarball=hector_slam-b7d19bf.tar.gz
slam_sha256=a2cce7650a4e0315a8aa0a4b92f36fc641295d9386276d239798a66c4d27010c
slam_upstream=https://github.com/tu-darmstadt-ros-pkg/hector_slam
slam_commit=b7d19bfee3c2848d611e8da142445b896790d7fb
slam_license=BSD
slam_packages=(libeigen3-dev)

slam_build() {
  local src=$1 out=$2 lib=$1/hector_mapping/include/hector_slam_lib
  # util/UtilFunctions.h is ROS-free but for one helper, getYawFromQuat, which converts a ROS
  # quaternion message through ROS tf and which nothing in the library calls. Dropping the tf include
  # and that helper makes the library build without ROS; the rest is used as it is.
  sed -i -e '/#include <tf\/LinearMath\/Transform.h>/d' \
         -e '/^static double getYawFromQuat(const geometry_msgs::Quaternion &quat)$/,/^}$/d' "$lib/util/UtilFunctions.h"
  if grep -q 'tf::\|geometry_msgs' "$lib/util/UtilFunctions.h"; then
    echo "hector: the tf helper patch no longer applies to util/UtilFunctions.h" >&2
    return 1
  fi
  mkdir -p "$out/include"
  cp -r "$lib" "$out/include/"
  cp "$src/hector_mapping/package.xml" "$out/"
}
