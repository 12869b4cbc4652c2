"""Writes rosbag2 sqlite3 bags from a raw CARMEN log for the ROS 2 reader tests, with Python's sqlite3, struct
and zstandard: a writer that shares no code with slamsweep's. Usage:
    /usr/bin/python3 make_ros2_bags.py LOG OUT_DIR
LOG is a raw CARMEN log as slamsweep writes it (ODOM records, FLASER records, PARAM robot_front_laser_max).
Every bag holds /scan (sensor_msgs/msg/LaserScan from FLASER), /odom (nav_msgs/msg/Odometry from ODOM) and
/tf_static (base_link -> laser); message timestamps are the CARMEN stamps. Bags written:
    schema1 .. schema4   one .db3 of sqlite schema version 1 to 4, metadata.yaml versions 4, 4, 5 and 9
    split                two .db3 files (the first and second half of the messages; other topic ids)
    file_zstd            rosbag2's per-file zstd compression (split_0.db3.zstd, compression_mode FILE)
    message_zstd         rosbag2's per-message zstd compression (compression_mode MESSAGE)
    big_endian.db3       a lone .db3 whose messages are big-endian CDR
and the bad ones the error tests read:
    no_metadata          a folder with a .db3 and no metadata.yaml
    missing_split        metadata.yaml names two files, the second is missing
    wrong_type           /scan recorded as nav_msgs/msg/Odometry
    unknown_compression  metadata.yaml compression_format lz77
    unknown_encoding.db3 /scan serialised as json
    xcdr2.db3            /scan with an XCDR2 encapsulation header (00 07)
    short_message.db3    a /scan message cut after 20 bytes
Or, for MCAP split files another writer made from LOG (FOLDER/NAME_0.mcap .. NAME_<PARTS-1>.mcap, each a
contiguous slice of LOG's records, /tf_static in the first), the rest of a bag folder around them:
    /usr/bin/python3 make_ros2_bags.py --mcap-folder LOG FOLDER PARTS [FILE]
metadata.yaml (version 9, storage mcap) and, with FILE, rosbag2's per-file zstd (NAME_K.mcap.zstd).
"""
import math
import os
import shutil
import sqlite3
import struct
import sys
from decimal import Decimal, ROUND_HALF_UP

import zstandard

QOS = ("- history: 3\n  depth: 0\n  reliability: 1\n  durability: 2\n  deadline:\n    sec: 9223372036\n"
       "    nsec: 854775807\n  lifespan:\n    sec: 9223372036\n    nsec: 854775807\n  liveliness: 1\n"
       "  liveliness_lease_duration:\n    sec: 9223372036\n    nsec: 854775807\n  avoid_ros_namespace_conventions: false")
TYPES = {"/scan": "sensor_msgs/msg/LaserScan", "/odom": "nav_msgs/msg/Odometry", "/tf_static": "tf2_msgs/msg/TFMessage"}


