#pragma once

#include <span>
#include <vector>

namespace slamsweep::evaluator::inline statistics {

/// Holm's step-down adjustment of p-values for a family of tests: the i-th smallest p is multiplied by the
/// number of tests not yet rejected (m - i + 1), made monotone and capped at 1. Rejecting where the adjusted
/// value is at most alpha keeps the family-wise error rate at alpha. Returned in the input's order.
std::vector<double> HolmAdjusted(std::span<const double> p_values);

/// Bonferroni's adjustment: each p times the number of tests, capped at 1 (for intervals: a (1 - alpha/m)
/// interval per test keeps the family's coverage at 1 - alpha).
std::vector<double> BonferroniAdjusted(std::span<const double> p_values);

}  // namespace slamsweep::evaluator::inline statistics
