# Independent values for tests/evaluator/statistics: reads cases as JSON on stdin, writes results
# as JSON on stdout. Spearman's rho by scipy.stats.spearmanr; the pooled within-stratum rank
# correlation re-implemented from its documented definition with scipy.stats.rankdata and numpy;
# quantiles by numpy.quantile (linear interpolation).
import json
import sys

import numpy as np
from scipy import stats

cases = json.load(sys.stdin)
out = {"spearman": [], "pooled": [], "quantile": []}
for case in cases["spearman"]:
    rho = stats.spearmanr(case["x"], case["y"]).correlation
    out["spearman"].append(None if np.isnan(rho) else float(rho))
for case in cases["pooled"]:
    cx, cy = [], []
    strata = np.array(case["strata"])
    x, y = np.array(case["x"], float), np.array(case["y"], float)
    for s in sorted(set(case["strata"])):
        members = strata == s
        n = members.sum()
        if n < 2:
            continue
        cx.extend((stats.rankdata(x[members]) - (n + 1) / 2) / n)
        cy.extend((stats.rankdata(y[members]) - (n + 1) / 2) / n)
    cx, cy = np.array(cx), np.array(cy)
    denominator = np.sqrt(np.sum(cx * cx) * np.sum(cy * cy))
    out["pooled"].append(float(np.sum(cx * cy) / denominator) if len(cx) >= 2 and denominator > 0 else None)
for case in cases["quantile"]:
    out["quantile"].append(float(np.quantile(np.array(case["values"], float), case["q"])))
json.dump(out, sys.stdout)
