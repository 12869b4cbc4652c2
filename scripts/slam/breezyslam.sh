# shellcheck shell=bash
# Sourced by scripts/install-slam.sh, which reads these variables.
# shellcheck disable=SC2034
# BreezySLAM: CoreSLAM/tinySLAM by its authors' successors, in C with a C++ API (RMHC_SLAM). Built
# only as an independent tinySLAM for a test to compare slam-constructor's against: a static
# library (LGPL-3.0, linked into that test program alone) with its headers in include/breezyslam.
slam_name=breezyslam
slam_tarball=BreezySLAM-1170285.tar.gz
slam_sha256=2a361a1fb5cbd9c068a2e7bf33d8adf022f9b2231e5d57745a1046ffd30d64b0
slam_upstream=https://github.com/simondlevy/BreezySLAM
slam_commit=1170285cd42a88300eddd275fc3df36e642e3a2e
slam_license=LGPL-3.0
slam_packages=()

slam_build() {
  local src=$1 out=$2 objects=()
  mkdir -p "$src/_build" "$out/lib" "$out/include/breezyslam"
  # The files its own cpp/Makefile puts in libbreezyslam, with the portable (sisd) core.
  for file in c/coreslam.c c/coreslam_sisd.c c/random.c c/ziggurat.c; do
    gcc -O3 -fPIC -I"$src/c" -c "$src/$file" -o "$src/_build/$(basename "$file" .c).o"
    objects+=("$src/_build/$(basename "$file" .c).o")
  done
  for file in cpp/algorithms.cpp cpp/Scan.cpp cpp/Map.cpp cpp/WheeledRobot.cpp; do
    g++ -O3 -fPIC -I"$src/c" -c "$src/$file" -o "$src/_build/$(basename "$file" .cpp).o"
    objects+=("$src/_build/$(basename "$file" .cpp).o")
  done
  ar rcs "$out/lib/libbreezyslam.a" "${objects[@]}"
  cp "$src"/cpp/*.hpp "$src"/c/*.h "$out/include/breezyslam/"
  cp "$src/LICENSE.md" "$out/"
}
