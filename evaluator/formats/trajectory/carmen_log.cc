#include "evaluator/formats/trajectory/carmen_log.h"

#include <zlib.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <algorithm>
#include <fstream>
#include <optional>

#include "evaluator/core/gzip_inflate.h"
#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/output_file.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {
namespace {

constexpr std::string_view kFlaserLayout =
    "FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp ipc_hostname logger_timestamp";
constexpr std::string_view kRobotLaserLayout =
    "ROBOTLASER1 laser_type start_angle fov angular_res max_range accuracy remission_mode num_readings [ranges] "
    "num_remissions [remissions] laser_pose_x laser_pose_y laser_pose_theta robot_pose_x robot_pose_y "
    "robot_pose_theta tv rv forward_safety side_safety turn_axis ipc_timestamp ipc_hostname logger_timestamp";
constexpr std::string_view kOdomLayout = "ODOM x y theta tv rv accel ipc_timestamp ipc_hostname logger_timestamp";
constexpr std::string_view kParamLayout = "PARAM name value [ipc_timestamp ipc_hostname logger_timestamp]";

/// A count field (beams, remissions) that must leave room for `fields_after` more fields.
std::size_t ReadCount(const TextRecord& record, std::size_t index, std::string_view name) {
  const long long count = record.Integer(index, name);
  if (count < 0) {
    record.Fail("field " + std::to_string(index + 1) + " (" + std::string(name) + "): expected a count >= 0, got " +
                std::to_string(count));
  }
  // Larger than the line itself: no field count can match; say so before any arithmetic overflows.
  if (static_cast<unsigned long long>(count) > record.size()) {
    record.Fail("field " + std::to_string(index + 1) + " (" + std::string(name) + ") says " + std::to_string(count) +
                " values but the line has only " + std::to_string(record.size()) + " fields");
  }
  return static_cast<std::size_t>(count);
}

void RequireExactFields(const TextRecord& record, std::size_t expected, std::string_view why, std::string_view layout) {
  if (record.size() != expected) {
    record.Fail(std::string(why) + " needs " + std::to_string(expected) + " fields, got " +
                std::to_string(record.size()) +
                " (a truncated line, or a count that disagrees with its values?); layout: " + std::string(layout));
  }
}

std::vector<double> ReadNumbers(const TextRecord& record, std::size_t first, std::size_t count, std::string_view name) {
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = record.Number(first + i, name);
  return values;
}

Pose ReadPlanarPose(const TextRecord& record, std::size_t first, std::string_view prefix) {
  const std::string p(prefix);
  return Pose::Planar(record.Number(first, p + "x"), record.Number(first + 1, p + "y"),
                      record.Number(first + 2, p + "theta"));
}

/// FLASER and RLASER share one layout; `type` is the message name (record.Text(0)).
CarmenLaserRecord ParseFlaser(const TextRecord& record) {
  const std::string type(record.Text(0));
  const std::string layout = type + std::string(kFlaserLayout.substr(kFlaserLayout.find(' ')));
  record.RequireFields(2, layout);
  const std::size_t beams = ReadCount(record, 1, "num_readings");
  RequireExactFields(record, beams + 11, type + " with num_readings = " + std::to_string(beams), layout);
  CarmenLaserRecord laser;
  laser.type = type;
  laser.ranges_m = ReadNumbers(record, 2, beams, "range");
  const std::size_t base = 2 + beams;
  laser.robot_pose = ReadPlanarPose(record, base, "");
  laser.laser_pose = laser.robot_pose;
  laser.odom_pose = ReadPlanarPose(record, base + 3, "odom_");
  laser.ipc_stamp_s = record.Number(base + 6, "ipc_timestamp");
  laser.ipc_host = std::string(record.Text(base + 7));
  laser.logger_stamp_s = record.Number(base + 8, "logger_timestamp");
  laser.line = record.line_number();
  return laser;
}

CarmenLaserRecord ParseRobotLaser(const TextRecord& record) {
  record.RequireFields(10, kRobotLaserLayout);
  CarmenLaserRecord laser;
  laser.type = "ROBOTLASER1";
  CarmenBeamGeometry geometry;
  geometry.laser_type = static_cast<int>(record.Integer(1, "laser_type"));
  geometry.start_angle_rad = record.Number(2, "start_angle");
  geometry.fov_rad = record.Number(3, "fov");
  geometry.angular_resolution_rad = record.Number(4, "angular_res");
  geometry.max_range_m = record.Number(5, "max_range");
  geometry.accuracy_m = record.Number(6, "accuracy");
  geometry.remission_mode = static_cast<int>(record.Integer(7, "remission_mode"));
  laser.geometry = geometry;
  const std::size_t beams = ReadCount(record, 8, "num_readings");
  record.RequireFields(10 + beams, kRobotLaserLayout);
  const std::size_t remissions = ReadCount(record, 9 + beams, "num_remissions");
  RequireExactFields(record, 24 + beams + remissions,
                     "ROBOTLASER1 with num_readings = " + std::to_string(beams) +
                         " and num_remissions = " + std::to_string(remissions),
                     kRobotLaserLayout);
  laser.ranges_m = ReadNumbers(record, 9, beams, "range");
  laser.remissions = ReadNumbers(record, 10 + beams, remissions, "remission");
  const std::size_t base = 10 + beams + remissions;
  laser.laser_pose = ReadPlanarPose(record, base, "laser_pose_");
  laser.robot_pose = ReadPlanarPose(record, base + 3, "robot_pose_");
  laser.odom_pose = laser.robot_pose;
  // tv rv forward_safety side_safety turn_axis: checked as numbers, not kept.
  ReadNumbers(record, base + 6, 5, "tv/rv/forward_safety/side_safety/turn_axis");
  laser.ipc_stamp_s = record.Number(base + 11, "ipc_timestamp");
  laser.ipc_host = std::string(record.Text(base + 12));
  laser.logger_stamp_s = record.Number(base + 13, "logger_timestamp");
  laser.line = record.line_number();
  return laser;
}

CarmenOdomRecord ParseOdom(const TextRecord& record) {
  RequireExactFields(record, 10, "ODOM", kOdomLayout);
  CarmenOdomRecord odom;
  odom.pose = ReadPlanarPose(record, 1, "");
  odom.tv_mps = record.Number(4, "tv");
  odom.rv_radps = record.Number(5, "rv");
  odom.accel_mps2 = record.Number(6, "accel");
  odom.ipc_stamp_s = record.Number(7, "ipc_timestamp");
  odom.ipc_host = std::string(record.Text(8));
  odom.logger_stamp_s = record.Number(9, "logger_timestamp");
  odom.line = record.line_number();
  return odom;
}

std::string Host(const std::string& host) { return host.empty() ? "nohost" : host; }

void AppendPose(std::string& out, const Pose& pose) {
  out += ' ' + ShortestText(pose.position.x()) + ' ' + ShortestText(pose.position.y()) + ' ' + ShortestText(pose.Yaw());
}

void AppendNumbers(std::string& out, const std::vector<double>& values) {
  for (double value : values) out += ' ' + ShortestText(value);
}

// ---- Fast path --------------------------------------------------------------------------------
// A corrected log is millions of numbers in FLASER and ODOM lines. These are read straight from the
// file buffer with std::from_chars, without splitting lines into field vectors. Anything unusual
// (a bad number, a wrong field count, NaN) makes the fast path give up on that line; the line is
// then parsed by the TextRecord path above, which produces the precise error message (or accepts
// what the fast path was too strict for). So both paths accept exactly the same logs.

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// Exact powers of ten as doubles (10^22 is the largest that a double holds exactly).
constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

class LineCursor {
 public:
  LineCursor(const char* begin, const char* end) : p_(begin), end_(end) {}

