#!/usr/bin/python3
"""The plot of bench/scale in docs/scale-and-cost.md: time (run of the 4 shards, merge, report) and disk against runs, from
one or more results.json files of scale_bench.py (every size in them; a size measured twice keeps the
last file's figures). Drawn by gnuplot (scripts/install-deps.sh installs it).

Usage: bench/scale/plot.py OUT.png RESULTS.json...
"""
import json
import os
import subprocess
import sys
import tempfile


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    out, inputs = sys.argv[1], sys.argv[2:]
    sizes = {}
    for path in inputs:
        with open(path) as handle:
            for result in json.load(handle)["sizes"]:
                sizes[result["runs"]] = result
    with tempfile.TemporaryDirectory() as work:
        data = os.path.join(work, "scale.dat")
        with open(data, "w") as handle:
            handle.write("# runs run_s merge_s report_s disk_mb disk_kb_per_run\n")
            for runs in sorted(sizes):
                r = sizes[runs]
                handle.write(f"{runs} {r['run']['wall_s']:.2f} {r['merge']['wall_s']:.2f} {r['report']['wall_s']:.2f} "
                             f"{r['disk']['allocated_bytes'] / 1e6:.2f} {r['disk']['disk_kb_per_run']:.1f}\n")
        script = f"""
set terminal pngcairo size 900,420 font ',10'
set output '{out}'
set multiplot layout 1,2
set key top left
set grid
set xlabel 'runs'
set xtics rotate by -30
set ylabel 'seconds (wall, 2 cores)'
set title 'time'
plot '{data}' using 1:2 with linespoints title 'run (4 shards)', '' using 1:3 with linespoints title 'merge', \\
     '' using 1:4 with linespoints title 'report'
set ylabel 'MB (allocated)'
set y2label 'KB per run'
set ytics nomirror
set y2tics
set yrange [0:*]
set y2range [0:*]
set title 'disk (sweep folder, report included)'
plot '{data}' using 1:5 with linespoints title 'total', '' using 1:6 axes x1y2 with linespoints title 'per run'
unset multiplot
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
