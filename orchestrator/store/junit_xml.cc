#include "orchestrator/store/junit_xml.h"

#include <cstdint>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "orchestrator/files/atomic_file.h"
#include "orchestrator/run/run_spec.h"
#include "orchestrator/store/json_lookup.h"

namespace slamsweep::orchestrator::inline store {
namespace {

using nlohmann::json;

// XML 1.0 `Char`: anything else (most C0 controls, surrogates, U+FFFE/U+FFFF) makes the document
// unreadable for every JUnit consumer, so it is dropped rather than escaped.
bool IsXmlChar(std::uint32_t c) {
  return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD) ||
         (c >= 0x10000 && c <= 0x10FFFF);
}

void AppendUtf8(std::string& out, std::uint32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

struct Decoded {
  std::uint32_t code_point;
  std::size_t length;
};

// One UTF-8 sequence at `i`; overlong forms, surrogates and truncated sequences decode as U+FFFD of length 1.
Decoded DecodeUtf8(std::string_view text, std::size_t i) {
  constexpr Decoded kInvalid{0xFFFD, 1};
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
  const std::uint8_t lead = byte(i);
  if (lead < 0x80) return {lead, 1};
  std::size_t length = 0;
  std::uint32_t c = 0;
  std::uint32_t minimum = 0;
  if ((lead & 0xE0) == 0xC0) {
    length = 2, c = lead & 0x1F, minimum = 0x80;
  } else if ((lead & 0xF0) == 0xE0) {
    length = 3, c = lead & 0x0F, minimum = 0x800;
  } else if ((lead & 0xF8) == 0xF0) {
    length = 4, c = lead & 0x07, minimum = 0x10000;
  } else {
    return kInvalid;
  }
  if (i + length > text.size()) return kInvalid;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return kInvalid;
    c = (c << 6) | (byte(i + k) & 0x3F);
  }
  if (c < minimum || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return kInvalid;
  return {c, length};
}

std::string Text(const json& value) {
  if (value.is_null()) return {};
  if (value.is_string()) return value.get<std::string>();
  return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string Seconds(double seconds) { return fmt::format("{:.3f}", seconds); }

struct Testcase {
  std::string xml;
  bool failed = false;
  double time_s = 0.0;
};

Testcase RenderTestcase(const RunRecord& run) {
  Testcase testcase;
  testcase.time_s = run.wall_s.value_or(0.0);
  std::string body;
  std::vector<std::string> notes;
  if (run.status != RunStatus::kOk) {
    testcase.failed = true;
    const std::string reason = Text(FieldOrNull(run.result, "reason"));
    std::string kind = Text(FieldOrNull(run.result, "failure_kind"));
    if (kind.empty()) kind = RunStatusName(RunStatus::kFailed);
    body +=
        fmt::format("      <failure message=\"{0}\" type=\"{1}\">{0}</failure>\n", XmlEscape(reason), XmlEscape(kind));
  } else {
    // Thresholds judge numbers; a run that produced none already failed above.
    ThresholdCheck check = CheckThresholds(run);
    if (!check.exceeded.empty()) {
      testcase.failed = true;
      std::string lines;
      for (const std::string& line : check.exceeded) lines += (lines.empty() ? "" : "\n") + line;
      body += fmt::format("      <failure message=\"{}\" type=\"threshold\">{}</failure>\n",
                          XmlEscape(check.exceeded.front()), XmlEscape(lines));
    }
  }
  // Marks travel with the case: a flagged pass is not a plain pass (Jenkins shows properties and output).
  std::string properties;
  std::vector<std::string> flag_notes;
  for (RunFlag flag : run.flags) {
    properties += fmt::format("        <property name=\"flag\" value=\"{}\"/>\n", RunFlagName(flag));
    flag_notes.push_back(fmt::format("{}: {}", RunFlagLabel(flag), RunFlagMeaning(flag)));
  }
  notes.insert(notes.begin(), flag_notes.begin(), flag_notes.end());
  if (!properties.empty()) body = "      <properties>\n" + properties + "      </properties>\n" + body;
  if (!notes.empty()) {
    std::string lines;
    for (const std::string& line : notes) lines += line + "\n";
    body += fmt::format("      <system-out>{}</system-out>\n", XmlEscape(lines));
  }
  // Jenkins groups by classname: one class per sequence x noise, the rows a report table compares;
  // the name says which group (algorithm and parameters) and iteration the run is.
  const std::string group = AlgorithmLabel(run.algorithm, run.parameters);
  const std::string open =
      fmt::format("    <testcase classname=\"{}\" name=\"{}\" time=\"{}\"", XmlEscape(run.sequence + "." + run.noise),
                  XmlEscape(fmt::format("{} i{} ({})", group, run.iteration, run.run_id)), Seconds(testcase.time_s));
  testcase.xml = body.empty() ? open + "/>\n" : open + ">\n" + body + "    </testcase>\n";
  return testcase;
}

struct Suite {
  std::string testcases;
  std::size_t tests = 0;
  std::size_t failures = 0;
  double time_s = 0.0;
};

}  // namespace

ThresholdCheck CheckThresholds(const RunRecord& run) {
  ThresholdCheck check;
  const json& thresholds = FieldOrNull(run.run_spec, "thresholds");
  if (thresholds.is_null()) return check;
  if (!thresholds.is_array()) {
    check.exceeded.push_back("run.json: thresholds: expected an array; no threshold could be checked");
    return check;
  }
  for (std::size_t i = 0; i < thresholds.size(); ++i) {
    const json& t = thresholds[i];
    const json& metric = FieldOrNull(t, "metric");
    const json& statistic_field = FieldOrNull(t, "statistic");
    const json& max = FieldOrNull(t, "max");
    const json& min = FieldOrNull(t, "min");
    if (!metric.is_string() || !(statistic_field.is_null() || statistic_field.is_string()) ||
        !(max.is_null() || max.is_number()) || !(min.is_null() || min.is_number()) ||
        (max.is_null() && min.is_null())) {
      check.exceeded.push_back(fmt::format(
          "run.json: thresholds[{}]: expected {{\"metric\", \"statistic\", \"max\" and/or \"min\"}}; it could not be "
          "checked",
          i));
      continue;
    }
    const std::string name = metric.get<std::string>();
    const std::string statistic = statistic_field.is_string() ? statistic_field.get<std::string>() : "rmse";
    const std::string label = name + "." + statistic;
    const FlatMetric* found = nullptr;
    for (const FlatMetric& m : run.metrics) {
      if (m.metric == name && m.statistic == statistic) found = &m;
    }
    if (found == nullptr) {
      // A limit the run cannot show it meets is not met: a pass would hide a missing number.
      check.exceeded.push_back(fmt::format("{}: the run has no such metric, so its limit is not met", label));
      continue;
    }
    if (!found->value.has_value()) {
      check.exceeded.push_back(fmt::format("{} = null (not a number), the limit cannot be met", label));
      continue;
    }
    const double v = *found->value;
    if (max.is_number() && v > max.get<double>()) {
      check.exceeded.push_back(fmt::format("{} = {} > {}", label, v, max.get<double>()));
    }
    if (min.is_number() && v < min.get<double>()) {
      check.exceeded.push_back(fmt::format("{} = {} < {}", label, v, min.get<double>()));
    }
  }
  return check;
}

std::string XmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const Decoded d = DecodeUtf8(text, i);
    i += d.length;
    if (!IsXmlChar(d.code_point)) continue;
    switch (d.code_point) {
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
        out += "&apos;";
        break;
      // References, because a parser turns literal tabs and newlines in attributes into spaces.
      case '\t':
        out += "&#9;";
        break;
      case '\n':
        out += "&#10;";
        break;
      case '\r':
        out += "&#13;";
        break;
      default:
        AppendUtf8(out, d.code_point);
    }
  }
  return out;
}

