# shellcheck shell=bash
# slam_toolbox (Macenski, ROS 2 branch): its Karto core (lib/karto_sdk, LGPL-3.0) and its Ceres solver plugin
# (solvers/ceres_solver.*, LGPL-2.1), the Nav2 default 2D SLAM without ROS.
# Sourced by scripts/install-slam.sh, which reads these variables.
# shellcheck disable=SC2034
# Built unchanged into one shared library, OUT/lib/libslam_toolbox_karto.so (LGPL: a user can rebuild and relink it;
# only the slam-toolbox driver links it), by the CMake file of scripts/slam/slam-toolbox/ (upstream's need ament).
# Installed besides: Karto's and the solver's headers, the stand-ins below, config/mapper_params_offline.yaml (the
# offline node's parameters, which the driver's defaults are) and both licence files.
#
# Stand-ins (scripts/slam/slam-toolbox/ros/, written for slamsweep, installed with the headers): the ROS names the
# two upstream parts use, each a small header of ours under the include path upstream names:
#   rclcpp/rclcpp.hpp                    ParameterValue, Parameter, Logger and the RCLCPP_* log macros
#   rclcpp_lifecycle/lifecycle_node.hpp  LifecycleNode: Mapper.h's ScanSolver::Configure takes one; the solver
#                                        declares and reads its ceres_* parameters on it, as on the node
#   std_srvs/srv/empty.hpp               empty: the solver's header includes it, nothing uses it
#   pluginlib/class_list_macros.hpp      PLUGINLIB_EXPORT_CLASS as a compile-time check (the driver constructs the
#                                        solver, as the node's plugin loader would)
#   slam_toolbox/toolbox_types.hpp       the two graph iterator types the solver uses (upstream's header pulls in
#                                        tf2 and the toolbox's messages)
# One link-time change, no source patch: the solver asks Ceres for 50 threads, which makes its sums depend on
# thread scheduling; ceres_one_thread.cc, linked with --wrap=ceres::Solve, runs each solve on one thread.
slam_name=slam-toolbox
slam_tarball=slam_toolbox-a3442d2.tar.gz
slam_sha256=5421588cb1b9a49cdfa69d20645d284045f78a97587f3b281c7f363b1b1a61f8
slam_upstream=https://github.com/SteveMacenski/slam_toolbox
slam_commit=a3442d2f6824ff058fab0cb0a635e7a454294855
slam_license="LGPL-3.0 (Karto) and LGPL-2.1 (Ceres solver plugin)"
slam_packages=(libceres-dev libtbb-dev libboost-serialization-dev libboost-thread-dev libboost-system-dev
               libsuitesparse-dev libeigen3-dev)

slam_build() {
  local src=$1 out=$2 here=$slam_files
  cmake -S "$here" -B "$src/_build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSLAM_TOOLBOX_SOURCE="$src" >/dev/null
  cmake --build "$src/_build" -j "$(nproc)"
  # The wrap only works while the solver calls ceres::Solve: an upstream that stopped would leave it unused.
  # nm's list is read whole first: grep -q in a pipe may stop reading early, and under pipefail nm's SIGPIPE
  # would fail the test at random.
  local solve=_ZN5ceres5SolveERKNS_6Solver7OptionsEPNS_7ProblemEPNS0_7SummaryE undefined
  undefined=$(nm -u "$(find "$src/_build" -name 'ceres_solver.cpp.o')")
  if ! grep -q " $solve\$" <<<"$undefined"; then
    echo "slam-toolbox: solvers/ceres_solver.cpp no longer calls ceres::Solve(options, problem, summary)" >&2
    return 1
  fi
  mkdir -p "$out/lib" "$out/include/solvers" "$out/share/slam-toolbox"
  cp "$src/_build/libslam_toolbox_karto.so" "$out/lib/"
  cp -r "$src/lib/karto_sdk/include/karto_sdk" "$out/include/"
  cp "$src/solvers/ceres_solver.hpp" "$src/solvers/ceres_utils.h" "$out/include/solvers/"
  cp -r "$here/ros/." "$out/include/"
  cp "$src/config/mapper_params_offline.yaml" "$out/share/slam-toolbox/"
  cp "$src/LICENSE" "$out/LICENSE"
  cp "$src/lib/karto_sdk/LICENSE" "$out/LICENSE.karto_sdk"
  cp "$src/package.xml" "$out/"
}
