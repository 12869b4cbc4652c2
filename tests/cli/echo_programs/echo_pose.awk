#!/usr/bin/awk -f
# Test fixture, not a SLAM program: prints, as a TUM trajectory, one pose field of the records of
# a slamsweep CARMEN program input -- what a cheating program would do to score well if the input
# held the reference. Usage: awk -v field=FIELD -v out=OUT.tum -f echo_pose.awk INPUT.log
#   field = flaser_pose | flaser_odom | robotlaser_robot | robotlaser_laser | odom
function tum(stamp, x, y, theta) {
  printf "%.9f %.9f %.9f 0 0 0 %.9f %.9f\n", stamp, x, y, sin(theta / 2), cos(theta / 2) > out
}
$1 == "FLASER" && (field == "flaser_pose" || field == "flaser_odom") {
  n = $2
  base = (field == "flaser_pose") ? 3 + n : 6 + n
  tum($(9 + n), $(base), $(base + 1), $(base + 2))
}
$1 == "ROBOTLASER1" && (field == "robotlaser_robot" || field == "robotlaser_laser") {
  n = $9
  remissions = $(10 + n)
  laser = 11 + n + remissions
  base = (field == "robotlaser_laser") ? laser : laser + 3
  tum($(laser + 11), $(base), $(base + 1), $(base + 2))
}
$1 == "ODOM" && field == "odom" { tum($8, $2, $3, $4) }
