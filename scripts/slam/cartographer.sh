# shellcheck shell=bash
# Sourced by scripts/install-slam.sh, which reads these variables.
# shellcheck disable=SC2034
# Cartographer (Hess et al.): the library with its 2D trajectory builder and pose graph, static,
# Release, without its tests, benchmarks, gRPC or Prometheus. Installed into OUT: lib/libcartographer.a,
# include/cartographer/** (sources' headers and the generated protobuf headers) and
# share/cartographer/configuration_files (the Lua options the driver starts from).
slam_name=cartographer
slam_tarball=cartographer-877157a.tar.gz
slam_sha256=c5f4152ce96b158a31848508b275965b6be87fff4459424ec33bbefe21a31826
slam_upstream=https://github.com/cartographer-project/cartographer
slam_commit=877157a0d91788a7700221d87232d412cb3c1ef4
slam_license=Apache-2.0
slam_packages=(libceres-dev libabsl-dev liblua5.3-dev libprotobuf-dev protobuf-compiler libcairo2-dev
               libgoogle-glog-dev libgflags-dev libboost-iostreams-dev libsuitesparse-dev libgmock-dev)

slam_build() {
  local src=$1 out=$2
  # Only the library target is built: configuring still needs GMock (its tests are declared), which
  # is why libgmock-dev is listed; nothing of the tests is compiled.
  cmake -S "$src" -B "$src/_build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_POSITION_INDEPENDENT_CODE=ON \
    -DBUILD_GRPC=OFF -DBUILD_PROMETHEUS=OFF >/dev/null
  cmake --build "$src/_build" -j "$(nproc)" --target cartographer
  mkdir -p "$out/lib" "$out/include" "$out/share/cartographer"
  cp "$src/_build/libcartographer.a" "$out/lib/"
  (cd "$src" && find cartographer -name '*.h' -exec cp --parents {} "$out/include/" \;)
  (cd "$src/_build" && find cartographer -name '*.h' -exec cp --parents {} "$out/include/" \;)
  cp -r "$src/configuration_files" "$out/share/cartographer/"
  cp "$src/LICENSE" "$src/package.xml" "$out/"
}
