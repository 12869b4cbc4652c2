#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace slamsweep::report::inline plots {

/// How one algorithm is drawn everywhere in a report: the colour of its points, lines, boxes and
/// table swatch, and its marker.
struct AlgorithmStyle {
  /// Index into the style table: colour = slot % kPaletteColours, marker = slot % kPaletteMarkers.
  std::size_t slot = 0;
  std::uint32_t rgb = 0;         ///< 0xRRGGBB
  int point_type = 7;            ///< gnuplot pngcairo point type of the (filled) marker
  std::string_view colour_name;  ///< "blue", for captions and alt texts
  std::string_view marker_name;  ///< "circle"
  std::string_view glyph;        ///< the marker as a character ("●"), for HTML legends

  /// "#0072B2".
  std::string Hex() const;
  /// "palette-c0" .. "palette-c7": the style sheet class of the colour (PaletteStyleSheet).
  std::string CssClass() const;
};

/// Okabe and Ito's colour-blind-safe colours without their yellow (too faint on white), plus a dark grey:
/// eight colours. Together with seven markers (circle, square, triangle, diamond, inverted
/// triangle, pentagon, asterisk) they make 56 styles; colour and marker both change from one slot
/// to the next (8 and 7 are coprime), so even two algorithms sharing a colour differ in marker.
inline constexpr std::size_t kPaletteColours = 8;
inline constexpr std::size_t kPaletteMarkers = 7;
inline constexpr std::size_t kPaletteStyles = kPaletteColours * kPaletteMarkers;

/// The styles of the algorithms of one report.
///
/// A style depends on the algorithm's name, never on its position in a sweep, so a rerun with
/// another subset of algorithms draws each one as before:
/// - the paper's roster and slamsweep's built-in algorithms have fixed slots 0-7 (gmapping,
///   cartographer, hector, tinyslam, vinyslam, icp-slam, rbpf-slam, odometry: eight different
///   colours, the odometry baseline dark grey);
/// - any other name takes slot 8 + FNV-1a(name) mod 48. Two such names of one report may share a
///   colour (their markers then differ); only when two names hash to the same slot does the one
///   later in name order take the next free slot, so that no two algorithms of a report look alike.
class AlgorithmPalette {
 public:
  /// `names`: every algorithm name of the report, in any order (duplicates are ignored).
  explicit AlgorithmPalette(const std::vector<std::string>& names);

  /// The style of a name given to the constructor; any other name gets its preferred slot.
  AlgorithmStyle StyleOf(std::string_view name) const;

 private:
  std::map<std::string, std::size_t, std::less<>> slots_;
};

/// The style of slot `slot` (taken modulo kPaletteStyles).
AlgorithmStyle StyleOfSlot(std::size_t slot);

/// The slot a name prefers before collisions are resolved (its fixed slot, or its hash slot).
std::size_t PreferredSlot(std::string_view name);

/// CSS rules `.palette-cN { color: #RRGGBB; }` for the eight colours, for the report's style.css
/// (pages may not carry inline styles under Jenkins' Content-Security-Policy).
std::string PaletteStyleSheet();

}  // namespace slamsweep::report::inline plots