std::string RenderJUnit(const std::vector<RunRecord>& runs) {
  std::map<std::string, Suite> suites;  // sorted by sequence: a stable file for diffs between sweeps
  std::size_t failures = 0;
  double time_s = 0.0;
  for (const RunRecord& run : runs) {
    const Testcase testcase = RenderTestcase(run);
    Suite& suite = suites[run.sequence];
    suite.testcases += testcase.xml;
    ++suite.tests;
    suite.time_s += testcase.time_s;
    if (testcase.failed) {
      ++suite.failures;
      ++failures;
    }
    time_s += testcase.time_s;
  }
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += fmt::format("<testsuites name=\"slamsweep\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{}\">\n",
                     runs.size(), failures, Seconds(time_s));
  for (const auto& [sequence, suite] : suites) {
    xml +=
        fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" skipped=\"0\" time=\"{}\">\n",
                    XmlEscape(sequence), suite.tests, suite.failures, Seconds(suite.time_s));
    xml += suite.testcases;
    xml += "  </testsuite>\n";
  }
  xml += "</testsuites>\n";
  return xml;
}

void WriteJUnit(const std::vector<RunRecord>& runs, const std::filesystem::path& file) {
  WriteFileAtomically(file, RenderJUnit(runs));
}

}  // namespace slamsweep::orchestrator::inline store
