#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"

namespace slamsweep::evaluator::inline formats::inline bag {

/// tf's frame names without the leading '/' that ROS1 tf (before tf2) allowed: "/odom" == "odom".
std::string CanonicalFrame(std::string_view frame);

/// A small tf: frames form a forest in which every frame has at most one parent, and each edge
/// holds the child's pose in the parent, either fixed (/tf_static) or as samples over time (/tf).
/// Value type; lookups are const.
class TransformTree {
 public:
  /// Adds the fixed pose of `child` in `parent`. Returns false (and ignores the edge) when `child`
  /// already has another parent or a time-varying pose, as tf2 would reject it.
  bool AddStatic(std::string_view parent, std::string_view child, const Pose& pose);
  /// Adds one sample of the pose of `child` in `parent`. Returns false as AddStatic does. Samples may
  /// come in any order; a later sample with the same stamp replaces the earlier one.
  bool AddSample(std::string_view parent, std::string_view child, double stamp_s, const Pose& pose);

  /// Every frame, sorted and joined by ", " ("(none)" for an empty tree): for messages.
  std::string FrameList() const;

  /// True when both frames are in one tree.
  bool Connected(std::string_view parent, std::string_view child) const;

  /// The pose of `child` in `parent` at stamp_s (time-varying edges interpolated as
  /// TrajectoryInterpolator does). Outside a time-varying edge's samples: nullopt, or that edge's
  /// nearest sample when `clamp` (for fixed mounts published on /tf). nullopt when not connected.
  std::optional<Pose> Lookup(std::string_view parent, std::string_view child, double stamp_s, bool clamp) const;

  /// The pose of `child` in `parent` at every stamp of a time-varying edge between them (sorted,
  /// each once) where all such edges can be interpolated. Empty when the frames are not connected
  /// or only fixed edges join them.
  Trajectory Track(std::string_view parent, std::string_view child) const;

 private:
  struct Edge {
    std::string parent;
    bool is_static = false;
    Pose fixed;
    /// Time-varying edges: pose by stamp.
    std::map<double, Pose> samples;
  };

  /// Frames from `frame` up to its root, `frame` first.
  std::vector<std::string> Ancestors(const std::string& frame) const;
  /// The frames whose edges lead from `child` and from `parent` up to their common ancestor
  /// (each frame stands for the edge to its parent); nullopt when they share none.
  struct Path {
    std::vector<std::string> up_from_child;
    std::vector<std::string> up_from_parent;
  };
  std::optional<Path> FindPath(const std::string& parent, const std::string& child) const;
  std::optional<Pose> EdgeAt(const Edge& edge, double stamp_s, bool clamp) const;
  /// The edge from `parent` to `child` of that kind, made when new; nullptr when the frames are the same or
  /// `child` already hangs from another parent or by another kind (AddStatic's and AddSample's false).
  Edge* EdgeFor(std::string_view parent, std::string_view child, bool is_static);
  std::optional<Pose> ChainAt(const std::vector<std::string>& frames, double stamp_s, bool clamp) const;

  /// Keyed by child frame.
  std::map<std::string, Edge, std::less<>> edges_;
};

}  // namespace slamsweep::evaluator::inline formats::inline bag
