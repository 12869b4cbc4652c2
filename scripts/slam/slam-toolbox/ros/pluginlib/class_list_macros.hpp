// Stand-in for ROS's pluginlib/class_list_macros.hpp, written for slamsweep: slam_toolbox's Ceres solver ends by
// exporting itself as a karto::ScanSolver plugin. slamsweep's driver constructs the solver itself (what the node's
// plugin loader would do), so the export only checks at compile time that the class is such a plugin.
#pragma once

#include <type_traits>

#define PLUGINLIB_EXPORT_CLASS(Derived, Base) \
  static_assert(std::is_base_of_v<Base, Derived>, #Derived " is not a " #Base " plugin");
