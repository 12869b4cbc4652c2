#include "orchestrator/store/junit_xml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/orchestrator/store/store_test_util.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
using testing::MakeFailedResult;
using testing::MakeOkResult;
using testing::MakeSpec;
using ::testing::Not;

// An independent XML parser (Python's ElementTree) reads the file back and reports its structure as JSON.
constexpr const char* kReadBack = R"py(
import json, sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
print(json.dumps({"tag": root.tag, "attrib": root.attrib, "suites": [
    {"tag": s.tag, "attrib": s.attrib, "cases": [
        {"tag": c.tag, "attrib": c.attrib,
         "failures": [{"attrib": f.attrib, "text": f.text or ""} for f in c.findall("failure")],
         "system_out": [o.text or "" for o in c.findall("system-out")]}
        for c in s]}
    for s in root]}))
)py";

json ParseWithPython(const slamsweep::testing::TempDir& dir, const std::filesystem::path& xml) {
  const auto script = slamsweep::testing::WriteFile(dir / "read_back.py", kReadBack);
  const std::string command = "/usr/bin/python3 '" + script.string() + "' '" + xml.string() + "' 2>&1";
  std::string output;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return json();
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof(buffer), pipe)) output.append(buffer, n);
  const int status = ::pclose(pipe);
  EXPECT_EQ(status, 0) << output;
  return json::parse(output, nullptr, false);
}

RunRecord MakeRun(const json& spec, const json& result, std::vector<FlatMetric> metrics = {}) {
  RunRecord run;
  run.run_id = spec.at("run_id");
  run.run_spec = spec;
  run.result = result;
  run.status = RecordedRunStatus(result.at("status").get<std::string>()).value();
  run.algorithm = spec.at("algorithm").at("name");
  run.sequence = spec.at("sequence").at("name");
  run.noise = "clean";
  ReadResultFields(result, run);
  run.metrics = std::move(metrics);
  return run;
}

std::vector<FlatMetric> MetricsOf(const json& result) {
  std::vector<FlatMetric> metrics;
  for (const json& m : result.at("metrics")) {
    metrics.push_back({m.at("metric"), m.at("statistic"), m.at("value").get<double>(), m.at("unit")});
  }
  return metrics;
}

TEST(JUnitXmlTest, OneSuitePerSequenceOneCasePerRunWithFailuresAndThresholds) {
  slamsweep::testing::TempDir dir;
  auto past_spec = MakeSpec("past", "icp-slam", "intel");
  past_spec["thresholds"] = {{{"metric", "ape_trans"}, {"statistic", "rmse"}, {"max", 0.5}},
                             {{"metric", "corners"}, {"statistic", "value"}, {"max", 100}, {"min", 20}},
                             {{"metric", "relations_trans"}, {"statistic", "mean"}, {"max", 1.0}},
                             {{"metric", "ape_rot"}, {"max", 2.0}}};
  const auto past = MakeOkResult("past", 2.0, 0.7);
  const auto fine = MakeOkResult("fine", 1.25, 0.2);
  const auto crashed = MakeFailedResult("crashed", "killed by SIGSEGV");
  const std::vector<RunRecord> runs = {
      MakeRun(past_spec, past, MetricsOf(past)),
      MakeRun(MakeSpec("fine", "icp-slam", "intel"), fine, MetricsOf(fine)),
      MakeRun(MakeSpec("crashed", "rbpf", "fr079"), crashed),
  };
  const auto file = dir / "junit.xml";
  WriteJUnit(runs, file);
  const json xml = ParseWithPython(dir, file);
  ASSERT_FALSE(xml.is_discarded());
  EXPECT_EQ(xml.at("tag"), "testsuites");
  EXPECT_EQ(xml.at("attrib").at("tests"), "3");
  EXPECT_EQ(xml.at("attrib").at("failures"), "2");
  const json& suites = xml.at("suites");
  ASSERT_EQ(suites.size(), 2u);
  EXPECT_EQ(suites[0].at("attrib").at("name"), "fr079");
  EXPECT_EQ(suites[0].at("attrib").at("tests"), "1");
  EXPECT_EQ(suites[1].at("attrib").at("name"), "intel");
  EXPECT_EQ(suites[1].at("attrib").at("tests"), "2");
  EXPECT_EQ(suites[1].at("attrib").at("failures"), "1");
  EXPECT_EQ(suites[1].at("attrib").at("time"), "3.250");

  const json& crashed_case = suites[0].at("cases")[0];
  // A class per sequence x noise, the runs a report table compares; the name says the row and iteration.
  EXPECT_EQ(crashed_case.at("attrib").at("classname"), "fr079.clean");
  EXPECT_EQ(crashed_case.at("attrib").at("name"), "rbpf i0 (crashed)");
  EXPECT_EQ(crashed_case.at("attrib").at("time"), "1.500");
  ASSERT_EQ(crashed_case.at("failures").size(), 1u);
  EXPECT_EQ(crashed_case.at("failures")[0].at("attrib").at("type"), "signal");
  EXPECT_EQ(crashed_case.at("failures")[0].at("attrib").at("message"), "killed by SIGSEGV");

  const json& past_case = suites[1].at("cases")[0];
  EXPECT_EQ(past_case.at("attrib").at("classname"), "intel.clean");
  EXPECT_EQ(past_case.at("attrib").at("name"), "icp-slam i0 (past)");
  ASSERT_EQ(past_case.at("failures").size(), 1u);
  EXPECT_EQ(past_case.at("failures")[0].at("attrib").at("type"), "threshold");
  // 0.7 > 0.5 and 17 corners < min 20; 17 <= max 100 is fine. The statistic defaults to rmse; both
  // missing metrics are failures too: a limit the run cannot show it meets is not met.
  EXPECT_EQ(past_case.at("failures")[0].at("text"),
            "ape_trans.rmse = 0.7 > 0.5\ncorners.value = 17 < 20\n"
            "relations_trans.mean: the run has no such metric, so its limit is not met\n"
            "ape_rot.rmse: the run has no such metric, so its limit is not met");
  EXPECT_EQ(past_case.at("failures")[0].at("attrib").at("message"), "ape_trans.rmse = 0.7 > 0.5");
  EXPECT_TRUE(past_case.at("system_out").empty());

  const json& fine_case = suites[1].at("cases")[1];
  EXPECT_EQ(fine_case.at("attrib").at("name"), "icp-slam i0 (fine)");
  EXPECT_TRUE(fine_case.at("failures").empty());
  EXPECT_TRUE(fine_case.at("system_out").empty());
}

