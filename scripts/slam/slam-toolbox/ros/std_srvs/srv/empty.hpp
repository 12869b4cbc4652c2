// Stand-in for ROS 2's std_srvs/srv/empty.hpp, written for slamsweep: slam_toolbox's Ceres solver header
// includes it but uses nothing of it.
#pragma once
