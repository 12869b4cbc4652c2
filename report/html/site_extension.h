#pragma once

#include <filesystem>

#include "report/html/html.h"

namespace slamsweep::report::inline html {

struct ReportSummary;

/// A part of the site made outside report/html (the nightly history of report/history), so that report/html
/// does not depend on it. Written after the sweep's own pages and before the index.
class SiteExtension {
 public:
  virtual ~SiteExtension() = default;
  /// Writes its pages and images under `out_dir` (adding them to `summary`) and returns its section of the
  /// index page. Throws evaluator::InputError for unusable input (e.g. a history file that is not one).
  virtual Html Write(const std::filesystem::path& out_dir, ReportSummary& summary) = 0;
};

}  // namespace slamsweep::report::inline html