TEST(JUnitXmlTest, EscapesMarkupAndDropsControlCharacters) {
  slamsweep::testing::TempDir dir;
  auto spec = MakeSpec("id<&>\"'", "alg<&>\"'", "seq\"<x>'&");
  const std::string reason = std::string("bad <tag> & \"quoted\" 'single'\x01\x1b[31m\ttab\nline\x7f\xff end");
  const auto result = MakeFailedResult("x", reason);
  const auto file = dir / "junit.xml";
  WriteJUnit({MakeRun(spec, result)}, file);
  const json xml = ParseWithPython(dir, file);
  ASSERT_FALSE(xml.is_discarded());
  EXPECT_EQ(xml.at("suites")[0].at("attrib").at("name"), "seq\"<x>'&");
  const json& testcase = xml.at("suites")[0].at("cases")[0];
  EXPECT_EQ(testcase.at("attrib").at("classname"), "seq\"<x>'&.clean");
  EXPECT_EQ(testcase.at("attrib").at("name"), "alg<&>\"' i0 (id<&>\"')");
  // \x01 and ESC are dropped, tab and newline survive (also in the attribute), DEL is a legal XML character,
  // the stray byte 0xff becomes U+FFFD.
  const std::string expected = "bad <tag> & \"quoted\" 'single'[31m\ttab\nline\x7f\xEF\xBF\xBD end";
  EXPECT_EQ(testcase.at("failures")[0].at("attrib").at("message"), expected);
  EXPECT_EQ(testcase.at("failures")[0].at("text"), expected);
}

TEST(JUnitXmlTest, XmlEscapeByHand) {
  EXPECT_EQ(XmlEscape("a<b>&\"'"), "a&lt;b&gt;&amp;&quot;&apos;");
  EXPECT_EQ(XmlEscape(std::string("x\0y", 3)), "xy");
  EXPECT_EQ(XmlEscape("\t\n\r"), "&#9;&#10;&#13;");
  EXPECT_EQ(XmlEscape("caf\xC3\xA9 \xF0\x9F\x98\x80"), "caf\xC3\xA9 \xF0\x9F\x98\x80");
  // Overlong '/', a lone continuation byte, a truncated sequence, an encoded surrogate, U+FFFE.
  EXPECT_EQ(XmlEscape("\xC0\xAF"), "\xEF\xBF\xBD\xEF\xBF\xBD");
  EXPECT_EQ(XmlEscape("\x80"), "\xEF\xBF\xBD");
  EXPECT_EQ(XmlEscape("\xE2\x82"), "\xEF\xBF\xBD\xEF\xBF\xBD");
  EXPECT_EQ(XmlEscape("\xED\xA0\x80"), "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");
  EXPECT_EQ(XmlEscape("\xEF\xBF\xBE"), "");
}

