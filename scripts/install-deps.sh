#!/usr/bin/env bash
# Installs the Debian 12 packages slamsweep needs to build, test and run.
# Idempotent and fast when everything is present: it asks dpkg first and only calls apt
# for what is missing. Used by both README commands, .ci/run and docker/.
# With arguments it installs those packages instead, by the same check: scripts/install-slam.sh
# passes each roster algorithm's build dependencies this way.
#   --build    only what compiling slamsweep needs (docker/Dockerfile's build stage, without tests)
#   --runtime  only what an installed slamsweep needs to run (the image's runtime stage: no compilers)
#   --main     what the main job (scripts/quickstart.sh) builds and runs: --build and the programs sweeps
#              run, without the test suite's tools (Chromium, Slurm, GoogleTest, scipy...)
set -euo pipefail

build_packages=(
  # toolchain
  g++ cmake ninja-build pkg-config
  # the linker: lld drops a batched object's unused code and the libraries only that code needed
  lld
  # libraries (docs/development.md says why each is there)
  libeigen3-dev libopencv-dev nlohmann-json3-dev libyaml-cpp-dev libspdlog-dev libfmt-dev
  libcli11-dev zlib1g-dev libdeflate-dev libsqlite3-dev libboost-dev libboost-filesystem-dev libssl-dev
  # ROS 2 bags: MCAP chunks and rosbag2 compression (libzstd), MCAP lz4 chunks (liblz4's frame API)
  libzstd-dev liblz4-dev
  # PNG maps without OpenCV's imgcodecs (libpng-dev); numbers of trajectory files (libfast-float-dev)
  libpng-dev libfast-float-dev
  # `slamsweep serve` and `submit`: the HTTP server and client (cpp-httplib)
  libcpp-httplib-dev
  # the sandbox's seccomp filter against nested user namespaces where it has no /proc (libseccomp)
  libseccomp-dev
  # map GIFs in the report (giflib); MRPT's rawlog reading/writing (libmrpt-obs-dev)
  libgif-dev libmrpt-obs-dev
  # ROS1 bags (evaluator/formats/rosbag): librosbag and message headers
  librosbag-dev libsensor-msgs-dev libnav-msgs-dev libtf2-msgs-dev libgeometry-msgs-dev
)

# Programs and data slamsweep runs or reads: the report's plots (gnuplot), MRPT's real SLAM programs
# (mrpt-apps) and their sample dataset and configs (mrpt-common), the sandbox every SLAM program runs in
# (bubblewrap: orchestrator/sandbox).
run_programs=(gnuplot-nox mrpt-apps mrpt-common bubblewrap)

# What the installed programs link (scripts/docker-check.sh runs ldd on each in the image: a library
# missing here fails it) and run_programs; the package names are Debian 12's.
runtime_packages=(
  libstdc++6 zlib1g libboost-filesystem1.74.0 libboost-iostreams1.74.0 libdeflate0 libfmt9 libssl3 libyaml-cpp0.7
  libspdlog1.10 libsqlite3-0 libzstd1 liblz4-1 libcpp-httplib0.11 libgif7 libpng16-16 libopencv-core406 libopencv-imgproc406
  libmrpt-obs2.5 librosbag-storage4d libroscpp-serialization0d librostime1d libcpp-common0d libseccomp2
  # the Cartographer driver (Ceres, linked statically, brings ATLAS's BLAS and LAPACK: libceres-dev
  # depends on libatlas-base-dev)
  libabsl20220623 libcholmod3 libcxsparse3 libgoogle-glog0v6 liblua5.3-0 libprotobuf32 libatlas3-base liblapack3
  # the slam_toolbox driver's libslam_toolbox_karto.so (Ceres linked statically, as above; its Karto needs these)
  libboost-serialization1.74.0 libtbb12
  "${run_programs[@]}"
)

packages=(
  "${build_packages[@]}"
  "${run_programs[@]}"
  # headless Chromium checks the report in tests; python3-* write the test bags (ROS 1 bags; ROS 2 bags
  # with rosbag2's zstd compression: python3-zstandard)
  chromium python3-rosbag python3-sensor-msgs python3-nav-msgs python3-tf2-msgs python3-zstandard
  # tests and benchmarks (ccache: scripts/build.sh's compiler cache, so the test command's build of a fresh
  # clone compiles only what changed; hyperfine: bench/cli, whole-process times); python3-scipy is the
  # independent reference for the Spearman rank correlation of the metric validity study and the
  # rank tests; python3-statsmodels for the Holm correction (tests/evaluator/statistics); python3-pil reads
  # the stage animations back (tests/evaluator/formats/map); python3-opencv runs bench/map_metrics_reference.py, the
  # plain Python + OpenCV paper map metrics that `eval map` is timed against (docs/performance.md)
  # clang-format checks the source layout (tests/architecture)
  libgtest-dev libgmock-dev libbenchmark-dev shellcheck clang-format ccache hyperfine python3-scipy python3-statsmodels python3-pil python3-opencv
  # the service tests: /metrics parsed by the Prometheus project's own parser; wrk drives bench/service/load_test.sh
  python3-prometheus-client wrk
  # the Slurm executor's test: a real one-node cluster on localhost (jobs/slurm/local-cluster.sh)
  slurm-wlm munge
)

case "${1:-}" in
  --build) packages=("${build_packages[@]}") ;;
  --runtime) packages=("${runtime_packages[@]}") ;;
  --main) packages=("${build_packages[@]}" "${run_programs[@]}") ;;
  "") ;;
  *) packages=("$@") ;;
esac

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$package")
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
