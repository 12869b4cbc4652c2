// The other side of the ROS 2 bag tests: foxglove's MCAP library and ROS 2 CDR serialisation, which
// share no code with slamsweep. Run with NODE_PATH set to the node_modules of
// scripts/install-bag-tools.sh.
//   node bag_tool.cjs dump BAG.mcap [TOPIC...]      JSON: profile, topics with types and counts, and the
//                                                  decoded messages of the named topics
//   node bag_tool.cjs write-carmen LOG OUT.mcap [--compression none|zstd|lz4|NAME] [--no-chunks] [--no-summary]
//                                                  an MCAP bag (ros2 profile) of a raw CARMEN log: ODOM ->
//                                                  /odom, FLASER -> /scan, /tf_static base_link -> laser
//                                                  (another NAME labels uncompressed chunks with it)
"use strict";

const fs = require("node:fs");
const zlib = require("node:zlib");
const { McapIndexedReader, McapStreamReader, McapWriter } = require("@mcap/core");
const { loadDecompressHandlers } = require("@mcap/support");
const { parse } = require("@foxglove/rosmsg");
const { MessageReader, MessageWriter } = require("@foxglove/rosmsg2-serialization");

// --- dump -------------------------------------------------------------------------------------------

function poseOf(pose) {
  return [pose.position.x, pose.position.y, pose.position.z, pose.orientation.x, pose.orientation.y,
    pose.orientation.z, pose.orientation.w];
}

function transformOf(t) {
  return {
    stamp: [t.header.stamp.sec, t.header.stamp.nanosec], frame_id: t.header.frame_id, child_frame_id: t.child_frame_id,
    pose: [t.transform.translation.x, t.transform.translation.y, t.transform.translation.z, t.transform.rotation.x,
      t.transform.rotation.y, t.transform.rotation.z, t.transform.rotation.w],
  };
}

/** The fields the tests compare, by type. */
function summarise(type, message) {
  const stamp = message.header ? [message.header.stamp.sec, message.header.stamp.nanosec] : undefined;
  const frame_id = message.header ? message.header.frame_id : undefined;
  switch (type) {
    case "sensor_msgs/msg/LaserScan":
      return {
        stamp, frame_id, angle_min: message.angle_min, angle_max: message.angle_max,
        angle_increment: message.angle_increment, range_min: message.range_min, range_max: message.range_max,
        ranges: Array.from(message.ranges),
      };
    case "nav_msgs/msg/Odometry":
      return { stamp, frame_id, child_frame_id: message.child_frame_id, pose: poseOf(message.pose.pose) };
    case "geometry_msgs/msg/PoseWithCovarianceStamped":
      return { stamp, frame_id, pose: poseOf(message.pose.pose) };
    case "geometry_msgs/msg/PoseStamped":
      return { stamp, frame_id, pose: poseOf(message.pose) };
    case "tf2_msgs/msg/TFMessage":
      return { transforms: message.transforms.map(transformOf) };
    default:
      return {};
  }
}

async function readAll(bytes, visit) {
  const decompressHandlers = await loadDecompressHandlers();
  let reader;
  try {
    const readable = {
      size: async () => BigInt(bytes.length),
      read: async (offset, length) => bytes.subarray(Number(offset), Number(offset + length)),
    };
    reader = await McapIndexedReader.Initialize({ readable, decompressHandlers });
  } catch {
    reader = undefined;
  }
  if (reader && reader.chunkIndexes.length > 0) {
    for await (const message of reader.readMessages()) {
      const channel = reader.channelsById.get(message.channelId);
      visit(channel, reader.schemasById.get(channel.schemaId), message);
    }
    return { profile: reader.header.profile, indexed: true };
  }
  // No usable index: read the records in order, as a recorder writes them.
  const stream = new McapStreamReader({ decompressHandlers });
  stream.append(bytes);
  const channels = new Map();
  const schemas = new Map();
  let profile = "";
  for (let record; (record = stream.nextRecord()) !== undefined;) {
    if (record.type === "Header") profile = record.profile;
    if (record.type === "Schema") schemas.set(record.id, record);
    if (record.type === "Channel") channels.set(record.id, record);
    if (record.type === "Message") {
      const channel = channels.get(record.channelId);
      visit(channel, schemas.get(channel.schemaId), record);
    }
  }
  if (!stream.done()) throw new Error("the MCAP stream ended early");
  return { profile, indexed: false };
}

async function dump(path, wanted) {
  const bytes = new Uint8Array(fs.readFileSync(path));
  const readers = new Map();
  const topics = new Map();
  const messages = {};
  for (const topic of wanted) messages[topic] = [];
  const header = await readAll(bytes, (channel, schema, message) => {
    if (!topics.has(channel.topic)) topics.set(channel.topic, { topic: channel.topic, type: schema.name, count: 0 });
    topics.get(channel.topic).count += 1;
    if (!wanted.includes(channel.topic)) return;
    if (!readers.has(schema.id)) {
      readers.set(schema.id, new MessageReader(parse(new TextDecoder().decode(schema.data), { ros2: true })));
    }
    const decoded = readers.get(schema.id).readMessage(message.data);
    messages[channel.topic].push({ log_time: message.logTime.toString(), ...summarise(schema.name, decoded) });
  });
  const sorted = [...topics.values()].sort((a, b) => (a.topic < b.topic ? -1 : 1));
  process.stdout.write(JSON.stringify({ ...header, topics: sorted, messages }) + "\n");
}