  void SkipBlanks() {
    while (p_ != end_ && IsBlank(*p_)) ++p_;
  }
  bool AtEnd() {
    SkipBlanks();
    return p_ == end_;
  }
  bool Token(std::string_view& token) {
    SkipBlanks();
    const char* start = p_;
    while (p_ != end_ && !IsBlank(*p_)) ++p_;
    token = std::string_view(start, static_cast<std::size_t>(p_ - start));
    return p_ != start;
  }
  bool Number(double& value) {
    SkipBlanks();
    if (SimpleDecimal(value)) return true;
    const auto [stop, error] = std::from_chars(p_, end_, value);
    if (error != std::errc() || (stop != end_ && !IsBlank(*stop)) || !std::isfinite(value)) return false;
    p_ = stop;
    return true;
  }
  bool Count(std::size_t& count) {
    SkipBlanks();
    long long value = 0;
    const auto [stop, error] = std::from_chars(p_, end_, value);
    if (error != std::errc() || (stop != end_ && !IsBlank(*stop)) || value < 0) return false;
    // Every value needs at least two characters (digit and separator): a larger count cannot fit.
    if (static_cast<unsigned long long>(value) > static_cast<unsigned long long>(end_ - stop) / 2 + 1) return false;
    p_ = stop;
    count = static_cast<std::size_t>(value);
    return true;
  }
  bool PlanarPose(Pose& pose) {
    double x = 0.0, y = 0.0, theta = 0.0;
    if (!Number(x) || !Number(y) || !Number(theta)) return false;
    pose = Pose::Planar(x, y, theta);
    return true;
  }

