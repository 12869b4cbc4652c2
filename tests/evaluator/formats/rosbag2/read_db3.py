"""Reads a rosbag2 sqlite3 bag folder the way a ROS 2 tool would, with Python's sqlite3, re and struct
(no slamsweep code), and writes what the tests compare as JSON.
Usage: /usr/bin/python3 read_db3.py FOLDER OUT.json
Written: the metadata.yaml version and storage, the database's schema version and ros_distro, its tables,
topics (name, type, serialization format, count), and the first /scan and last /odom messages decoded from
their little-endian CDR."""
import json
import os
import re
import sqlite3
import struct
import sys


class Cdr:
    def __init__(self, data):
        if data[:4] != b"\x00\x01\x00\x00":
            raise ValueError(f"expected little-endian plain CDR, got {data[:4].hex()}")
        self.data, self.offset = data[4:], 0

    def get(self, kind):
        size = struct.calcsize(kind)
        self.offset += -self.offset % size
        (value,) = struct.unpack_from("<" + kind, self.data, self.offset)
        self.offset += size
        return value

    def string(self):
        length = self.get("I")
        text = self.data[self.offset:self.offset + length - 1].decode()
        self.offset += length
        return text


def main(folder, output):
    with open(os.path.join(folder, "metadata.yaml")) as text:
        metadata = text.read()
    first_file = re.search(r'relative_file_paths:\n\s+- "?([^"\n]+)"?', metadata).group(1)
    db = sqlite3.connect(os.path.join(folder, first_file))
    out = {
        "metadata_version": int(re.search(r"^\s+version: (\d+)", metadata, re.M).group(1)),
        "storage": re.search(r"storage_identifier: (\S+)", metadata).group(1),
        "schema": list(db.execute("SELECT schema_version, ros_distro FROM schema").fetchone()),
        "tables": sorted(row[0] for row in db.execute("SELECT name FROM sqlite_master WHERE type='table'")),
        "stored_metadata_version": db.execute("SELECT metadata_version FROM metadata").fetchone()[0],
        "topics": [list(row) for row in db.execute(
            "SELECT name, type, serialization_format, (SELECT COUNT(*) FROM messages WHERE topic_id = topics.id) "
            "FROM topics ORDER BY name")],
    }
    scan = Cdr(db.execute("SELECT data FROM messages JOIN topics ON topics.id = topic_id WHERE name = '/scan' "
                          "ORDER BY timestamp LIMIT 1").fetchone()[0])
    out["first_scan"] = {"sec": scan.get("i"), "nanosec": scan.get("I"), "frame_id": scan.string(),
                         "fields": [scan.get("f") for _ in range(7)]}
    out["first_scan"]["ranges"] = [scan.get("f") for _ in range(scan.get("I"))]
    odom = Cdr(db.execute("SELECT data FROM messages JOIN topics ON topics.id = topic_id WHERE name = '/odom' "
                          "ORDER BY timestamp DESC LIMIT 1").fetchone()[0])
    out["last_odom"] = {"sec": odom.get("i"), "nanosec": odom.get("I"), "frame_id": odom.string(),
                        "child_frame_id": odom.string(), "pose": [odom.get("d") for _ in range(7)]}
    with open(output, "w") as target:
        json.dump(out, target)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
