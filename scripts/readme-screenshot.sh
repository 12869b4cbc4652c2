#!/usr/bin/env bash
# Makes docs/images/overview.png again, the README's screenshot of a report's overview: jobs/browser-check.sh
# builds and runs the report's browser tests (headless Chromium under Jenkins' CSP, a fixture shaped like the
# paper's sweep) and this copies the overview's screenshot from what it wrote.
# Usage: scripts/readme-screenshot.sh   (exit code: jobs/browser-check.sh's when it fails)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
shots=$(mktemp -d)
trap 'rm -rf -- "$shots"' EXIT
"$root/jobs/browser-check.sh" "$shots"
mkdir -p "$root/docs/images"
cp -- "$shots/report_overview_screenshot.png" "$root/docs/images/overview.png"
echo "docs/images/overview.png: $(stat -c %s "$root/docs/images/overview.png") bytes"