 private:
  /// `[-]digits[.digits]` with at most 15 significant digits and 22 decimals, the form of nearly
  /// every number in a CARMEN log. Then mantissa and 10^decimals are exact doubles and one
  /// division rounds correctly (Clinger's fast path), so the value is the one std::from_chars gives,
  /// several times faster. Anything else (exponent, long mantissa, no digit) is left to from_chars.
  bool SimpleDecimal(double& value) {
    const char* q = p_;
    const bool negative = q != end_ && *q == '-';
    if (negative) ++q;
    std::uint64_t mantissa = 0;
    int digits = 0;
    int decimals = 0;
    const char* integer_start = q;
    while (q != end_ && *q >= '0' && *q <= '9') {
      mantissa = mantissa * 10 + static_cast<std::uint64_t>(*q - '0');
      ++digits;
      ++q;
    }
    if (q == integer_start) return false;
    if (q != end_ && *q == '.') {
      ++q;
      const char* fraction_start = q;
      while (q != end_ && *q >= '0' && *q <= '9') {
        mantissa = mantissa * 10 + static_cast<std::uint64_t>(*q - '0');
        ++digits;
        ++q;
      }
      decimals = static_cast<int>(q - fraction_start);
      if (decimals == 0) return false;
    }
    if (digits > 15 || decimals > 22 || (q != end_ && !IsBlank(*q))) return false;
    const double magnitude = static_cast<double>(mantissa) / kExactPowersOfTen[decimals];
    value = negative ? -magnitude : magnitude;
    p_ = q;
    return true;
  }

  const char* p_;
  const char* end_;
};

/// The stamps and host that end FLASER, ROBOTLASER1 and ODOM lines; nothing may follow them.
bool ReadStampTail(LineCursor& cursor, double& ipc_stamp_s, std::string& host, double& logger_stamp_s) {
  std::string_view host_text;
  if (!cursor.Number(ipc_stamp_s) || !cursor.Token(host_text) || !cursor.Number(logger_stamp_s)) return false;
  host.assign(host_text);
  return cursor.AtEnd();
}

bool FastFlaser(LineCursor& cursor, std::size_t line, std::string_view type, CarmenLaserRecord& laser) {
  std::size_t beams = 0;
  if (!cursor.Count(beams)) return false;
  laser.type.assign(type);
  laser.ranges_m.resize(beams);
  for (double& range : laser.ranges_m) {
    if (!cursor.Number(range)) return false;
  }
  if (!cursor.PlanarPose(laser.robot_pose) || !cursor.PlanarPose(laser.odom_pose)) return false;
  laser.laser_pose = laser.robot_pose;
  laser.line = line;
  return ReadStampTail(cursor, laser.ipc_stamp_s, laser.ipc_host, laser.logger_stamp_s);
}

bool FastOdom(LineCursor& cursor, std::size_t line, CarmenOdomRecord& odom) {
  if (!cursor.PlanarPose(odom.pose) || !cursor.Number(odom.tv_mps) || !cursor.Number(odom.rv_radps) ||
      !cursor.Number(odom.accel_mps2)) {
    return false;
  }
  odom.line = line;
  return ReadStampTail(cursor, odom.ipc_stamp_s, odom.ipc_host, odom.logger_stamp_s);
}

/// Parses a log line by line, as the lines arrive: ReadCarmenLog feeds it while inflating, so the
/// text is parsed while it is still in cache and the whole log is never held at once.
class CarmenLogParser {
 public:
  explicit CarmenLogParser(const std::filesystem::path& source) : source_(source) {}

