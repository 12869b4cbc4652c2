# Independent values for tests/evaluator/statistics/rank_tests_test.cc: reads cases as JSON on stdin,
# writes p-values as JSON on stdout. Mann-Whitney U by scipy.stats.mannwhitneyu, Wilcoxon signed-rank by
# scipy.stats.wilcoxon (zeros dropped, no continuity correction), Holm by statsmodels' multipletests.
import json
import sys

from scipy import stats
from statsmodels.stats.multitest import multipletests

cases = json.load(sys.stdin)
out = {"mann_whitney": [], "wilcoxon": [], "holm": []}
for case in cases["mann_whitney"]:
    result = stats.mannwhitneyu(case["x"], case["y"], alternative=case["alternative"], method=case["method"],
                                use_continuity=True)
    out["mann_whitney"].append(float(result.pvalue))
for case in cases["wilcoxon"]:
    result = stats.wilcoxon(case["x"], case["y"], zero_method="wilcox", correction=False,
                            alternative=case["alternative"], method=case["method"])
    out["wilcoxon"].append(float(result.pvalue))
for case in cases["holm"]:
    out["holm"].append([float(p) for p in multipletests(case["p"], method="holm")[1]])
json.dump(out, sys.stdout)
