// Stand-in for ROS 2's rclcpp, written for slamsweep (not ROS code): the part slam_toolbox's Ceres solver
// plugin (solvers/ceres_solver.*) uses, so that the plugin compiles unchanged without ROS. A parameter value
// of the four types the solver reads, the Parameter get_parameter returns, a named Logger and the RCLCPP_*
// logging macros (INFO and above to stderr, as a node's console shows them; DEBUG dropped, rclcpp's default
// level).
#pragma once

#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace rclcpp {

/// A parameter's value: bool, integer, double or string (the types slam_toolbox's parameters have).
class ParameterValue {
 public:
  ParameterValue() = default;
  explicit ParameterValue(bool value) : value_(value) {}
  explicit ParameterValue(int value) : value_(static_cast<std::int64_t>(value)) {}
  explicit ParameterValue(std::int64_t value) : value_(value) {}
  explicit ParameterValue(double value) : value_(value) {}
  explicit ParameterValue(std::string value) : value_(std::move(value)) {}
  explicit ParameterValue(const char* value) : value_(std::string(value)) {}

  /// The value as a string, bool, integer or double; a value of another type throws, as rclcpp does.
  const std::string& as_string() const { return Get<std::string>("string"); }
  bool as_bool() const { return Get<bool>("bool"); }
  std::int64_t as_int() const { return Get<std::int64_t>("integer"); }
  double as_double() const { return Get<double>("double"); }

 private:
  template <typename T>
  const T& Get(const char* type) const {
    if (const T* value = std::get_if<T>(&value_)) return *value;
    throw std::runtime_error(std::string("parameter value is not a ") + type);
  }

  std::variant<std::monostate, bool, std::int64_t, double, std::string> value_;
};

/// A named parameter, what get_parameter returns.
class Parameter {
 public:
  Parameter(std::string name, ParameterValue value) : name_(std::move(name)), value_(std::move(value)) {}
  const std::string& get_name() const { return name_; }
  const ParameterValue& get_parameter_value() const { return value_; }
  const std::string& as_string() const { return value_.as_string(); }
  bool as_bool() const { return value_.as_bool(); }
  std::int64_t as_int() const { return value_.as_int(); }
  double as_double() const { return value_.as_double(); }

 private:
  std::string name_;
  ParameterValue value_;
};

/// A logger is its name; messages go to stderr as "[LEVEL] [name]: message".
class Logger {
 public:
  explicit Logger(std::string name = "") : name_(std::move(name)) {}
  const char* get_name() const { return name_.c_str(); }

 private:
  std::string name_;
};

inline Logger get_logger(const std::string& name) { return Logger(name); }

namespace stand_in {

__attribute__((format(printf, 3, 4))) inline void Log(const char* level, const Logger& logger, const char* format,
                                                      ...) {
  std::fprintf(stderr, "[%s] [%s]: ", level, logger.get_name());
  va_list arguments;
  va_start(arguments, format);
  std::vfprintf(stderr, format, arguments);
  va_end(arguments);
  std::fputc('\n', stderr);
}

}  // namespace stand_in
}  // namespace rclcpp

// rclcpp's default level is INFO: DEBUG messages are not shown.
#define RCLCPP_DEBUG(logger, ...) \
  do {                            \
    (void)(logger);               \
  } while (false)
#define RCLCPP_INFO(logger, ...) ::rclcpp::stand_in::Log("INFO", (logger), __VA_ARGS__)
#define RCLCPP_WARN(logger, ...) ::rclcpp::stand_in::Log("WARN", (logger), __VA_ARGS__)
#define RCLCPP_ERROR(logger, ...) ::rclcpp::stand_in::Log("ERROR", (logger), __VA_ARGS__)
#define RCLCPP_FATAL(logger, ...) ::rclcpp::stand_in::Log("FATAL", (logger), __VA_ARGS__)
