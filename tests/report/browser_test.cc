// The report in a real browser: headless Chromium loads pages from a local server that sends
// Jenkins' default Content-Security-Policy. No CSP violation may be logged and every <img> of a
// page must have been fetched with status 200. The index's screenshot is kept as an artifact.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "report/html/standard_artwork.h"
#include "report/html/write_report.h"
#include "tests/report/fake_artwork.h"
#include "tests/report/fixture_sweep.h"
#include "tests/support/shared_data.h"

extern char** environ;

namespace slamsweep::report {
namespace {

namespace fs = std::filesystem;
using slamsweep::testing::TempDir;
using testing::ReadAll;

constexpr const char* kChromium = "/usr/bin/chromium";
constexpr const char* kPython = "/usr/bin/python3";

/// A child process (no shell) with stdout and stderr sent to files; killed when destroyed.
class Child {
 public:
  Child(const std::vector<std::string>& argv, const fs::path& stdout_file, const fs::path& stderr_file) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    // Its own process group, so that Chromium's helper processes end with it.
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    if (posix_spawn(&pid_, argv[0].c_str(), &actions, &attributes, args.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
  }
  ~Child() {
    if (pid_ > 0 && !exited_) {
      kill(-pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  bool started() const { return pid_ > 0; }
  /// Waits up to `timeout`; true when the process ended by itself.
  bool Wait(std::chrono::seconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  }
  void Stop() {
    if (pid_ <= 0 || exited_) return;
    kill(-pid_, SIGTERM);
    if (!Wait(std::chrono::seconds(5))) kill(-pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    exited_ = true;
  }

 private:
  pid_t pid_ = -1;
  bool exited_ = false;
};

struct BrowserRun {
  std::string stderr_text;
  bool finished = false;
};

BrowserRun LoadInChromium(const std::string& url, const fs::path& work, const std::string& name,
                          const fs::path& screenshot, int window_height_px = 2000) {
  std::vector<std::string> argv = {kChromium, "--headless=new", "--no-sandbox", "--disable-gpu",
                                   "--no-first-run", "--enable-logging=stderr", "--v=0",
                                   "--user-data-dir=" + (work / ("profile-" + name)).string(),
                                   "--window-size=1280," + std::to_string(window_height_px)};
  if (screenshot.empty()) {
    argv.push_back("--dump-dom");
  } else {
    argv.push_back("--screenshot=" + screenshot.string());
  }
  argv.push_back(url);
  Child chromium(argv, work / (name + ".out"), work / (name + ".err"));
  BrowserRun run;
  if (!chromium.started()) return run;
  run.finished = chromium.Wait(std::chrono::seconds(40));
  chromium.Stop();
  run.stderr_text = ReadAll(work / (name + ".err"));
  return run;
}

std::vector<std::string> CspViolations(const std::string& stderr_text) {
  std::vector<std::string> lines;
  std::istringstream in(stderr_text);
  for (std::string line; std::getline(in, line);) {
    if (line.find("Refused to") != std::string::npos || line.find("Content Security Policy") != std::string::npos) {
      lines.push_back(line);
    }
  }
  return lines;
}

class BrowserTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kChromium) || !fs::exists(kPython)) {
      const std::string why = std::string(kChromium) + " or " + kPython + " is missing (apt-get install chromium)";
      if (slamsweep::testing::RunningInCi()) FAIL() << why;
      GTEST_SKIP() << why;
    }
    testing::WriteFixtureSweep(dir_ / "sweep", Runs());
    artwork_ = MakeStandardArtwork();
    ReportOptions options;
    options.artwork = artwork_ ? artwork_.get() : &fake_;
    WriteReport(dir_ / "sweep", dir_ / "report", options);
    server_ = std::make_unique<Child>(
        std::vector<std::string>{kPython, SLAMSWEEP_CSP_SERVER, (dir_ / "report").string(),
                                 (dir_ / "port").string(), (dir_ / "requests.log").string()},
        dir_ / "server.out", dir_ / "server.err");
    ASSERT_TRUE(server_->started());
    for (int i = 0; i < 200 && !fs::exists(dir_ / "port"); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_TRUE(fs::exists(dir_ / "port")) << ReadAll(dir_ / "server.err");
    base_url_ = "http://127.0.0.1:" + ReadAll(dir_ / "port") + "/";
  }
  void TearDown() override {
    if (server_) server_->Stop();
  }

  virtual std::vector<testing::FixtureRun> Runs() const { return testing::StandardFixtureRuns(); }

  // Loads `page` and checks: no CSP violation, every image of the page requested with 200.
  void CheckPage(const std::string& page, const fs::path& screenshot = {}, int window_height_px = 2000) {
    SCOPED_TRACE(page);
    const std::string name = "page" + std::to_string(++pages_);
    const BrowserRun run = LoadInChromium(base_url_ + page, dir_.path(), name, screenshot, window_height_px);
    EXPECT_TRUE(run.finished) << "chromium did not finish in 40 s";
    EXPECT_TRUE(CspViolations(run.stderr_text).empty()) << ::testing::PrintToString(CspViolations(run.stderr_text));
    const std::string log = ReadAll(dir_ / "requests.log");
    EXPECT_NE(log.find("200 /" + page), std::string::npos) << log;
    EXPECT_NE(log.find("200 /style.css"), std::string::npos) << log;
    const fs::path page_dir = fs::path("/" + page).parent_path();
    const std::vector<std::string> images = testing::ImageSources(dir_ / "report" / page);
    for (const std::string& src : images) {
      const std::string path = (page_dir / src).lexically_normal().generic_string();
      EXPECT_NE(log.find("200 " + path + "\n"), std::string::npos) << "image not loaded: " << path;
    }
  }

  TempDir dir_;
  testing::FakeArtwork fake_;
  std::unique_ptr<Artwork> artwork_;
  std::unique_ptr<Child> server_;
  std::string base_url_;
  int pages_ = 0;
};

TEST_F(BrowserTest, PagesLoadUnderJenkinsCsp) {
  const fs::path screenshot = fs::path(SLAMSWEEP_ARTIFACT_DIR) / "report_index_screenshot.png";
  CheckPage("index.html", screenshot);
  EXPECT_TRUE(fs::exists(screenshot));
  std::cout << "screenshot of the index: " << screenshot.string() << "\n";
  RecordProperty("screenshot", screenshot.string());
  EXPECT_FALSE(testing::ImageSources(dir_ / "report/index.html").empty());
  CheckPage("sequences/intel-clean.html");
  CheckPage("runs/_script_alert_1___script_-intel-clean-i0-0000abcd.html");
  CheckPage("validity.html");
  const fs::path metrics_screenshot = fs::path(SLAMSWEEP_ARTIFACT_DIR) / "report_metrics_screenshot.png";
  CheckPage("metrics.html", metrics_screenshot, 3400);
  EXPECT_TRUE(fs::exists(metrics_screenshot));
  std::cout << "screenshot of the metric specification: " << metrics_screenshot.string() << "\n";
}

// The validity page (report/html/validity_page.h) with numbers and its scatter plots, on a sweep of
// graded noise settings; its screenshot is kept as an artifact.
class ValidityBrowserTest : public BrowserTest {
 protected:
  std::vector<testing::FixtureRun> Runs() const override { return testing::ValidityFixtureRuns(); }
};

TEST_F(ValidityBrowserTest, TheValidityPageWithItsPlotsLoadsUnderJenkinsCsp) {
  const fs::path screenshot = fs::path(SLAMSWEEP_ARTIFACT_DIR) / "report_validity_screenshot.png";
  fs::remove(screenshot);
  CheckPage("validity.html", screenshot, 3400);
  EXPECT_TRUE(fs::exists(screenshot));
  EXPECT_EQ(testing::ImageSources(dir_ / "report/validity.html").size(), 24u);
  std::cout << "screenshot of the validity page: " << screenshot.string() << "\n";
}

// The segment-length and parameter pages (report/html/view_pages.h) on a sweep that has both; their
// screenshots, and the sequence page's with its palette swatches, are kept as artifacts.
class ViewsBrowserTest : public BrowserTest {
 protected:
  std::vector<testing::FixtureRun> Runs() const override { return testing::ViewsFixtureRuns(); }
};

TEST_F(ViewsBrowserTest, SegmentAndParameterPagesLoadUnderJenkinsCsp) {
  const std::pair<const char*, const char*> pages[] = {
      {"sequences/intel-clean/segments.html", "report_segments_screenshot.png"},
      {"sequences/intel-clean/parameters.html", "report_parameters_screenshot.png"},
      {"sequences/intel-clean.html", "report_sequence_screenshot.png"}};
  for (const auto& [page, file] : pages) {
    const fs::path screenshot = fs::path(SLAMSWEEP_ARTIFACT_DIR) / file;
    fs::remove(screenshot);
    // Tall windows: the screenshot shows the whole page, every figure of it.
    CheckPage(page, screenshot, 3400);
    EXPECT_TRUE(fs::exists(screenshot)) << page;
    EXPECT_FALSE(testing::ImageSources(dir_ / "report" / page).empty()) << page;
    std::cout << "screenshot of " << page << ": " << screenshot.string() << "\n";
    RecordProperty(std::string("screenshot ") + page, screenshot.string());
  }
  EXPECT_TRUE(testing::BrokenLinks(dir_ / "report").empty());
}

// The detector itself: a page with an inline style must be reported, or a silent browser would
// pass every check above.
TEST_F(BrowserTest, InlineStyleIsReportedAsViolation) {
  slamsweep::testing::WriteFile(dir_ / "report/bad.html",
                                "<!DOCTYPE html><html><head><style>p{color:red}</style></head><body><p>x</p></body></html>");
  const BrowserRun run = LoadInChromium(base_url_ + "bad.html", dir_.path(), "bad", {});
  EXPECT_TRUE(run.finished);
  EXPECT_FALSE(CspViolations(run.stderr_text).empty()) << run.stderr_text;
}

}  // namespace
}  // namespace slamsweep::report
