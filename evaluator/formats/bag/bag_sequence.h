#pragma once

#include <filesystem>

#include "evaluator/formats/bag/bag_messages.h"
#include "evaluator/formats/bag/bag_options.h"
#include "evaluator/formats/bag/bag_topics.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline formats::inline bag {

/// A bag with 2D laser scans as a Sequence, whatever the bag's format (`summary` and `read` come
/// from its reader):
///  - scans: the scan topic's messages ordered by header.stamp (the record time when a stamp is 0),
///    as evo times messages; later messages with an already seen stamp are dropped. Fields map
///    directly; NaN and +-inf ranges (REP 117: no return / too close) become range_max_m.
///  - odometry: each scan gets the odometry pose interpolated at its stamp (linear position, slerp
///    orientation); scans outside the odometry's time span are dropped, with a warning counting them.
///    When the odometry has more poses than there are scans, they are the sequence's recorded
///    odometry readings too (Sequence::odometry_readings), with each scan's pose among them.
///  - sensor_pose_on_robot: /tf_static or /tf base_frame -> laser frame (a /tf mount is taken at the
///    scan's stamp, or its nearest sample); identity, with a warning, when /tf does not join them.
///  - reference: reference_topic (Odometry, PoseStamped, PoseWithCovarianceStamped) or
///    reference_frame (/tf reference_frame -> base_frame).
///  - a warning when header stamps and the bag's record times differ by more than a second (a
///    simulation clock, a robot without time sync): the stamps are used.
/// Poses are projected onto the plane (x, y, yaw): the sequences are 2D. Quaternions are normalised.
/// Throws InputError naming the bag (and topic or frames) when a topic is missing, ambiguous or of
/// another type, odometry or reference cannot be formed, no scan lies within the odometry's span, or
/// a message holds an unusable pose or scan.
Sequence ReadBagSequence(const std::filesystem::path& bag, const BagSummary& summary, const BagMessageSource& read,
                         const BagReadOptions& options);

}  // namespace slamsweep::evaluator::inline formats::inline bag
