# Independent values for tests/evaluator/statistics/friedman_test.cc: reads cases as JSON on stdin, writes
# JSON on stdout. Mean ranks by scipy.stats.rankdata (average ties); Friedman's chi-square (tie-corrected) by
# scipy.stats.friedmanchisquare; Iman-Davenport's p by scipy.stats.f.sf; Nemenyi's critical difference from
# scipy.stats.studentized_range's quantile at infinite degrees of freedom.
import json
import sys

import numpy as np
from scipy import stats

cases = json.load(sys.stdin)
out = {"friedman": [], "critical_difference": []}
for case in cases["friedman"]:
    values = np.array(case["values"], float)
    n, k = values.shape
    ranks = np.array([stats.rankdata(row) for row in values])
    chi2, chi2_p = stats.friedmanchisquare(*values.T)
    result = {"mean_ranks": ranks.mean(axis=0).tolist(), "chi_square": float(chi2), "chi_square_p": float(chi2_p),
              "iman_davenport_f": None, "iman_davenport_p": 0.0}
    if n * (k - 1) - chi2 > 1e-9:  # else every data set ranks alike: F is infinite
        f = (n - 1) * chi2 / (n * (k - 1) - chi2)
        result["iman_davenport_f"] = float(f)
        result["iman_davenport_p"] = float(stats.f.sf(f, k - 1, (k - 1) * (n - 1)))
    out["friedman"].append(result)
for case in cases["critical_difference"]:
    k, n, alpha = case["k"], case["n"], case["alpha"]
    q = stats.studentized_range.ppf(1 - alpha, k, np.inf)
    out["critical_difference"].append({"q": float(q), "cdf": float(stats.studentized_range.cdf(case["at"], k, np.inf)),
                                       "cd": float(q / np.sqrt(2) * np.sqrt(k * (k + 1) / (6 * n)))})
json.dump(out, sys.stdout)
