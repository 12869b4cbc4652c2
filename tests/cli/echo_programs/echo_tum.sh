#!/bin/sh
# Test fixture, not a SLAM program: hands back its TUM input unchanged as its trajectory, and
# records what it could see while it ran: its working directory, the run folder's files and its
# environment. Usage: echo_tum.sh INPUT.tum OUTPUT_DIR
set -eu
cp "$1" "$2/trajectory.tum"
pwd > "$2/seen_cwd.txt"
ls -a .. > "$2/seen_run_folder.txt"
env > "$2/seen_environment.txt"
