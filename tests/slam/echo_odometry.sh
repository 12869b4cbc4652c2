#!/bin/sh
# The roster test's negative control, not a SLAM program: hands back the odometry it was given (its TUM
# input) as its trajectory. A test that this program passes cannot tell SLAM from dead reckoning.
# Usage: echo_odometry.sh INPUT.tum OUTPUT_DIR
set -eu
cp "$1" "$2/trajectory.tum"
