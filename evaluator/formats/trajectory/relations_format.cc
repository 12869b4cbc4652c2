#include "evaluator/formats/trajectory/relations_format.h"

#include <array>

#include "evaluator/core/huge_pages.h"
#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/euler_angles.h"
#include "evaluator/formats/trajectory/output_file.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {
namespace {

constexpr std::string_view kLayout = "t1 t2 x y z roll pitch yaw";
constexpr std::array<std::string_view, 8> kFieldNames = {"t1", "t2", "x", "y", "z", "roll", "pitch", "yaw"};

}  // namespace

Relations ParseRelations(std::string_view content, const std::filesystem::path& source) {
  Relations relations;
  relations.reserve(CountLines(content));
  AdviseHugePages(relations);
  // v: t1 t2 x y z roll pitch yaw
  const auto add = [&](const std::array<double, 8>& v) {
    Relation relation;
    relation.t1_s = v[0];
    relation.t2_s = v[1];
    relation.delta.position = {v[2], v[3], v[4]};
    relation.delta.orientation = QuaternionFromRollPitchYaw({.roll_rad = v[5], .pitch_rad = v[6], .yaw_rad = v[7]});
    relations.push_back(relation);
  };
  // Lines of eight finite numbers take the quick path; any other line is read field by field, which names
  // what is wrong with it.
  ForEachNumberLine<8>(
      content, [&](const std::array<double, 8>& v, std::string_view, std::size_t) { add(v); },
      [&](std::string_view line, std::size_t line_number) {
        const TextRecord record(source, line_number, SplitFields(line, " \t\r"));
        if (record.size() != 8) {
          record.Fail("expected 8 fields (" + std::string(kLayout) + "), got " + std::to_string(record.size()));
        }
        std::array<double, 8> v{};
        for (std::size_t i = 0; i < v.size(); ++i) v[i] = record.Number(i, kFieldNames[i]);  // the first bad one fails
        add(v);
      });
  if (relations.empty()) {
    throw InputError(Located(source, 0, "no relations found (expected lines '" + std::string(kLayout) + "')"));
  }
  return relations;
}

Relations ReadRelations(const std::filesystem::path& path) {
  return ParseRelations(ReadTextFileContent(path).text(), path);
}

void WriteRelations(const Relations& relations, std::ostream& out) {
  for (const Relation& relation : relations) {
    const RollPitchYaw angles = RollPitchYawFromQuaternion(relation.delta.orientation);
    const Eigen::Vector3d& t = relation.delta.position;
    out << ShortestText(relation.t1_s) << ' ' << ShortestText(relation.t2_s) << ' ' << ShortestText(t.x()) << ' '
        << ShortestText(t.y()) << ' ' << ShortestText(t.z()) << ' ' << ShortestText(angles.roll_rad) << ' '
        << ShortestText(angles.pitch_rad) << ' ' << ShortestText(angles.yaw_rad) << '\n';
  }
}

void WriteRelations(const Relations& relations, const std::filesystem::path& path) {
  WriteOutputFile(path, [&](std::ostream& out) { WriteRelations(relations, out); });
}

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
