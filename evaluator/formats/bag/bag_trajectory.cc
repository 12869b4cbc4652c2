#include "evaluator/formats/bag/bag_trajectory.h"

#include <fmt/format.h>

#include <system_error>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/bag/bag_conversions.h"
#include "evaluator/formats/bag/transform_tree.h"

namespace slamsweep::evaluator::inline formats::inline bag {
namespace {

bool Exists(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::exists(path, error);
}

/// The frames of "PARENT.CHILD": the split at a '.' whose frames the tree joins.
std::pair<std::string, std::string> SplitFrames(const std::filesystem::path& bag, const TransformTree& tree,
                                                std::string_view frames, std::string_view selector) {
  std::vector<std::pair<std::string, std::string>> joined;
  for (std::size_t dot = frames.find('.'); dot != std::string_view::npos; dot = frames.find('.', dot + 1)) {
    std::string parent(frames.substr(0, dot));
    std::string child(frames.substr(dot + 1));
    if (!parent.empty() && !child.empty() && tree.Connected(parent, child) &&
        CanonicalFrame(parent) != CanonicalFrame(child)) {
      joined.emplace_back(std::move(parent), std::move(child));
    }
  }
  if (joined.size() == 1) return joined.front();
  if (joined.empty()) {
    throw InputError(fmt::format(
        "{}: '{}': expected /tf:PARENT.CHILD with two frames that /tf and /tf_static join; frames in the bag: {}",
        bag.string(), selector, tree.FrameList()));
  }
  std::string splits;
  for (const auto& [parent, child] : joined)
    splits += fmt::format("{}'{}' -> '{}'", splits.empty() ? "" : ", ", parent, child);
  throw InputError(fmt::format("{}: '{}' splits into frames in more than one way ({}); rename a frame", bag.string(),
                               selector, splits));
}

}  // namespace

std::optional<BagTrajectoryArgument> SplitBagTrajectoryArgument(std::string_view text) {
  if (Exists(std::filesystem::path(text))) return BagTrajectoryArgument{std::filesystem::path(text), ""};
  // From the last ':' back: the first prefix that exists is the longest.
  for (std::size_t colon = text.rfind(':'); colon != std::string_view::npos && colon > 0;
       colon = text.rfind(':', colon - 1)) {
    const std::filesystem::path prefix(text.substr(0, colon));
    if (Exists(prefix)) return BagTrajectoryArgument{prefix, std::string(text.substr(colon + 1))};
  }
  return std::nullopt;
}

Trajectory ReadBagTrajectory(const std::filesystem::path& bag, const BagSummary& summary, const BagMessageSource& read,
                             std::string_view selector, std::vector<std::string>& warnings) {
  if (selector.empty()) {
    throw InputError(fmt::format("{}: a bag holds many trajectories: name one as {}:TOPIC or {}:/tf:PARENT.CHILD; {}",
                                 bag.string(), bag.string(), bag.string(), DescribeTopics(summary)));
  }
  for (const std::string_view tf_topic : {std::string_view(kTfTopic), std::string_view(kTfStaticTopic)}) {
    const std::string prefix = std::string(tf_topic) + ":";
    if (!selector.starts_with(prefix)) continue;
    BagRequest request;
    request.read_tf = true;
    const BagMessages messages = read(request);
    const TransformTree tree = BuildTransformTree(messages, bag, warnings);
    const auto [parent, child] = SplitFrames(bag, tree, selector.substr(prefix.size()), selector);
    Trajectory track = tree.Track(parent, child);
    if (track.empty()) {
      throw InputError(fmt::format("{}: '{}': /tf holds no time-varying transform between '{}' and '{}'", bag.string(),
                                   selector, parent, child));
    }
    return track;
  }
  const std::string topic(selector);
  RequireTopic(bag, summary, topic, "trajectory", kTrajectoryKinds);
  BagRequest request;
  request.pose_topics.push_back(topic);
  const BagMessages messages = read(request);
  std::size_t duplicates = 0;
  Trajectory trajectory = ToTrajectory(messages.poses.at(topic), bag, topic, duplicates);
  if (trajectory.empty())
    throw InputError(fmt::format("{}: trajectory topic '{}' has no messages", bag.string(), topic));
  if (duplicates > 0) {
    warnings.push_back(
        fmt::format("{}: dropped {} message(s) on '{}' repeating a stamp", bag.string(), duplicates, topic));
  }
  return trajectory;
}

}  // namespace slamsweep::evaluator::inline formats::inline bag
