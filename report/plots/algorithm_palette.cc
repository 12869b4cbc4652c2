#include "report/plots/algorithm_palette.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <set>

namespace slamsweep::report::inline plots {
namespace {

struct Colour {
  std::uint32_t rgb;
  std::string_view name;
};

// Okabe & Ito (2008), "Color Universal Design": distinguishable with protanopia, deuteranopia and
// tritanopia. Their yellow (#F0E442) is left out: a thin yellow line is hard to see on white.
constexpr std::array<Colour, kPaletteColours> kColours = {{{0x0072B2, "blue"},
                                                           {0xD55E00, "vermillion"},
                                                           {0x009E73, "bluish green"},
                                                           {0xCC79A7, "reddish purple"},
                                                           {0xE69F00, "orange"},
                                                           {0x56B4E9, "sky blue"},
                                                           {0x000000, "black"},
                                                           {0x555555, "dark grey"}}};

struct Marker {
  int point_type;  // gnuplot pngcairo
  std::string_view name;
  std::string_view glyph;
};

constexpr std::array<Marker, kPaletteMarkers> kMarkers = {{{7, "circle", "●"},
                                                           {5, "square", "■"},
                                                           {9, "triangle", "▲"},
                                                           {13, "diamond", "◆"},
                                                           {11, "inverted triangle", "▼"},
                                                           {15, "pentagon", "⬟"},
                                                           {3, "asterisk", "✱"}}};

// The built-in algorithm names (configs/*.yaml, slamsweep algorithms) in slot order.
constexpr std::array<std::string_view, kPaletteColours> kFixedNames = {
    "gmapping", "cartographer", "hector", "tinyslam", "vinyslam", "icp-slam", "rbpf-slam", "odometry"};

std::uint64_t Fnv1a(std::string_view text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

}  // namespace

std::string AlgorithmStyle::Hex() const { return fmt::format("#{:06X}", rgb); }

std::string AlgorithmStyle::CssClass() const { return fmt::format("palette-c{}", slot % kPaletteColours); }

AlgorithmStyle StyleOfSlot(std::size_t slot) {
  slot %= kPaletteStyles;
  const Colour& colour = kColours[slot % kPaletteColours];
  const Marker& marker = kMarkers[slot % kPaletteMarkers];
  return AlgorithmStyle{slot, colour.rgb, marker.point_type, colour.name, marker.name, marker.glyph};
}

std::size_t PreferredSlot(std::string_view name) {
  const auto fixed = std::find(kFixedNames.begin(), kFixedNames.end(), name);
  if (fixed != kFixedNames.end()) return static_cast<std::size_t>(fixed - kFixedNames.begin());
  return kFixedNames.size() + Fnv1a(name) % (kPaletteStyles - kFixedNames.size());
}

AlgorithmPalette::AlgorithmPalette(const std::vector<std::string>& names) {
  const std::set<std::string> sorted(names.begin(), names.end());
  std::set<std::size_t> taken;
  // Fixed names first, so that a custom name can never push a built-in one off its slot.
  for (const std::string& name : sorted) {
    const std::size_t slot = PreferredSlot(name);
    if (slot < kFixedNames.size()) {
      slots_[name] = slot;
      taken.insert(slot);
    }
  }
  for (const std::string& name : sorted) {
    if (slots_.count(name) > 0) continue;
    std::size_t slot = PreferredSlot(name);
    // More names than styles: styles repeat rather than loop forever.
    for (std::size_t tries = 0; taken.count(slot) > 0 && tries < kPaletteStyles; ++tries) {
      slot = (slot + 1) % kPaletteStyles;
    }
    slots_[name] = slot;
    taken.insert(slot);
  }
}

AlgorithmStyle AlgorithmPalette::StyleOf(std::string_view name) const {
  const auto found = slots_.find(name);
  return StyleOfSlot(found != slots_.end() ? found->second : PreferredSlot(name));
}

std::string PaletteStyleSheet() {
  std::string css;
  for (std::size_t c = 0; c < kColours.size(); ++c) {
    css += fmt::format(".palette-c{} {{ color: #{:06X}; }}\n", c, kColours[c].rgb);
  }
  return css;
}

}  // namespace slamsweep::report::inline plots
