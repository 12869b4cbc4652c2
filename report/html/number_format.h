#pragma once

#include <optional>
#include <string>

#include "report/model/mean_std.h"

namespace slamsweep::report::inline html {

/// A number for a table: integers as integers, others with 4 significant digits and no
/// exponent (0.1234, 12.35, 1235); NaN/inf as "n/a".
std::string FormatNumber(double value);

/// "mean ± std" (sample std; both with the same decimals: the mean's 4 significant digits, more
/// when the std needs them for 2 significant digits); "mean ± n/a" for one value; "n/a" for none.
std::string FormatMeanStd(const MeanStd& value);

/// An optional number with a unit ("3.2 s"), or "n/a".
std::string FormatOptional(const std::optional<double>& value, std::string_view unit);

}  // namespace slamsweep::report::inline html
