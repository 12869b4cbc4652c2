#include "evaluator/formats/bag/transform_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace slamsweep::evaluator {
namespace {

void ExpectPlanar(const std::optional<Pose>& pose, double x_m, double y_m, double yaw_rad) {
  ASSERT_TRUE(pose.has_value());
  EXPECT_NEAR(pose->position.x(), x_m, 1e-12);
  EXPECT_NEAR(pose->position.y(), y_m, 1e-12);
  EXPECT_NEAR(NormalizeAngleRad(pose->Yaw() - yaw_rad), 0.0, 1e-12);
}

TEST(CanonicalFrameTest, DropsLeadingSlashes) {
  EXPECT_EQ(CanonicalFrame("/odom"), "odom");
  EXPECT_EQ(CanonicalFrame("base_link"), "base_link");
  EXPECT_EQ(CanonicalFrame("/"), "");
}

TEST(TransformTreeTest, ComposesStaticChainDownTheTree) {
  TransformTree tree;
  ASSERT_TRUE(tree.AddStatic("base_link", "mount", Pose::Planar(1.0, 0.0, std::numbers::pi / 2)));
  ASSERT_TRUE(tree.AddStatic("mount", "laser", Pose::Planar(2.0, 0.0, 0.0)));
  // laser in base_link: mount's +x is base_link's +y, so 2 m along it lands at (1, 2).
  ExpectPlanar(tree.Lookup("base_link", "laser", 0.0, false), 1.0, 2.0, std::numbers::pi / 2);
  // And the inverse direction.
  ExpectPlanar(tree.Lookup("laser", "base_link", 0.0, false), -2.0, 1.0, -std::numbers::pi / 2);
  ExpectPlanar(tree.Lookup("/laser", "/laser", 0.0, false), 0.0, 0.0, 0.0);
}

TEST(TransformTreeTest, LooksUpBetweenSiblingsThroughCommonParent) {
  TransformTree tree;
  tree.AddStatic("base_link", "front", Pose::Planar(1.0, 0.0, 0.0));
  tree.AddStatic("base_link", "rear", Pose::Planar(-1.0, 0.0, std::numbers::pi));
  // rear looks backwards from (-1, 0): front is 2 m behind it.
  ExpectPlanar(tree.Lookup("rear", "front", 0.0, false), -2.0, 0.0, std::numbers::pi);
}

TEST(TransformTreeTest, InterpolatesSamplesAndClampsOnlyWhenAsked) {
  TransformTree tree;
  tree.AddSample("odom", "base_link", 2.0, Pose::Planar(2.0, 0.0, 1.0));
  tree.AddSample("odom", "base_link", 0.0, Pose::Planar(0.0, 0.0, 0.0));
  ExpectPlanar(tree.Lookup("odom", "base_link", 0.5, false), 0.5, 0.0, 0.25);
  ExpectPlanar(tree.Lookup("odom", "base_link", 2.0, false), 2.0, 0.0, 1.0);
  EXPECT_FALSE(tree.Lookup("odom", "base_link", 2.5, false).has_value());
  EXPECT_FALSE(tree.Lookup("odom", "base_link", -0.1, false).has_value());
  ExpectPlanar(tree.Lookup("odom", "base_link", 2.5, true), 2.0, 0.0, 1.0);
  ExpectPlanar(tree.Lookup("odom", "base_link", -1.0, true), 0.0, 0.0, 0.0);
}

TEST(TransformTreeTest, TrackSamplesEveryStampWhereAllEdgesAreKnown) {
  TransformTree tree;
  for (double t : {0.0, 1.0, 2.0, 3.0}) tree.AddSample("odom", "base_link", t, Pose::Planar(t, 0.0, 0.0));
  tree.AddSample("map", "odom", 1.0, Pose::Planar(0.0, 10.0, 0.0));
  tree.AddSample("map", "odom", 3.0, Pose::Planar(0.0, 20.0, 0.0));
  const Trajectory track = tree.Track("map", "base_link");
  // 0.0 lies before map -> odom starts; 2.0 comes from odom -> base_link, map -> odom interpolated.
  ASSERT_EQ(track.size(), 3u);
  EXPECT_EQ(track.stamps_s(), (std::vector<double>{1.0, 2.0, 3.0}));
  ExpectPlanar(track.poses()[1], 2.0, 15.0, 0.0);
  EXPECT_TRUE(tree.Track("map", "elsewhere").empty());
}

TEST(TransformTreeTest, RejectsSecondParentSelfEdgeAndMixedKinds) {
  TransformTree tree;
  EXPECT_TRUE(tree.AddStatic("base_link", "laser", Pose()));
  EXPECT_TRUE(tree.AddStatic("/base_link", "laser", Pose::Planar(1.0, 0.0, 0.0)));  // same edge, updated
  EXPECT_FALSE(tree.AddStatic("odom", "laser", Pose()));
  EXPECT_FALSE(tree.AddSample("base_link", "laser", 1.0, Pose()));
  EXPECT_FALSE(tree.AddSample("odom", "/odom", 1.0, Pose()));
  ExpectPlanar(tree.Lookup("base_link", "laser", 0.0, false), 1.0, 0.0, 0.0);
}

TEST(TransformTreeTest, UnconnectedFramesAndCyclesGiveNothing) {
  TransformTree tree;
  tree.AddStatic("a", "b", Pose());
  tree.AddStatic("b", "a", Pose());  // a cycle: must not hang
  tree.AddStatic("c", "d", Pose());
  EXPECT_FALSE(tree.Connected("a", "d"));
  EXPECT_FALSE(tree.Lookup("a", "d", 0.0, true).has_value());
  EXPECT_TRUE(tree.Connected("c", "d"));
}

}  // namespace
}  // namespace slamsweep::evaluator
