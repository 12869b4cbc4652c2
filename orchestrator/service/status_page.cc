#include "orchestrator/service/status_page.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

namespace slamsweep::orchestrator::service {
namespace {

std::string Head(std::string_view title, bool refresh) {
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n{}<title>{}</title>\n"
      "<link rel=\"stylesheet\" href=\"/static/service.css\">\n</head>\n<body>\n",
      refresh ? fmt::format("<meta http-equiv=\"refresh\" content=\"{}\">\n", kPageRefreshSeconds) : "",
      HtmlEscape(title));
}

std::string Progress(const RunCounts& counts) {
  return fmt::format("<progress value=\"{}\" max=\"{}\"></progress> {}/{}", counts.finished(),
                     std::max<std::size_t>(counts.total, 1), counts.finished(), counts.total);
}

std::string Links(const SweepView& view) {
  const std::string id = std::to_string(view.sweep.id);
  std::vector<std::string> links;
  if (view.report == ReportState::kReady) {
    links.push_back("<a href=\"/sweeps/" + id + "/report/index.html\">report</a>");
    if (std::filesystem::exists(view.sweep.result_dir / "report" / "history")) {
      links.push_back("<a href=\"/sweeps/" + id + "/report/history/index.html\">history</a>");
    }
  } else if (view.report == ReportState::kWriting) {
    links.push_back("report being written");
  }
  if (IsFinished(view.sweep.state)) {
    links.push_back("<a href=\"/api/sweeps/" + id + "/junit.xml\">junit.xml</a>");
    links.push_back("<a href=\"/api/sweeps/" + id + "/summary.json\">summary.json</a>");
    links.push_back("<a href=\"/api/sweeps/" + id + "/summary.csv\">summary.csv</a>");
  }
  std::string joined;
  for (const std::string& link : links) joined += (joined.empty() ? "" : " | ") + link;
  return joined;
}

std::string StateCell(std::string_view state) {
  return fmt::format("<td class=\"state state-{}\">{}</td>", HtmlEscape(state), HtmlEscape(state));
}

}  // namespace

std::string HtmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string RenderIndexPage(const std::vector<SweepView>& sweeps, const QueueGauges& gauges) {
  std::string html = Head("slamsweep service", true);
  html += "<header><h1>slamsweep service</h1>\n";
  html += fmt::format("<p class=\"pool\">{} of {} worker slots busy, {} runs queued{}.</p>\n", gauges.runs_running,
                      gauges.slots, gauges.runs_queued,
                      gauges.draining ? "; <strong>draining</strong>: no new runs start" : "");
  html += "</header>\n<main>\n";
  if (sweeps.empty()) {
    html += "<p>No sweep submitted yet: <code>slamsweep submit CONFIG --server URL</code>.</p>\n";
  } else {
    html +=
        "<table>\n<thead><tr><th>sweep</th><th>name</th><th>submitted by</th><th>priority</th><th>state</th>"
        "<th>progress</th><th>failed</th><th>reused</th><th>ETA</th><th>results</th></tr></thead>\n<tbody>\n";
    std::vector<const SweepView*> ordered;
    for (const SweepView& view : sweeps) ordered.push_back(&view);
    std::sort(ordered.begin(), ordered.end(),
              [](const SweepView* a, const SweepView* b) { return a->sweep.id > b->sweep.id; });
    for (const SweepView* view : ordered) {
      const std::string id = std::to_string(view->sweep.id);
      html += fmt::format(
          "<tr><td><a href=\"/sweeps/{}\">{}</a></td><td>{}</td><td>{}</td><td class=\"number\">{}</td>{}"
          "<td>{}</td><td class=\"number\">{}</td><td class=\"number\">{}</td><td>{}</td><td>{}</td></tr>\n",
          id, id, HtmlEscape(view->sweep.name), HtmlEscape(view->sweep.submitter), view->sweep.priority,
          StateCell(view->sweep.cancel_requested && view->sweep.state == QueuedSweepState::kRunning
                        ? CancellingStateName()
                        : ToString(view->sweep.state)),
          Progress(view->counts), view->counts.failed, view->counts.reused, HtmlEscape(view->eta), Links(*view));
    }
    html += "</tbody>\n</table>\n";
  }
  html += fmt::format(
      "</main>\n<footer><p>Refreshes every {} s. API: <a href=\"/api/sweeps\">/api/sweeps</a>, "
      "<a href=\"/metrics\">/metrics</a>, <a href=\"/healthz\">/healthz</a>.</p></footer>\n</body>\n</html>\n",
      kPageRefreshSeconds);
  return html;
}