class Cdr:
    """Plain CDR: a 4-byte encapsulation header, then each value aligned to its size from the byte after it."""

    def __init__(self, big_endian=False):
        self.order = ">" if big_endian else "<"
        self.data = bytearray(b"\x00\x00\x00\x00" if big_endian else b"\x00\x01\x00\x00")

    def put(self, kind, value):
        size = struct.calcsize(kind)
        self.data += b"\x00" * (-(len(self.data) - 4) % size)
        self.data += struct.pack(self.order + kind, value)

    def string(self, text):
        encoded = text.encode() + b"\x00"
        self.put("I", len(encoded))
        self.data += encoded

    def header(self, ns, frame):
        self.put("i", ns // 1000000000)
        self.put("I", ns % 1000000000)
        self.string(frame)


def scan_message(ns, ranges, max_range, big_endian=False):
    cdr = Cdr(big_endian)
    cdr.header(ns, "laser")
    count = len(ranges)
    increment = math.pi / count if count in (180, 360) else math.pi / (count - 1)
    for value in (-math.pi / 2, -math.pi / 2 + increment * (count - 1), increment, 0.0, 0.0, 0.0, max_range):
        cdr.put("f", value)
    cdr.put("I", count)
    for value in ranges:
        cdr.put("f", value)
    cdr.put("I", 0)
    return bytes(cdr.data)


def odometry_message(ns, x, y, theta, big_endian=False):
    cdr = Cdr(big_endian)
    cdr.header(ns, "odom")
    cdr.string("base_link")
    for value in (x, y, 0.0, 0.0, 0.0, math.sin(theta / 2), math.cos(theta / 2)) + (0.0,) * 36 + (0.0,) * 42:
        cdr.put("d", value)
    return bytes(cdr.data)


def tf_static_message(ns, big_endian=False):
    cdr = Cdr(big_endian)
    cdr.put("I", 1)
    cdr.header(ns, "base_link")
    cdr.string("laser")
    for value in (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0):
        cdr.put("d", value)
    return bytes(cdr.data)


def stamp_ns(text):
    return int((Decimal(text) * 1000000000).to_integral_value(rounding=ROUND_HALF_UP))


def read_carmen(path):
    """(topic, ns, fields) in log order, and the laser's max range."""
    records, max_range = [], 80.0
    with open(path) as log:
        for line in log:
            f = line.split()
            if not f:
                continue
            if f[0] == "PARAM" and f[1] == "robot_front_laser_max":
                max_range = float(f[2])
            elif f[0] == "ODOM":
                records.append(("/odom", stamp_ns(f[7]), (float(f[1]), float(f[2]), float(f[3]))))
            elif f[0] == "FLASER":
                n = int(f[1])
                records.append(("/scan", stamp_ns(f[2 + n + 6]), [float(v) for v in f[2:2 + n]]))
    return records, max_range


def messages(records, max_range, big_endian=False):
    """(topic, ns, cdr bytes), /tf_static first."""
    out = [("/tf_static", records[0][1], tf_static_message(records[0][1], big_endian))]
    for topic, ns, fields in records:
        if topic == "/odom":
            out.append((topic, ns, odometry_message(ns, *fields, big_endian=big_endian)))
        else:
            out.append((topic, ns, scan_message(ns, fields, max_range, big_endian)))
    return out


def write_db3(path, schema, rows, types=None, formats=None, first_id=1):
    """An sqlite3 storage file of `schema` version (1 to 4)."""
    types = dict(TYPES, **(types or {}))
    formats = formats or {}
    db = sqlite3.connect(path)
    topic_columns = "id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, serialization_format TEXT NOT NULL"
    if schema >= 2:
        db.execute("CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL)")
        db.execute("INSERT INTO schema VALUES (?, ?)", (schema, {2: "galactic", 3: "humble", 4: "jazzy"}[schema]))
        topic_columns += ", offered_qos_profiles TEXT NOT NULL"
    if schema >= 3:
        db.execute("CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL, "
                   "metadata TEXT NOT NULL)")
    if schema >= 4:
        topic_columns += ", type_description_hash TEXT NOT NULL"
        db.execute("CREATE TABLE message_definitions(id INTEGER PRIMARY KEY, topic_type TEXT NOT NULL, "
                   "encoding TEXT NOT NULL, encoded_message_definition TEXT NOT NULL, "
                   "type_description_hash TEXT NOT NULL)")
    db.execute(f"CREATE TABLE topics({topic_columns})")
    db.execute("CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, "
               "timestamp INTEGER NOT NULL, data BLOB NOT NULL)")
    ids = {}
    for offset, topic in enumerate(sorted({row[0] for row in rows}, reverse=first_id > 1)):
        ids[topic] = first_id + offset
        values = [ids[topic], topic, types[topic], formats.get(topic, "cdr")]
        if schema >= 2:
            values.append(QOS)
        if schema >= 4:
            values.append("")
        db.execute(f"INSERT INTO topics VALUES ({', '.join('?' * len(values))})", values)
    db.executemany("INSERT INTO messages (topic_id, timestamp, data) VALUES (?, ?, ?)",
                   [(ids[topic], ns, data) for topic, ns, data in rows])
    db.commit()
    db.close()


def quoted(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def write_metadata(folder, version, files, rows, storage="sqlite3", compression=("", "")):
    """metadata.yaml in the layout of `version`; `files` lists (name, rows in it)."""
    start, end = min(r[1] for r in rows), max(r[1] for r in rows)
    lines = ["rosbag2_bagfile_information:", f"  version: {version}", f"  storage_identifier: {storage}",
             f"  duration:\n    nanoseconds: {end - start}", f"  starting_time:\n    nanoseconds_since_epoch: {start}",
             f"  message_count: {len(rows)}", "  topics_with_message_count:"]
    for topic in sorted(TYPES):
        lines += ["    - topic_metadata:", f"        name: {topic}", f"        type: {TYPES[topic]}",
                  "        serialization_format: cdr"]
        if version >= 9:
            lines += ["        offered_qos_profiles:", "          - history: keep_last", "            depth: 10"]
        elif version >= 4:
            lines.append(f"        offered_qos_profiles: {quoted(QOS)}")
        if version >= 7:
            lines.append("        type_description_hash: \"\"")
        lines.append(f"      message_count: {sum(1 for r in rows if r[0] == topic)}")
    lines += [f"  compression_format: {quoted(compression[0])}", f"  compression_mode: {quoted(compression[1])}",
              "  relative_file_paths:"] + [f"    - {name}" for name, _ in files]
    if version >= 5:
        lines.append("  files:")
        for name, part in files:
            s, e = min(r[1] for r in part), max(r[1] for r in part)
            lines += [f"    - path: {name}", f"      starting_time:\n        nanoseconds_since_epoch: {s}",
                      f"      duration:\n        nanoseconds: {e - s}", f"      message_count: {len(part)}"]
    if version >= 6:
        lines.append("  custom_data: {}")
    if version >= 8:
        lines.append("  ros_distro: jazzy")
    with open(os.path.join(folder, "metadata.yaml"), "w") as out:
        out.write("\n".join(lines) + "\n")


def bag_folder(out, name):
    folder = os.path.join(out, name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    return folder


def main(log, out):
    records, max_range = read_carmen(log)
    rows = messages(records, max_range)
    for schema, version in ((1, 4), (2, 4), (3, 5), (4, 9)):
        folder = bag_folder(out, f"schema{schema}")
        write_db3(os.path.join(folder, f"schema{schema}_0.db3"), schema, rows)
        write_metadata(folder, version, [(f"schema{schema}_0.db3", rows)], rows)

    folder = bag_folder(out, "split")
    half = len(rows) // 2
    write_db3(os.path.join(folder, "split_0.db3"), 3, rows[:half])
    write_db3(os.path.join(folder, "split_1.db3"), 3, rows[half:], first_id=7)
    write_metadata(folder, 5, [("split_0.db3", rows[:half]), ("split_1.db3", rows[half:])], rows)

    folder = bag_folder(out, "file_zstd")
    plain = os.path.join(folder, "file_zstd_0.db3")
    write_db3(plain, 3, rows)
    with open(plain, "rb") as source, open(plain + ".zstd", "wb") as target:
        target.write(zstandard.ZstdCompressor().compress(source.read()))
    os.remove(plain)
    write_metadata(folder, 5, [("file_zstd_0.db3.zstd", rows)], rows, compression=("zstd", "FILE"))

    folder = bag_folder(out, "message_zstd")
    compressor = zstandard.ZstdCompressor()
    write_db3(os.path.join(folder, "message_zstd_0.db3"), 3, [(t, ns, compressor.compress(d)) for t, ns, d in rows])
    write_metadata(folder, 5, [("message_zstd_0.db3", rows)], rows, compression=("zstd", "MESSAGE"))

    write_db3(os.path.join(out, "big_endian.db3"), 3, messages(records, max_range, big_endian=True))

    # The bad ones.
    folder = bag_folder(out, "no_metadata")
    write_db3(os.path.join(folder, "no_metadata_0.db3"), 3, rows)
    folder = bag_folder(out, "missing_split")
    write_db3(os.path.join(folder, "missing_split_0.db3"), 3, rows[:half])
    write_metadata(folder, 5, [("missing_split_0.db3", rows[:half]), ("missing_split_1.db3", rows[half:])], rows)
    folder = bag_folder(out, "wrong_type")
    write_db3(os.path.join(folder, "wrong_type_0.db3"), 3, rows, types={"/scan": "nav_msgs/msg/Odometry"})
    write_metadata(folder, 5, [("wrong_type_0.db3", rows)], rows)
    folder = bag_folder(out, "unknown_compression")
    write_db3(os.path.join(folder, "unknown_compression_0.db3"), 3, rows)
    write_metadata(folder, 5, [("unknown_compression_0.db3", rows)], rows, compression=("lz77", "FILE"))
    write_db3(os.path.join(out, "unknown_encoding.db3"), 3, rows, formats={"/scan": "json"})
    write_db3(os.path.join(out, "xcdr2.db3"), 3,
              [(t, ns, b"\x00\x07" + d[2:] if t == "/scan" else d) for t, ns, d in rows])
    scans = [i for i, row in enumerate(rows) if row[0] == "/scan"]
    write_db3(os.path.join(out, "short_message.db3"), 3,
              [(t, ns, d[:20] if i == scans[1] else d) for i, (t, ns, d) in enumerate(rows)])


def mcap_folder(log, folder, parts, mode):
    records, max_range = read_carmen(log)
    name = os.path.basename(os.path.normpath(folder))
    files = []
    for part in range(parts):
        first, last = part * len(records) // parts, (part + 1) * len(records) // parts
        rows = messages(records, max_range)
        rows = (rows[:1] if part == 0 else []) + rows[1 + first:1 + last]
        path = os.path.join(folder, f"{name}_{part}.mcap")
        if mode == "FILE":
            with open(path, "rb") as source, open(path + ".zstd", "wb") as target:
                target.write(zstandard.ZstdCompressor().compress(source.read()))
            os.remove(path)
            path += ".zstd"
        files.append((os.path.basename(path), rows))
    write_metadata(folder, 9, files, [row for _, rows in files for row in rows], storage="mcap",
                   compression=("zstd", mode) if mode else ("", ""))


if __name__ == "__main__":
    if sys.argv[1] == "--mcap-folder":
        mcap_folder(sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5] if len(sys.argv) > 5 else "")
    else:
        main(sys.argv[1], sys.argv[2])
