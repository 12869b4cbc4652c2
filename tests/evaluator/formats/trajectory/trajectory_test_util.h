#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/core/relation.h"
#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::testing_util {

/// Rotation angle between two orientations (radians), independent of quaternion sign.
inline double AngleBetweenRad(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return RotationAngleRad(a.conjugate() * b);
}

inline ::testing::AssertionResult SamePose(const Pose& expected, const Pose& actual, double tolerance) {
  const double position_error = (expected.position - actual.position).norm();
  const double angle_error = AngleBetweenRad(expected.orientation, actual.orientation);
  if (position_error <= tolerance && angle_error <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "position error " << position_error << " m, rotation error " << angle_error
                                       << " rad (tolerance " << tolerance << ")";
}

/// Same stamps bit for bit and the same poses to `tolerance`.
inline void ExpectSameTrajectory(const Trajectory& expected, const Trajectory& actual, double tolerance = 1e-12) {
  ASSERT_EQ(expected.size(), actual.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(expected.stamps_s()[i], actual.stamps_s()[i]) << "stamp " << i;
    EXPECT_TRUE(SamePose(expected.poses()[i], actual.poses()[i], tolerance)) << "pose " << i;
  }
}

/// A trajectory of `count` random poses: planar (x, y, yaw) or general SE(3), stamps increasing
/// at about 10 Hz with jitter, coordinates of tens of metres (like a building-sized run).
inline Trajectory RandomTrajectory(std::size_t count, bool planar, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0);
  std::uniform_real_distribution<double> angle(-3.14159, 3.14159);
  std::uniform_real_distribution<double> jitter(0.0, 0.01);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  Trajectory trajectory;
  double stamp_s = 1.0e9 + 0.123456789;
  for (std::size_t i = 0; i < count; ++i) {
    stamp_s += 0.1 + jitter(random);
    Pose pose;
    if (planar) {
      pose = Pose::Planar(coordinate(random), coordinate(random), angle(random));
    } else {
      pose.position = {coordinate(random), coordinate(random), coordinate(random)};
      pose.orientation =
          Eigen::Quaterniond(gaussian(random), gaussian(random), gaussian(random), gaussian(random)).normalized();
    }
    trajectory.Add(stamp_s, pose);
  }
  return trajectory;
}

/// Runs `action`, which must throw an InputError whose message contains every one of `parts`.
template <typename Action>
void ExpectInputError(Action&& action, std::initializer_list<std::string> parts) {
  try {
    action();
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    for (const std::string& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos) << "message '" << message << "' lacks '" << part << "'";
    }
  }
}

}  // namespace slamsweep::evaluator::testing_util
