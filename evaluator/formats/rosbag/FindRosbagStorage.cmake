# Locates Debian's ROS1 bag library (librosbag-dev, which brings librosbag-storage-dev) and the
# ROS1 message headers by hand. The packages' own catkin configs are not used on purpose: through
# pluginlib they pull in ament_cmake, which runs a Python helper at configure time and fails the
# whole configure step for everybody when the first python3 on PATH lacks ament_package.
# Defines SLAMSWEEP_ROSBAG_FOUND and the imported target slamsweep::ros1_bag.
set(SLAMSWEEP_ROSBAG_FOUND FALSE)

# rosbag/bag.h includes ROS 2's pluginlib, which lives in per-package include folders on Debian.
set(_slamsweep_ros_headers
  ROSBAG rosbag/bag.h ""
  PLUGINLIB pluginlib/class_loader.hpp pluginlib
  CLASS_LOADER class_loader/class_loader.hpp class_loader
  RCPPUTILS rcpputils/shared_library.hpp rcpputils
  RCUTILS rcutils/shared_library.h rcutils
  AMENT_INDEX ament_index_cpp/get_package_prefix.hpp ament_index_cpp
  SENSOR_MSGS sensor_msgs/LaserScan.h ""
  NAV_MSGS nav_msgs/Odometry.h ""
  TF2_MSGS tf2_msgs/TFMessage.h ""
  GEOMETRY_MSGS geometry_msgs/TransformStamped.h "")
set(_slamsweep_ros_include_dirs)
set(_slamsweep_ros_missing)
while(_slamsweep_ros_headers)
  list(POP_FRONT _slamsweep_ros_headers _key _header _suffix)
  find_path(SLAMSWEEP_${_key}_INCLUDE_DIR ${_header} PATH_SUFFIXES ${_suffix})
  if(SLAMSWEEP_${_key}_INCLUDE_DIR)
    list(APPEND _slamsweep_ros_include_dirs ${SLAMSWEEP_${_key}_INCLUDE_DIR})
  else()
    list(APPEND _slamsweep_ros_missing ${_header})
  endif()
endwhile()
list(REMOVE_DUPLICATES _slamsweep_ros_include_dirs)

# librosbag itself is only checked for (the reader needs rosbag::Bag and rosbag::View, which
# live in librosbag_storage); it marks a complete librosbag-dev installation.
set(_slamsweep_ros_libraries)
foreach(_lib rosbag rosbag_storage roscpp_serialization rostime cpp_common console_bridge)
  find_library(SLAMSWEEP_ROSLIB_${_lib} ${_lib})
  if(NOT SLAMSWEEP_ROSLIB_${_lib})
    list(APPEND _slamsweep_ros_missing lib${_lib})
  elseif(NOT _lib STREQUAL "rosbag")
    list(APPEND _slamsweep_ros_libraries ${SLAMSWEEP_ROSLIB_${_lib}})
  endif()
endforeach()

if(_slamsweep_ros_missing)
  set(SLAMSWEEP_ROSBAG_MISSING "${_slamsweep_ros_missing}")
else()
  set(SLAMSWEEP_ROSBAG_FOUND TRUE)
  if(NOT TARGET slamsweep::ros1_bag)
    add_library(slamsweep::ros1_bag INTERFACE IMPORTED GLOBAL)
    set_target_properties(slamsweep::ros1_bag PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${_slamsweep_ros_include_dirs}"
      INTERFACE_LINK_LIBRARIES "${_slamsweep_ros_libraries}")
  endif()
endif()