// --- write-carmen -----------------------------------------------------------------------------------

// The ROS 2 definitions, written as rosbag2 embeds them: the type's fields, then each type it uses.
const SEPARATOR = "=".repeat(80) + "\n";
const TYPES = {
  "std_msgs/Header": "builtin_interfaces/Time stamp\nstring frame_id\n",
  "builtin_interfaces/Time": "int32 sec\nuint32 nanosec\n",
  "geometry_msgs/Point": "float64 x\nfloat64 y\nfloat64 z\n",
  "geometry_msgs/Vector3": "float64 x\nfloat64 y\nfloat64 z\n",
  "geometry_msgs/Quaternion": "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n",
  "geometry_msgs/Pose": "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n",
  "geometry_msgs/PoseWithCovariance": "geometry_msgs/Pose pose\nfloat64[36] covariance\n",
  "geometry_msgs/Twist": "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n",
  "geometry_msgs/TwistWithCovariance": "geometry_msgs/Twist twist\nfloat64[36] covariance\n",
  "geometry_msgs/Transform": "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n",
  "geometry_msgs/TransformStamped": "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/Transform transform\n",
};
function definition(fields, uses) {
  return fields + uses.map((type) => `${SEPARATOR}MSG: ${type}\n${TYPES[type]}`).join("");
}
const LASER_SCAN = definition(
  "std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\nfloat32 time_increment\n" +
  "float32 scan_time\nfloat32 range_min\nfloat32 range_max\nfloat32[] ranges\nfloat32[] intensities\n",
  ["std_msgs/Header", "builtin_interfaces/Time"]);
const ODOMETRY = definition(
  "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n" +
  "geometry_msgs/TwistWithCovariance twist\n",
  ["std_msgs/Header", "builtin_interfaces/Time", "geometry_msgs/PoseWithCovariance", "geometry_msgs/Pose",
    "geometry_msgs/Point", "geometry_msgs/Quaternion", "geometry_msgs/TwistWithCovariance", "geometry_msgs/Twist",
    "geometry_msgs/Vector3"]);
const TF_MESSAGE = definition("geometry_msgs/TransformStamped[] transforms\n",
  ["geometry_msgs/TransformStamped", "std_msgs/Header", "builtin_interfaces/Time", "geometry_msgs/Transform",
    "geometry_msgs/Vector3", "geometry_msgs/Quaternion"]);

/** A CARMEN stamp's text as ROS time, exactly: seconds and nanoseconds from its decimal digits. */
function rosTime(text) {
  const [whole, fraction = ""] = text.split(".");
  let nanos = BigInt(whole) * 1000000000n + BigInt((fraction + "000000000").slice(0, 9));
  if (fraction.length > 9 && fraction[9] >= "5") nanos += 1n;
  return { sec: Number(nanos / 1000000000n), nanosec: Number(nanos % 1000000000n), nanos };
}

function yawQuaternion(yaw) {
  return { x: 0, y: 0, z: Math.sin(yaw / 2), w: Math.cos(yaw / 2) };
}

/** FLASER's fan as CARMEN infers it from the beam count (180/360 beams: pi/n apart; else pi/(n-1)). */
function flaserFan(count) {
  const increment = count === 180 || count === 360 ? Math.PI / count : Math.PI / (count - 1);
  return { angle_min: -Math.PI / 2, angle_increment: increment };
}

function readCarmen(path) {
  let text = fs.readFileSync(path);
  if (text[0] === 0x1f && text[1] === 0x8b) text = zlib.gunzipSync(text);
  const records = [];
  let maxRange = 80;
  for (const line of text.toString("utf8").split("\n")) {
    const f = line.trim().split(/\s+/);
    if (f[0] === "PARAM" && f[1] === "robot_front_laser_max") maxRange = Number(f[2]);
    if (f[0] === "ODOM") {
      // ODOM x y theta tv rv accel ipc_timestamp host logger_timestamp
      records.push({ kind: "odom", time: rosTime(f[7]), x: Number(f[1]), y: Number(f[2]), theta: Number(f[3]) });
    } else if (f[0] === "FLASER") {
      const n = Number(f[1]);
      // FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp host logger_timestamp
      records.push({ kind: "scan", time: rosTime(f[2 + n + 6]), ranges: f.slice(2, 2 + n).map(Number) });
    }
  }
  return { records, maxRange };
}

