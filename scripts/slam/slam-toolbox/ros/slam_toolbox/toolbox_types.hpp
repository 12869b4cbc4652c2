// Stand-in for slam_toolbox/toolbox_types.hpp, written for slamsweep (not slam_toolbox code): the upstream header
// pulls in tf2, tf2_ros and the toolbox's ROS messages and services; the Ceres solver plugin uses two of its
// names only, the iterators over the solver's graph of node poses, declared here in the same namespace.
#pragma once

#include <unordered_map>

#include <Eigen/Core>

#include "karto_sdk/Mapper.h"

namespace toolbox_types {

using GraphIterator = std::unordered_map<int, Eigen::Vector3d>::iterator;
using ConstGraphIterator = std::unordered_map<int, Eigen::Vector3d>::const_iterator;

}  // namespace toolbox_types