  /// Every line of `text`; a last line without '\n' counts as a line. Feeding a log in pieces that
  /// each end with '\n' numbers the lines as one call with the whole log does.
  void ParseLines(std::string_view text) {
    const char* p = text.data();
    const char* const end = p + text.size();
    while (p < end) {
      const char* newline = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
      const char* line_end = newline != nullptr ? newline : end;
      ParseLine(std::string_view(p, static_cast<std::size_t>(line_end - p)));
      p = line_end + 1;
    }
  }

  CarmenLog Finish() { return std::move(log_); }

 private:
  void ParseLine(std::string_view line) {
    ++line_number_;
    LineCursor cursor(line.data(), line.data() + line.size());
    std::string_view type;
    if (!cursor.Token(type) || type.front() == '#') return;
    if (type == "FLASER" || type == "RLASER") {
      if (FastFlaser(cursor, line_number_, type, laser_)) {
        log_.lasers.push_back(std::move(laser_));
        laser_ = CarmenLaserRecord{};
        laser_.ranges_m.reserve(log_.lasers.back().ranges_m.size());
        return;
      }
    } else if (type == "ODOM") {
      if (FastOdom(cursor, line_number_, odom_)) {
        log_.odometry.push_back(odom_);
        return;
      }
    } else if (type != "ROBOTLASER1" && type != "PARAM") {
      ++log_.skipped_messages[std::string(type)];
      return;
    }
    ParseSlowly(TextRecord(source_, line_number_, SplitFields(line, " \t\r")));
  }

  /// The checked path, for what the fast path gave up on: it reports the precise error.
  void ParseSlowly(const TextRecord& record) {
    const std::string_view type = record.Text(0);
    if (type == "FLASER" || type == "RLASER") {
      log_.lasers.push_back(ParseFlaser(record));
    } else if (type == "ROBOTLASER1") {
      log_.lasers.push_back(ParseRobotLaser(record));
    } else if (type == "ODOM") {
      log_.odometry.push_back(ParseOdom(record));
    } else {
      record.RequireFields(3, kParamLayout);
      log_.params.push_back({std::string(record.Text(1)), std::string(record.Text(2)), record.line_number()});
    }
  }

  const std::filesystem::path& source_;
  CarmenLog log_;
  std::size_t line_number_ = 0;
  CarmenLaserRecord laser_;
  CarmenOdomRecord odom_;
};

/// Inflates gzip `compressed` piece by piece into a small window and hands the complete lines of
/// each piece to `parser`. Concatenated gzip members are read one after another, as gzip does;
/// anything else after a member is ignored, as zlib's gzread does.
void InflateAndParse(const std::string& compressed, const std::filesystem::path& path, CarmenLogParser& parser) {
  struct InflateStream {
    z_stream stream{};
    ~InflateStream() { inflateEnd(&stream); }
  } z;
  if (inflateInit2(&z.stream, 16 + MAX_WBITS) != Z_OK) {
    throw InputError(Located(path, 0, "cannot start gzip inflate"));
  }
  // Small enough to stay in cache between inflate and parse, large enough for a few hundred lines.
  std::string window(std::size_t{1} << 18, '\0');
  std::size_t held = 0;  // bytes of a line not yet complete, at the start of the window
  std::size_t consumed = 0;
  std::size_t produced = 0;
  int code = Z_OK;
  while (true) {
    if (held == window.size()) window.resize(window.size() * 2);  // one very long line
    const std::size_t in_left = compressed.size() - consumed;
    z.stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data() + consumed));
    z.stream.avail_in = static_cast<uInt>(std::min<std::size_t>(in_left, std::size_t{1} << 30));
    z.stream.next_out = reinterpret_cast<Bytef*>(window.data() + held);
    z.stream.avail_out = static_cast<uInt>(window.size() - held);
    const uInt avail_in = z.stream.avail_in;
    const uInt avail_out = z.stream.avail_out;
    code = inflate(&z.stream, Z_NO_FLUSH);
    consumed += avail_in - z.stream.avail_in;
    const std::size_t fresh = avail_out - z.stream.avail_out;
    produced += fresh;
    if (produced > GzipInflateCap(compressed.size())) {
      throw InputError(Located(path, 0, GzipInflateCapMessage(compressed.size())));
    }
    const std::size_t filled = held + fresh;
    const std::string_view text(window.data(), filled);
    const std::size_t last_newline = text.rfind('\n');
    if (last_newline != std::string_view::npos) {
      parser.ParseLines(text.substr(0, last_newline + 1));
      held = filled - (last_newline + 1);
      std::memmove(window.data(), window.data() + last_newline + 1, held);
    } else {
      held = filled;
    }
    if (code == Z_STREAM_END) {
      const std::string_view rest(compressed.data() + consumed, compressed.size() - consumed);
      if (!HasGzipMagic(rest)) break;
      inflateReset(&z.stream);
      continue;
    }
    if (code == Z_BUF_ERROR && consumed == compressed.size()) break;  // input ended inside a member
    if (code != Z_OK && code != Z_BUF_ERROR) break;
  }
  if (code != Z_STREAM_END) {
    const std::string message = z.stream.msg != nullptr ? z.stream.msg : "unexpected end of data";
    throw InputError(Located(
        path, 0,
        "truncated or corrupt gzip file (" + message + ") after " + std::to_string(produced) + " decompressed bytes"));
  }
  parser.ParseLines(std::string_view(window.data(), held));
}

