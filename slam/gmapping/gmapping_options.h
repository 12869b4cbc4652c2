#pragma once

#include "evaluator/core/laser_scan.h"
#include "slam/common/parameters.h"

namespace slamsweep::slam::gmapping {

/// GMapping's parameters under the names ROS slam_gmapping gives them (the names users know), with
/// slam_gmapping's defaults. maxRange defaults to the scans' max range minus 1 cm, maxUrange to
/// maxRange, as slam_gmapping does.
struct GmappingOptions {
  double maxRange = 0;
  double maxUrange = 0;
  double sigma = 0.05;
  int kernelSize = 1;
  double lstep = 0.05;
  double astep = 0.05;
  int iterations = 5;
  double lsigma = 0.075;
  double ogain = 3.0;
  int lskip = 0;
  double minimumScore = 0.0;
  double srr = 0.1;
  double srt = 0.2;
  double str = 0.1;
  double stt = 0.2;
  double linearUpdate = 1.0;
  double angularUpdate = 0.5;
  double temporalUpdate = -1.0;
  double resampleThreshold = 0.5;
  int particles = 30;
  double xmin = -100;
  double ymin = -100;
  double xmax = 100;
  double ymax = 100;
  double delta = 0.05;
  double llsamplerange = 0.01;
  double llsamplestep = 0.01;
  double lasamplerange = 0.005;
  double lasamplestep = 0.005;
};

/// Reads every option (InputError for a value of the wrong type or out of range).
GmappingOptions ReadGmappingOptions(Parameters& parameters, const evaluator::LaserScan& first_scan);

}  // namespace slamsweep::slam::gmapping
