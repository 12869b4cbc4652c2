#include "evaluator/formats/trajectory/relations_format.h"

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/euler_angles.h"
#include "evaluator/formats/trajectory/output_file.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {
namespace {

constexpr std::string_view kLayout = "t1 t2 x y z roll pitch yaw";

}  // namespace

Relations ParseRelations(std::string_view content, const std::filesystem::path& source) {
  Relations relations;
  ForEachRecord(source, content, [&](const TextRecord& record) {
    if (record.size() != 8) {
      record.Fail("expected 8 fields (" + std::string(kLayout) + "), got " + std::to_string(record.size()));
    }
    Relation relation;
    relation.t1_s = record.Number(0, "t1");
    relation.t2_s = record.Number(1, "t2");
    relation.delta.position = {record.Number(2, "x"), record.Number(3, "y"), record.Number(4, "z")};
    relation.delta.orientation = QuaternionFromRollPitchYaw({.roll_rad = record.Number(5, "roll"),
                                                             .pitch_rad = record.Number(6, "pitch"),
                                                             .yaw_rad = record.Number(7, "yaw")});
    relations.push_back(relation);
  });
  if (relations.empty()) {
    throw InputError(Located(source, 0, "no relations found (expected lines '" + std::string(kLayout) + "')"));
  }
  return relations;
}

Relations ReadRelations(const std::filesystem::path& path) { return ParseRelations(ReadTextFile(path), path); }

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