std::string RenderSweepPage(const SweepView& view, const std::vector<RunView>& runs) {
  const QueuedSweep& sweep = view.sweep;
  const bool finished = IsFinished(sweep.state);
  std::string html =
      Head(fmt::format("sweep {} {}", sweep.id, sweep.name), !finished || view.report == ReportState::kWriting);
  html += fmt::format("<header><nav><a href=\"/\">all sweeps</a></nav><h1>sweep {}: {}</h1>\n", sweep.id,
                      HtmlEscape(sweep.name));
  html += "<dl>\n";
  const auto item = [&](std::string_view term, const std::string& value) {
    html += fmt::format("<dt>{}</dt><dd>{}</dd>\n", term, value);
  };
  item("state", HtmlEscape(ToString(sweep.state)) +
                    (sweep.cancel_requested && !finished ? fmt::format(" ({})", CancellingStateName()) : ""));
  item("config", HtmlEscape(sweep.config_name));
  item("submitted by", HtmlEscape(sweep.submitter));
  item("priority", std::to_string(sweep.priority));
  item("submitted", HtmlEscape(sweep.submitted_at));
  if (!sweep.started_at.empty()) item("started", HtmlEscape(sweep.started_at));
  if (!sweep.finished_at.empty()) item("finished", HtmlEscape(sweep.finished_at));
  item("progress", Progress(view.counts));
  if (!view.eta.empty()) item("ETA", HtmlEscape(view.eta));
  if (!sweep.message.empty()) item("message", HtmlEscape(sweep.message));
  item("results", HtmlEscape(sweep.result_dir.string()));
  const std::string links = Links(view);
  if (!links.empty()) item("files", links);
  html +=
      "</dl>\n</header>\n<main>\n<table>\n<thead><tr><th>run</th><th>state</th><th>attempts</th>"
      "<th>wall s</th><th>reason</th></tr></thead>\n<tbody>\n";
  for (const RunView& run : runs) {
    std::string state(ToString(run.state));
    if (run.reused_from) state += " from sweep " + std::to_string(*run.reused_from);
    html += fmt::format("<tr><td>{}</td>{}<td class=\"number\">{}</td><td class=\"number\">{}</td><td>{}</td></tr>\n",
                        HtmlEscape(run.run_id), StateCell(state), run.attempt,
                        run.wall_s ? fmt::format("{:.1f}", *run.wall_s) : "", HtmlEscape(run.reason));
  }
  html += "</tbody>\n</table>\n</main>\n</body>\n</html>\n";
  return html;
}

std::string_view ServiceStyleSheet() {
  return R"css(body { font-family: sans-serif; margin: 1.5em; color: #222; }
h1 { font-size: 1.4em; }
table { border-collapse: collapse; }
th, td { border-bottom: 1px solid #ddd; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
th { background: #f3f3f3; }
td.number { text-align: right; }
.state-ok { color: #16632a; }
.state-failed, .state-cancelled { color: #a11; }
.state-running, .state-cancelling { color: #1c4fa0; }
dl { display: grid; grid-template-columns: max-content auto; gap: 0.2em 1em; }
dt { font-weight: bold; }
dd { margin: 0; }
progress { width: 8em; }
footer { margin-top: 2em; color: #666; font-size: 0.9em; }
)css";
}

}  // namespace slamsweep::orchestrator::service
