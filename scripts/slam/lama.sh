# shellcheck shell=bash
# iris_lama (LaMa, IRIS lab, University of Aveiro): Slam2D (online graph-free SLAM: scan-to-map matching on a
# dynamic distance map) and PFSlam2D (a particle filter whose particles carry such maps). BSD-3-Clause.
# Sourced by scripts/install-slam.sh, which reads these variables.
# shellcheck disable=SC2034
# Built with its own CMake files, unchanged, as a shared library (Release): OUT/lib/libiris_lama.so with
# OUT/include/lama. The library compiles a vendored minisam whose sparse Cholesky includes Eigen's Amd.h,
# LGPL-2.1 (vendor/minisam/minisam/3rdparty/eigen3/COPYING.LGPL), and vendored zstd and lz4 (BSD): shared, so
# that a user can rebuild and relink it; only the lama and lama-pf drivers link it. Every licence file goes
# to OUT beside it.
slam_name=lama
slam_tarball=iris_lama-fd60e55.tar.gz
slam_sha256=83f8e81ad8fe962ff1d2c13daaed7c27899aa36945f811250bc1343e1d843d91
slam_upstream=https://github.com/iris-ua/iris_lama
slam_commit=fd60e55db67f59114a4ff0443519b34d484f92cf
slam_license="BSD-3-Clause; its vendored minisam compiles Eigen's Amd.h, LGPL-2.1"
slam_packages=(libeigen3-dev)

slam_build() {
  local src=$1 out=$2
  # Its CMakeLists.txt sets no build type: Release is asked for here, and position-independent code for the
  # vendored object libraries it links into the shared library.
  cmake -S "$src" -B "$src/_build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON \
    -DCMAKE_POSITION_INDEPENDENT_CODE=ON -DCMAKE_INSTALL_PREFIX="$out" -DCMAKE_INSTALL_LIBDIR=lib >/dev/null
  cmake --build "$src/_build" -j "$(nproc)"
  cmake --install "$src/_build" >/dev/null
  cp "$src/LICENSE.txt" "$out/LICENSE.txt"
  cp "$src/vendor/minisam/LICENSE" "$out/LICENSE.minisam"
  cp "$src/vendor/minisam/minisam/3rdparty/eigen3/COPYING.LGPL" "$out/COPYING.LGPL.minisam-eigen-amd"
  cp "$src/vendor/zstd/zstd/LICENSE" "$out/LICENSE.zstd"  # lz4 carries its BSD-2-Clause notice in its files
  cp "$src/package.xml" "$out/"
}