async function writeCarmen(logPath, outPath, options) {
  const { records: all, maxRange } = readCarmen(logPath);
  // One split file of a bag split in options.parts: the records of its slice; /tf_static in the first alone.
  const from = Math.floor((options.part * all.length) / options.parts);
  const records = all.slice(from, Math.floor(((options.part + 1) * all.length) / options.parts));
  let compressChunk;
  if (options.compression === "zstd") {
    const zstd = require("@foxglove/wasm-zstd");
    await zstd.isLoaded;
    compressChunk = (data) => ({ compression: "zstd", compressedData: new Uint8Array(zstd.compress(data)) });
  } else if (options.compression === "lz4") {
    const lz4 = require("lz4js");
    compressChunk = (data) => ({ compression: "lz4", compressedData: new Uint8Array(lz4.compress(data)) });
  } else if (options.compression !== "none") {
    // An unknown compression, for the error test: the data stays as it is under another name.
    compressChunk = (data) => ({ compression: options.compression, compressedData: data });
  }
  const chunks = [];
  const writable = { position: () => BigInt(chunks.reduce((n, c) => n + c.length, 0)), write: async (d) => { chunks.push(Buffer.from(d)); } };
  const summary = !options.noSummary;
  const writer = new McapWriter({
    writable, useChunks: !options.noChunks, compressChunk, chunkSize: 64 * 1024,
    useStatistics: summary, useSummaryOffsets: summary, useChunkIndex: summary && !options.noChunks,
    useMessageIndex: summary && !options.noChunks, useAttachmentIndex: summary, useMetadataIndex: summary,
    repeatSchemas: summary, repeatChannels: summary,
  });
  await writer.start({ profile: "ros2", library: "slamsweep tests: @mcap/core" });
  const channel = async (topic, name, text) => {
    const schemaId = await writer.registerSchema({ name, encoding: "ros2msg", data: new TextEncoder().encode(text) });
    const id = await writer.registerChannel({ topic, schemaId, messageEncoding: "cdr", metadata: new Map() });
    return { id, serialise: new MessageWriter(parse(text, { ros2: true })), sequence: 0 };
  };
  const scan = await channel("/scan", "sensor_msgs/msg/LaserScan", LASER_SCAN);
  const odom = await channel("/odom", "nav_msgs/msg/Odometry", ODOMETRY);
  const tfStatic = await channel("/tf_static", "tf2_msgs/msg/TFMessage", TF_MESSAGE);
  const add = async (ch, time, message) => {
    ch.sequence += 1;
    await writer.addMessage({ channelId: ch.id, sequence: ch.sequence, logTime: time.nanos, publishTime: time.nanos,
      data: ch.serialise.writeMessage(message) });
  };
  const zero36 = new Array(36).fill(0);
  const first = all[0].time;
  if (options.part === 0) await add(tfStatic, first, {
    transforms: [{
      header: { stamp: { sec: first.sec, nanosec: first.nanosec }, frame_id: "base_link" }, child_frame_id: "laser",
      transform: { translation: { x: 0, y: 0, z: 0 }, rotation: { x: 0, y: 0, z: 0, w: 1 } },
    }],
  });
  for (const record of records) {
    const header = { stamp: { sec: record.time.sec, nanosec: record.time.nanosec } };
    if (record.kind === "odom") {
      await add(odom, record.time, {
        header: { ...header, frame_id: "odom" }, child_frame_id: "base_link",
        pose: { pose: { position: { x: record.x, y: record.y, z: 0 }, orientation: yawQuaternion(record.theta) },
          covariance: zero36 },
        twist: { twist: { linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } }, covariance: zero36 },
      });
    } else {
      const fan = flaserFan(record.ranges.length);
      await add(scan, record.time, {
        header: { ...header, frame_id: "laser" }, angle_min: fan.angle_min,
        angle_max: fan.angle_min + fan.angle_increment * (record.ranges.length - 1),
        angle_increment: fan.angle_increment, time_increment: 0, scan_time: 0, range_min: 0, range_max: maxRange,
        ranges: new Float32Array(record.ranges), intensities: new Float32Array(0),
      });
    }
  }
  await writer.end();
  fs.writeFileSync(outPath, Buffer.concat(chunks));
}

async function main() {
  const [command, ...args] = process.argv.slice(2);
  if (command === "dump") return dump(args[0], args.slice(1));
  if (command === "write-carmen") {
    const options = { compression: "none", noChunks: false, noSummary: false, part: 0, parts: 1 };
    for (let i = 2; i < args.length; ++i) {
      if (args[i] === "--compression") options.compression = args[++i];
      else if (args[i] === "--no-chunks") options.noChunks = true;
      else if (args[i] === "--no-summary") options.noSummary = true;
      else if (args[i] === "--part") [options.part, options.parts] = args[++i].split("/").map(Number);
      else throw new Error(`unknown option ${args[i]}`);
    }
    return writeCarmen(args[0], args[1], options);
  }
  throw new Error("usage: bag_tool.cjs dump BAG [TOPIC...] | write-carmen LOG OUT [--compression C] [--no-chunks] [--no-summary] [--part K/N]");
}

main().catch((error) => {
  process.stderr.write(`bag_tool: ${error.stack || error}\n`);
  process.exit(1);
});
