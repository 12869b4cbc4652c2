// Stand-in for ROS 2's rclcpp_lifecycle::LifecycleNode, written for slamsweep (not ROS code): Karto's Mapper.h
// names it in ScanSolver::Configure and slam_toolbox's Ceres solver plugin reads its parameters from it. Like a
// node started with a parameter file, it holds the file's values as overrides: declare_parameter(name, default)
// takes the override when there is one, else the default; has_parameter is true once declared; get_parameter
// of a name never declared throws, as rclcpp does.
#pragma once

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "rclcpp/rclcpp.hpp"

namespace rclcpp_lifecycle {

class LifecycleNode {
 public:
  using SharedPtr = std::shared_ptr<LifecycleNode>;

  LifecycleNode(std::string name, std::map<std::string, rclcpp::ParameterValue> overrides)
      : logger_(std::move(name)), overrides_(std::move(overrides)) {}

  bool has_parameter(const std::string& name) const { return declared_.count(name) > 0; }

  const rclcpp::ParameterValue& declare_parameter(const std::string& name, const rclcpp::ParameterValue& fallback) {
    if (has_parameter(name)) throw std::runtime_error("parameter '" + name + "' has already been declared");
    const auto given = overrides_.find(name);
    return declared_.emplace(name, given != overrides_.end() ? given->second : fallback).first->second;
  }

  rclcpp::Parameter get_parameter(const std::string& name) const {
    const auto found = declared_.find(name);
    if (found == declared_.end()) throw std::runtime_error("parameter '" + name + "' is not declared");
    return rclcpp::Parameter(name, found->second);
  }

  rclcpp::Logger get_logger() const { return logger_; }

 private:
  rclcpp::Logger logger_;
  std::map<std::string, rclcpp::ParameterValue> overrides_;
  std::map<std::string, rclcpp::ParameterValue> declared_;
};

}  // namespace rclcpp_lifecycle
