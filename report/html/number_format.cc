#include "report/html/number_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace slamsweep::report::inline html {

namespace {

// Decimals that give `value` 4 significant digits; 0 for whole numbers (counts).
int Decimals(double value) {
  if (value == std::floor(value) && std::fabs(value) < 1e15) return 0;
  const int integer_digits = static_cast<int>(std::floor(std::log10(std::fabs(value)))) + 1;
  return std::clamp(4 - integer_digits, 0, 12);
}

// Decimals that give `value` 2 significant digits; 0 for whole numbers.
int SpreadDecimals(double value) {
  if (value == std::floor(value) && std::fabs(value) < 1e15) return 0;
  const int integer_digits = static_cast<int>(std::floor(std::log10(std::fabs(value)))) + 1;
  return std::clamp(2 - integer_digits, 0, 12);
}

std::string Fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

}  // namespace

std::string FormatNumber(double value) {
  if (!std::isfinite(value)) return "n/a";
  return Fixed(value, Decimals(value));
}

std::string FormatMeanStd(const MeanStd& value) {
  if (value.n == 0) return "n/a";
  if (!std::isfinite(value.mean)) return "n/a";
  // Mean and std with the same decimals: the mean's 4 significant digits, or more when the std
  // needs them for 2 significant digits (a whole mean of 13 with std 2.13 reads "13.0 ± 2.1").
  int decimals = Decimals(value.mean);
  if (value.std && std::isfinite(*value.std) && *value.std > 0)
    decimals = std::max(decimals, SpreadDecimals(*value.std));
  std::string out = Fixed(value.mean, decimals);
  out += " ± ";
  out += value.std && std::isfinite(*value.std) ? Fixed(*value.std, decimals) : std::string("n/a");
  return out;
}

std::string FormatOptional(const std::optional<double>& value, std::string_view unit) {
  if (!value) return "n/a";
  std::string out = FormatNumber(*value);
  if (!unit.empty()) {
    out += ' ';
    out.append(unit);
  }
  return out;
}

}  // namespace slamsweep::report::inline html