std::string ReadBytes(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(Located(path, 0, "no such file (expected a readable regular file)"));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(Located(path, 0, "cannot open file for reading"));
  std::string bytes(static_cast<std::size_t>(std::filesystem::file_size(path, error)), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (static_cast<std::size_t>(in.gcount()) != bytes.size()) {
    throw InputError(Located(path, 0, "cannot read the whole file"));
  }
  return bytes;
}

}  // namespace

CarmenLog ParseCarmenLog(std::string_view content, const std::filesystem::path& source) {
  CarmenLogParser parser(source);
  parser.ParseLines(content);
  return parser.Finish();
}

CarmenLog ReadCarmenLog(const std::filesystem::path& path) {
  const std::string bytes = ReadBytes(path);
  if (!HasGzipMagic(bytes)) return ParseCarmenLog(bytes, path);
  if (const std::optional<std::string> text = InflateWholeGzip(bytes)) return ParseCarmenLog(*text, path);
  // Damaged: zlib's streaming inflate parses what is good and says where the data ends.
  CarmenLogParser parser(path);
  InflateAndParse(bytes, path, parser);
  return parser.Finish();
}

std::string FormatCarmenRecord(const CarmenLaserRecord& record) {
  std::string out;
  if (record.type == "ROBOTLASER1") {
    const CarmenBeamGeometry geometry = record.geometry.value_or(CarmenBeamGeometry{});
    out = "ROBOTLASER1 " + std::to_string(geometry.laser_type) + ' ' + ShortestText(geometry.start_angle_rad) + ' ' +
          ShortestText(geometry.fov_rad) + ' ' + ShortestText(geometry.angular_resolution_rad) + ' ' +
          ShortestText(geometry.max_range_m) + ' ' + ShortestText(geometry.accuracy_m) + ' ' +
          std::to_string(geometry.remission_mode) + ' ' + std::to_string(record.ranges_m.size());
    AppendNumbers(out, record.ranges_m);
    out += ' ' + std::to_string(record.remissions.size());
    AppendNumbers(out, record.remissions);
    AppendPose(out, record.laser_pose);
    AppendPose(out, record.robot_pose);
    out += " 0 0 0 0 0";  // tv rv forward_safety side_safety turn_axis: not kept by the parser
  } else {
    out = (record.type == "RLASER" ? "RLASER " : "FLASER ") + std::to_string(record.ranges_m.size());
    AppendNumbers(out, record.ranges_m);
    AppendPose(out, record.robot_pose);
    AppendPose(out, record.odom_pose);
  }
  out +=
      ' ' + ShortestText(record.ipc_stamp_s) + ' ' + Host(record.ipc_host) + ' ' + ShortestText(record.logger_stamp_s);
  return out;
}

std::string FormatCarmenRecord(const CarmenOdomRecord& record) {
  std::string out = "ODOM";
  AppendPose(out, record.pose);
  out += ' ' + ShortestText(record.tv_mps) + ' ' + ShortestText(record.rv_radps) + ' ' +
         ShortestText(record.accel_mps2) + ' ' + ShortestText(record.ipc_stamp_s) + ' ' + Host(record.ipc_host) + ' ' +
         ShortestText(record.logger_stamp_s);
  return out;
}

std::string FormatCarmenRecord(const CarmenParam& param) { return "PARAM " + param.name + ' ' + param.value; }

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
