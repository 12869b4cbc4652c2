// slamsweep-slam-tinyslam: tinySLAM as slam-constructor builds it from tiny_slam_base.properties.
#include "slam/slam_constructor/slam_constructor_run.h"

int main(int argc, char** argv) {
  return slamsweep::slam::DriverMain(
      argc, argv, "slamsweep-slam-tinyslam",
      [](slamsweep::slam::Parameters& parameters, const slamsweep::slam::DriverArgs& args,
         const slamsweep::evaluator::RobotLog&) {
        return slamsweep::slam::slam_constructor::ConfigureFromProperties(
            slamsweep::slam::slam_constructor::ConfigFile("slams/tiny_slam_base.properties", SLAM_CONSTRUCTOR_ROOT),
            parameters, args);
      });
}