TEST(JUnitXmlTest, MalformedThresholdsFailNamingWhich) {
  auto spec = MakeSpec("r");
  spec["thresholds"] = {{{"metric", 3}}, {{"metric", "ape_trans"}, {"statistic", "rmse"}}, "nonsense"};
  const auto result = MakeOkResult("r");
  const ThresholdCheck check = CheckThresholds(MakeRun(spec, result, MetricsOf(result)));
  ASSERT_EQ(check.exceeded.size(), 3u);
  EXPECT_THAT(check.exceeded[0], HasSubstr("thresholds[0]"));
  EXPECT_THAT(check.exceeded[2], HasSubstr("thresholds[2]"));
  spec["thresholds"] = "all";
  EXPECT_THAT(CheckThresholds(MakeRun(spec, result)).exceeded.at(0), HasSubstr("expected an array"));
}

TEST(JUnitXmlTest, AThresholdOnAMetricTheRunLacksIsAFailureNotANote) {
  slamsweep::testing::TempDir dir;
  auto spec = MakeSpec("r");
  spec["thresholds"] = {{{"metric", "relations_trans"}, {"statistic", "mean"}, {"max", 0.5}}};
  const auto result = MakeOkResult("r");
  const ThresholdCheck check = CheckThresholds(MakeRun(spec, result, MetricsOf(result)));
  ASSERT_EQ(check.exceeded.size(), 1u);
  EXPECT_THAT(check.exceeded[0], HasSubstr("relations_trans.mean: the run has no such metric"));
  const auto file = dir / "junit.xml";
  WriteJUnit({MakeRun(spec, result, MetricsOf(result))}, file);
  std::ifstream in(file);
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(xml, HasSubstr("failures=\"1\""));
  EXPECT_THAT(xml, HasSubstr("type=\"threshold\""));
}

TEST(JUnitXmlTest, NullMetricFailsItsThreshold) {
  auto spec = MakeSpec("r");
  spec["thresholds"] = {{{"metric", "ape_trans"}, {"statistic", "rmse"}, {"max", 1.0}}};
  const ThresholdCheck check =
      CheckThresholds(MakeRun(spec, MakeOkResult("r"), {FlatMetric{"ape_trans", "rmse", std::nullopt, "m"}}));
  ASSERT_EQ(check.exceeded.size(), 1u);
  EXPECT_THAT(check.exceeded[0], HasSubstr("ape_trans.rmse = null"));
}

TEST(JUnitXmlTest, EmptyRunListIsAValidDocument) {
  slamsweep::testing::TempDir dir;
  WriteJUnit({}, dir / "junit.xml");
  const json xml = ParseWithPython(dir, dir / "junit.xml");
  ASSERT_FALSE(xml.is_discarded());
  EXPECT_EQ(xml.at("attrib").at("tests"), "0");
  EXPECT_TRUE(xml.at("suites").empty());
}

TEST(JUnitXmlTest, AFlaggedRunCarriesEachFlagAsAPropertyAndItsMeaningInItsOutput) {
  const auto result = MakeOkResult("r");
  RunRecord run = MakeRun(MakeSpec("r"), result, MetricsOf(result));
  run.flags = RunFlags{RunFlag::kStale, RunFlag::kUnisolated};
  const std::string xml = RenderJUnit({run});
  EXPECT_THAT(xml, HasSubstr("<property name=\"flag\" value=\"stale\"/>"));
  EXPECT_THAT(xml, HasSubstr("<property name=\"flag\" value=\"unisolated\"/>"));
  EXPECT_THAT(xml, HasSubstr(std::string(RunFlagMeaning(RunFlag::kUnisolated))));
  EXPECT_THAT(RenderJUnit({MakeRun(MakeSpec("r"), result, MetricsOf(result))}), Not(HasSubstr("<properties>")));
}

}  // namespace
}  // namespace slamsweep::orchestrator
