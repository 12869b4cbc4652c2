#include "evaluator/formats/bag/transform_tree.h"

#include <iterator>
#include <set>

#include "evaluator/trajectory_metrics/interpolation.h"

namespace slamsweep::evaluator::inline formats::inline bag {

std::string CanonicalFrame(std::string_view frame) {
  while (!frame.empty() && frame.front() == '/') frame.remove_prefix(1);
  return std::string(frame);
}

TransformTree::Edge* TransformTree::EdgeFor(std::string_view parent, std::string_view child, bool is_static) {
  const std::string parent_frame = CanonicalFrame(parent);
  const std::string child_frame = CanonicalFrame(child);
  if (parent_frame == child_frame) return nullptr;
  const auto [it, inserted] = edges_.try_emplace(child_frame);
  Edge& edge = it->second;
  if (inserted) {
    edge.parent = parent_frame;
    edge.is_static = is_static;
  } else if (edge.parent != parent_frame || edge.is_static != is_static) {
    return nullptr;
  }
  return &edge;
}

bool TransformTree::AddStatic(std::string_view parent, std::string_view child, const Pose& pose) {
  Edge* edge = EdgeFor(parent, child, true);
  if (edge == nullptr) return false;
  edge->fixed = pose;
  return true;
}

bool TransformTree::AddSample(std::string_view parent, std::string_view child, double stamp_s, const Pose& pose) {
  Edge* edge = EdgeFor(parent, child, false);
  if (edge == nullptr) return false;
  edge->samples.insert_or_assign(stamp_s, pose);
  return true;
}

std::vector<std::string> TransformTree::Ancestors(const std::string& frame) const {
  std::vector<std::string> chain{frame};
  std::set<std::string> seen{frame};
  for (auto it = edges_.find(frame); it != edges_.end(); it = edges_.find(chain.back())) {
    // A cycle (a in b and b in a) ends the walk instead of looping forever.
    if (!seen.insert(it->second.parent).second) break;
    chain.push_back(it->second.parent);
  }
  return chain;
}

std::optional<TransformTree::Path> TransformTree::FindPath(const std::string& parent, const std::string& child) const {
  const std::vector<std::string> from_child = Ancestors(child);
  const std::vector<std::string> from_parent = Ancestors(parent);
  const std::set<std::string> child_side(from_child.begin(), from_child.end());
  for (std::size_t i = 0; i < from_parent.size(); ++i) {
    if (child_side.count(from_parent[i]) == 0) continue;
    Path path;
    path.up_from_parent.assign(from_parent.begin(), from_parent.begin() + static_cast<std::ptrdiff_t>(i));
    for (const std::string& frame : from_child) {
      if (frame == from_parent[i]) break;
      path.up_from_child.push_back(frame);
    }
    return path;
  }
  return std::nullopt;
}

std::optional<Pose> TransformTree::EdgeAt(const Edge& edge, double stamp_s, bool clamp) const {
  if (edge.is_static) return edge.fixed;
  if (edge.samples.empty()) return std::nullopt;
  const auto after = edge.samples.lower_bound(stamp_s);
  if (after != edge.samples.end() && after->first == stamp_s) return after->second;
  if (after == edge.samples.begin() || after == edge.samples.end()) {
    if (!clamp) return std::nullopt;
    return after == edge.samples.end() ? std::prev(after)->second : after->second;
  }
  const auto before = std::prev(after);
  const double fraction = (stamp_s - before->first) / (after->first - before->first);
  return InterpolatePose(before->second, after->second, fraction);
}

std::optional<Pose> TransformTree::ChainAt(const std::vector<std::string>& frames, double stamp_s, bool clamp) const {
  // frames[0] is the deepest; its pose in the top frame's parent is edge(top) * ... * edge(frames[0]).
  Pose pose;
  for (auto frame = frames.rbegin(); frame != frames.rend(); ++frame) {
    const std::optional<Pose> edge = EdgeAt(edges_.find(*frame)->second, stamp_s, clamp);
    if (!edge) return std::nullopt;
    pose = pose * *edge;
  }
  return pose;
}

std::string TransformTree::FrameList() const {
  std::set<std::string> frames;
  for (const auto& [child, edge] : edges_) {
    frames.insert(child);
    frames.insert(edge.parent);
  }
  std::string list;
  for (const std::string& frame : frames) list += (list.empty() ? "" : ", ") + frame;
  return list.empty() ? "(none)" : list;
}

bool TransformTree::Connected(std::string_view parent, std::string_view child) const {
  return FindPath(CanonicalFrame(parent), CanonicalFrame(child)).has_value();
}

std::optional<Pose> TransformTree::Lookup(std::string_view parent, std::string_view child, double stamp_s,
                                          bool clamp) const {
  const std::optional<Path> path = FindPath(CanonicalFrame(parent), CanonicalFrame(child));
  if (!path) return std::nullopt;
  const std::optional<Pose> child_in_root = ChainAt(path->up_from_child, stamp_s, clamp);
  const std::optional<Pose> parent_in_root = ChainAt(path->up_from_parent, stamp_s, clamp);
  if (!child_in_root || !parent_in_root) return std::nullopt;
  return parent_in_root->Inverse() * *child_in_root;
}

Trajectory TransformTree::Track(std::string_view parent, std::string_view child) const {
  Trajectory track;
  const std::optional<Path> path = FindPath(CanonicalFrame(parent), CanonicalFrame(child));
  if (!path) return track;
  std::set<double> stamps;
  for (const std::vector<std::string>* side : {&path->up_from_child, &path->up_from_parent}) {
    for (const std::string& frame : *side) {
      for (const auto& [stamp_s, pose] : edges_.find(frame)->second.samples) stamps.insert(stamp_s);
    }
  }
  for (const double stamp_s : stamps) {
    if (const std::optional<Pose> pose = Lookup(parent, child, stamp_s, /*clamp=*/false)) track.Add(stamp_s, *pose);
  }
  return track;
}

}  // namespace slamsweep::evaluator::inline formats::inline bag
