#include "report/plots/algorithm_palette.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace slamsweep::report {
namespace {

const std::vector<std::string> kRoster = {"gmapping", "cartographer", "hector",    "tinyslam",
                                          "vinyslam", "icp-slam",     "rbpf-slam", "odometry"};

TEST(AlgorithmPaletteTest, TheBuiltInAlgorithmsHaveEightDifferentColours) {
  const AlgorithmPalette palette(kRoster);
  std::set<std::uint32_t> colours;
  for (const std::string& name : kRoster) colours.insert(palette.StyleOf(name).rgb);
  EXPECT_EQ(colours.size(), 8u);
  EXPECT_EQ(palette.StyleOf("gmapping").Hex(), "#0072B2");
  EXPECT_EQ(palette.StyleOf("odometry").colour_name, "dark grey");
}

TEST(AlgorithmPaletteTest, AStyleDoesNotDependOnTheOtherAlgorithmsOfTheSweep) {
  // Every subset of these names (a rerun with --only-algorithms) draws each name as the full set does.
  const std::vector<std::string> names = {"gmapping", "hector", "my-slam", "icp-slam", "odometry", "other-slam"};
  ASSERT_NE(PreferredSlot("my-slam"), PreferredSlot("other-slam"));
  const AlgorithmPalette full(names);
  for (unsigned mask = 1; mask < (1u << names.size()); ++mask) {
    std::vector<std::string> subset;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (mask & (1u << i)) subset.push_back(names[i]);
    }
    // The order of the names does not matter either.
    std::vector<std::string> reversed(subset.rbegin(), subset.rend());
    const AlgorithmPalette part(reversed);
    for (const std::string& name : subset) {
      EXPECT_EQ(part.StyleOf(name).slot, full.StyleOf(name).slot) << name << " in subset " << mask;
    }
  }
}

TEST(AlgorithmPaletteTest, TwoNamesWithTheSameSlotAreStillToldApart) {
  // Find two custom names whose hash slots collide (brute force over a few hundred names).
  std::string first;
  std::string second;
  for (int i = 0; i < 1000 && second.empty(); ++i) {
    for (int j = 0; j < i; ++j) {
      const std::string a = "slam-" + std::to_string(j);
      const std::string b = "slam-" + std::to_string(i);
      if (PreferredSlot(a) == PreferredSlot(b)) {
        first = std::min(a, b);
        second = std::max(a, b);
        break;
      }
    }
  }
  ASSERT_FALSE(second.empty());
  const AlgorithmPalette palette({second, first});
  EXPECT_EQ(palette.StyleOf(first).slot, PreferredSlot(first));  // the first in name order keeps its slot
  EXPECT_NE(palette.StyleOf(second).slot, palette.StyleOf(first).slot);
}

TEST(AlgorithmPaletteTest, FiftySixAlgorithmsGetFiftySixDifferentStyles) {
  std::vector<std::string> names = kRoster;
  for (int i = 0; names.size() < kPaletteStyles; ++i) names.push_back("variant-" + std::to_string(i));
  const AlgorithmPalette palette(names);
  std::set<std::pair<std::uint32_t, int>> styles;
  for (const std::string& name : names) styles.insert({palette.StyleOf(name).rgb, palette.StyleOf(name).point_type});
  EXPECT_EQ(styles.size(), kPaletteStyles);
}

TEST(AlgorithmPaletteTest, NeighbouringSlotsDifferInColourAndMarker) {
  for (std::size_t slot = 0; slot + 1 < kPaletteStyles; ++slot) {
    EXPECT_NE(StyleOfSlot(slot).rgb, StyleOfSlot(slot + 1).rgb);
    EXPECT_NE(StyleOfSlot(slot).point_type, StyleOfSlot(slot + 1).point_type);
  }
}

// Colour-vision deficiency check, computed independently of the palette's own claims: every pair of
// the eight colours seen through Machado, Oliveira & Fernandes (2009)'s simulation matrices at full
// severity must stay at least 15 CIE76 Delta E apart (the published Okabe-Ito set reaches 16).
using Matrix = std::array<std::array<double, 3>, 3>;

double Linear(double channel) {
  const double c = channel / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

std::array<double, 3> Lab(const std::array<double, 3>& rgb_linear) {
  const auto [r, g, b] = rgb_linear;
  const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; };
  return {116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z))};
}

std::array<double, 3> Seen(std::uint32_t rgb, const Matrix& m) {
  const std::array<double, 3> v = {Linear((rgb >> 16) & 0xFF), Linear((rgb >> 8) & 0xFF), Linear(rgb & 0xFF)};
  std::array<double, 3> out{};
  for (int i = 0; i < 3; ++i) out[i] = std::clamp(m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2], 0.0, 1.0);
  return out;
}

TEST(AlgorithmPaletteTest, ColoursStayApartForColourBlindReaders) {
  const std::pair<const char*, Matrix> visions[] = {
      {"normal", {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}},
      {"protanopia",
       {{{0.152286, 1.052583, -0.204868}, {0.114503, 0.786281, 0.099216}, {-0.003882, -0.048116, 1.051998}}}},
      {"deuteranopia",
       {{{0.367322, 0.860646, -0.227968}, {0.280085, 0.672501, 0.047413}, {-0.011820, 0.042940, 0.968881}}}},
      {"tritanopia",
       {{{1.255528, -0.076749, -0.178779}, {-0.078411, 0.930809, 0.147602}, {0.004733, 0.691367, 0.303900}}}},
  };
  for (const auto& [vision, matrix] : visions) {
    for (std::size_t a = 0; a < kPaletteColours; ++a) {
      for (std::size_t b = a + 1; b < kPaletteColours; ++b) {
        const auto la = Lab(Seen(StyleOfSlot(a).rgb, matrix));
        const auto lb = Lab(Seen(StyleOfSlot(b).rgb, matrix));
        const double delta_e = std::hypot(la[0] - lb[0], la[1] - lb[1], la[2] - lb[2]);
        EXPECT_GE(delta_e, 15.0) << vision << ": " << StyleOfSlot(a).colour_name << " vs "
                                 << StyleOfSlot(b).colour_name;
      }
    }
  }
}

TEST(AlgorithmPaletteTest, StyleSheetHasOneClassPerColour) {
  const std::string css = PaletteStyleSheet();
  for (std::size_t c = 0; c < kPaletteColours; ++c) {
    const AlgorithmStyle style = StyleOfSlot(c);
    const std::string rule = fmt::format(".{} {{ color: {}; }}", style.CssClass(), style.Hex());
    EXPECT_NE(css.find(rule), std::string::npos) << css;
  }
}

}  // namespace
}  // namespace slamsweep::report
