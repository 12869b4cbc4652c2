#include "evaluator/formats/bag/bag_topics.h"

#include <fmt/format.h>

#include <algorithm>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline bag {
namespace {

/// The kinds' type names, spelled as the bag spells its types (ROS 2: pkg/msg/Type, ROS 1: pkg/Type).
std::string KindNames(std::initializer_list<BagMessageKind> kinds, bool ros2) {
  std::string names;
  std::size_t index = 0;
  for (const BagMessageKind kind : kinds) {
    if (index > 0) names += index + 1 == kinds.size() ? " or " : ", ";
    std::string name = Ros2TypeName(kind);
    if (!ros2) name.erase(name.find("/msg/"), 4);
    names += name;
    ++index;
  }
  return names;
}

}  // namespace

std::string DescribeTopics(const BagSummary& summary) {
  std::string described;
  for (const BagTopic& topic : summary.topics) {
    described += fmt::format("{}{} ({})", described.empty() ? "" : ", ", topic.topic, topic.datatype);
  }
  return described.empty() ? "the bag has no topics" : "topics in the bag: " + described;
}

std::vector<std::string> TopicsOfKind(const BagSummary& summary, BagMessageKind kind) {
  std::vector<std::string> topics;
  for (const BagTopic& topic : summary.topics) {
    if (KindOfDatatype(topic.datatype) == kind) topics.push_back(topic.topic);
  }
  std::sort(topics.begin(), topics.end());
  return topics;
}

const BagTopic& RequireTopic(const std::filesystem::path& bag, const BagSummary& summary, std::string_view topic,
                             std::string_view role, std::initializer_list<BagMessageKind> kinds) {
  const auto found = std::find_if(summary.topics.begin(), summary.topics.end(),
                                  [&](const BagTopic& candidate) { return candidate.topic == topic; });
  if (found == summary.topics.end()) {
    throw InputError(fmt::format("{}: no {} topic '{}'; {}", bag.string(), role, topic, DescribeTopics(summary)));
  }
  if (std::find(kinds.begin(), kinds.end(), KindOfDatatype(found->datatype)) == kinds.end()) {
    const bool ros2 = found->datatype.find("/msg/") != std::string::npos;
    throw InputError(fmt::format("{}: {} topic '{}' holds {}, expected {}", bag.string(), role, topic, found->datatype,
                                 KindNames(kinds, ros2)));
  }
  return *found;
}

}  // namespace slamsweep::evaluator::inline formats::inline bag
