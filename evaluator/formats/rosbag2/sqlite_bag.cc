#include "evaluator/formats/rosbag2/sqlite_bag.h"

#include <fmt/format.h>
#include <sqlite3.h>

#include <algorithm>
#include <cstdint>
#include <system_error>
#include <utility>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// One prepared statement, finalised when destroyed.
struct SqliteStatement {
  sqlite3_stmt* statement = nullptr;
  ~SqliteStatement() { sqlite3_finalize(statement); }
};

namespace {

using Statement = SqliteStatement;

[[noreturn]] void Fail(const std::string& name, sqlite3* db, const std::string& doing) {
  throw InputError(fmt::format("{}: {}: {}", name, doing, db != nullptr ? sqlite3_errmsg(db) : "out of memory"));
}

std::unique_ptr<Statement> Prepare(sqlite3* db, const std::string& name, const std::string& sql) {
  auto statement = std::make_unique<Statement>();
  if (sqlite3_prepare_v2(db, sql.c_str(), -1, &statement->statement, nullptr) != SQLITE_OK) {
    Fail(name, db, "not a readable rosbag2 sqlite3 file (" + sql + ")");
  }
  return statement;
}

/// A file: URI for `path`, with the characters a URI gives meaning to escaped.
std::string FileUri(const std::filesystem::path& path) {
  std::string uri = "file:";
  for (const char c : std::filesystem::absolute(path).string()) {
    if (c == '%' || c == '?' || c == '#') {
      uri += fmt::format("%{:02X}", static_cast<unsigned char>(c));
    } else {
      uri += c;
    }
  }
  return uri + "?immutable=1";
}

std::string Text(sqlite3_stmt* statement, int column) {
  const unsigned char* text = sqlite3_column_text(statement, column);
  return text != nullptr ? reinterpret_cast<const char*>(text) : "";
}

std::set<std::string> ColumnsOf(sqlite3* db, const std::string& name, const std::string& table) {
  std::set<std::string> columns;
  const auto statement = Prepare(db, name, "PRAGMA table_info(" + table + ")");
  while (sqlite3_step(statement->statement) == SQLITE_ROW) columns.insert(Text(statement->statement, 1));
  return columns;
}

void RequireColumns(sqlite3* db, const std::string& name, const std::string& table,
                    std::initializer_list<const char*> wanted) {
  const std::set<std::string> columns = ColumnsOf(db, name, table);
  if (columns.empty()) {
    throw InputError(fmt::format("{}: not a rosbag2 sqlite3 file: it has no table '{}'", name, table));
  }
  for (const char* column : wanted) {
    if (columns.count(column) == 0) {
      throw InputError(
          fmt::format("{}: not a rosbag2 sqlite3 file: table '{}' has no column '{}'", name, table, column));
    }
  }
}

/// A bag is untrusted input: its schema is SQL that SQLite would run. Views and triggers are off (a "messages"
/// view of a recursive query would never end, or make blobs of any size), functions in the schema may not reach
/// beyond it, and no value may be longer than the file: a blob stored in the file cannot be, so a longer one was
/// computed (zeroblob in a generated column) and would cost memory the file does not hold.
void DistrustSchema(sqlite3* db, const std::string& name, std::uintmax_t file_bytes) {
  constexpr int kMinimumLength = 1 << 20;
  for (const auto& [option, value] : {std::pair{SQLITE_DBCONFIG_ENABLE_VIEW, 0},
                                      {SQLITE_DBCONFIG_ENABLE_TRIGGER, 0},
                                      {SQLITE_DBCONFIG_TRUSTED_SCHEMA, 0},
                                      {SQLITE_DBCONFIG_DEFENSIVE, 1}}) {
    if (sqlite3_db_config(db, option, value, static_cast<int*>(nullptr)) != SQLITE_OK)
      Fail(name, db, "cannot configure SQLite");
  }
  const auto limit = static_cast<int>(std::clamp<std::uintmax_t>(file_bytes, kMinimumLength, INT32_MAX));
  sqlite3_limit(db, SQLITE_LIMIT_LENGTH, limit);
}

}  // namespace

SqliteBag::SqliteBag(sqlite3* db, std::string name, std::unique_ptr<std::vector<std::uint8_t>> bytes)
    : db_(db), name_(std::move(name)), bytes_(std::move(bytes)) {}

SqliteBag::SqliteBag(SqliteBag&& other) noexcept
    : db_(std::exchange(other.db_, nullptr)),
      name_(std::move(other.name_)),
      bytes_(std::move(other.bytes_)),
      schema_version_(other.schema_version_),
      topics_(std::move(other.topics_)),
      start_ns_(other.start_ns_),
      end_ns_(other.end_ns_) {}

SqliteBag& SqliteBag::operator=(SqliteBag&& other) noexcept {
  if (this != &other) {
    sqlite3_close(db_);
    db_ = std::exchange(other.db_, nullptr);
    name_ = std::move(other.name_);
    bytes_ = std::move(other.bytes_);
    schema_version_ = other.schema_version_;
    topics_ = std::move(other.topics_);
    start_ns_ = other.start_ns_;
    end_ns_ = other.end_ns_;
  }
  return *this;
}

SqliteBag::~SqliteBag() { sqlite3_close(db_); }

SqliteBag SqliteBag::Open(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw InputError(Located(path, 0, "no such sqlite3 bag file"));
  sqlite3* db = nullptr;
  const int opened = sqlite3_open_v2(FileUri(path).c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr);
  SqliteBag bag(db, path.string(), nullptr);
  if (opened != SQLITE_OK) Fail(bag.name_, db, "cannot open as an SQLite database");
  DistrustSchema(db, bag.name_, std::filesystem::file_size(path, error));
  bag.Load();
  return bag;
}

SqliteBag SqliteBag::FromBytes(std::vector<std::uint8_t> bytes, std::string name) {
  sqlite3* db = nullptr;
  const int opened = sqlite3_open_v2(":memory:", &db, SQLITE_OPEN_READWRITE, nullptr);
  auto owned = std::make_unique<std::vector<std::uint8_t>>(std::move(bytes));
  SqliteBag bag(db, std::move(name), std::move(owned));
  if (opened != SQLITE_OK) Fail(bag.name_, db, "cannot open an in-memory SQLite database");
  DistrustSchema(db, bag.name_, bag.bytes_->size());
  const auto size = static_cast<sqlite3_int64>(bag.bytes_->size());
  if (sqlite3_deserialize(db, "main", bag.bytes_->data(), size, size, SQLITE_DESERIALIZE_READONLY) != SQLITE_OK) {
    Fail(bag.name_, db, "cannot read as an SQLite database");
  }
  bag.Load();
  return bag;
}

void SqliteBag::Load() {
  RequireColumns(db_, name_, "topics", {"id", "name", "type", "serialization_format"});
  RequireColumns(db_, name_, "messages", {"id", "topic_id", "timestamp", "data"});
  if (ColumnsOf(db_, name_, "schema").count("schema_version") > 0) {
    const auto version = Prepare(db_, name_, "SELECT MAX(schema_version) FROM schema");
    if (sqlite3_step(version->statement) == SQLITE_ROW) schema_version_ = sqlite3_column_int(version->statement, 0);
  }
  const auto topics = Prepare(db_, name_, "SELECT id, name, type, serialization_format FROM topics ORDER BY id");
  int step = SQLITE_ROW;
  while ((step = sqlite3_step(topics->statement)) == SQLITE_ROW) {
    topics_.push_back(SqliteTopic{sqlite3_column_int64(topics->statement, 0), Text(topics->statement, 1),
                                  Text(topics->statement, 2), Text(topics->statement, 3), 0});
  }
  if (step != SQLITE_DONE) Fail(name_, db_, "cannot read table topics");
  const auto counts =
      Prepare(db_, name_, "SELECT topic_id, COUNT(*), MIN(timestamp), MAX(timestamp) FROM messages GROUP BY topic_id");
  bool first = true;
  while ((step = sqlite3_step(counts->statement)) == SQLITE_ROW) {
    const std::int64_t topic_id = sqlite3_column_int64(counts->statement, 0);
    const auto topic =
        std::find_if(topics_.begin(), topics_.end(), [&](const SqliteTopic& t) { return t.id == topic_id; });
    if (topic == topics_.end()) {
      throw InputError(fmt::format("{}: messages name topic id {}, which table topics lacks", name_, topic_id));
    }
    topic->message_count = static_cast<std::uint64_t>(sqlite3_column_int64(counts->statement, 1));
    const std::int64_t start = sqlite3_column_int64(counts->statement, 2);
    const std::int64_t end = sqlite3_column_int64(counts->statement, 3);
    start_ns_ = first ? start : std::min(start_ns_, start);
    end_ns_ = first ? end : std::max(end_ns_, end);
    first = false;
  }
  if (step != SQLITE_DONE) Fail(name_, db_, "cannot read table messages");
}

void SqliteBag::ReadMessages(
    const std::set<std::int64_t>& topic_ids,
    const std::function<void(std::int64_t, std::int64_t, std::span<const std::uint8_t>)>& visit) const {
  if (topic_ids.empty()) return;
  std::string ids;
  for (const std::int64_t id : topic_ids) {
    if (!ids.empty()) ids += ',';
    ids += std::to_string(id);
  }
  const auto messages =
      Prepare(db_, name_,
              "SELECT topic_id, timestamp, data FROM messages WHERE topic_id IN (" + ids + ") ORDER BY timestamp, id");
  int step = SQLITE_ROW;
  while ((step = sqlite3_step(messages->statement)) == SQLITE_ROW) {
    const auto* data = static_cast<const std::uint8_t*>(sqlite3_column_blob(messages->statement, 2));
    const auto size = static_cast<std::size_t>(sqlite3_column_bytes(messages->statement, 2));
    visit(sqlite3_column_int64(messages->statement, 0), sqlite3_column_int64(messages->statement, 1),
          std::span<const std::uint8_t>(data, size));
  }
  if (step != SQLITE_DONE) Fail(name_, db_, "cannot read table messages");
}

SqliteBagWriter::SqliteBagWriter(const std::filesystem::path& path, const std::string& ros_distro) : path_(path) {
  std::error_code error;
  if (std::filesystem::exists(path, error)) throw InputError(Located(path, 0, "exists already; not overwritten"));
  if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK) {
    Fail(path.string(), db_, "cannot create");
  }
  Execute("PRAGMA journal_mode = MEMORY");
  Execute("PRAGMA synchronous = OFF");
  Execute("BEGIN TRANSACTION");
  Execute("CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL)");
  Execute("CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL, metadata TEXT NOT NULL)");
  Execute(
      "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, serialization_format TEXT "
      "NOT NULL, offered_qos_profiles TEXT NOT NULL)");
  Execute(
      "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp INTEGER NOT NULL, data "
      "BLOB NOT NULL)");
  Execute("CREATE INDEX timestamp_idx ON messages (timestamp ASC)");
  const auto schema = Prepare(db_, path_.string(), "INSERT INTO schema (schema_version, ros_distro) VALUES (3, ?)");
  sqlite3_bind_text(schema->statement, 1, ros_distro.c_str(), -1, SQLITE_TRANSIENT);
  if (sqlite3_step(schema->statement) != SQLITE_DONE) Fail(path_.string(), db_, "cannot write table schema");
  insert_message_ = Prepare(db_, path_.string(), "INSERT INTO messages (topic_id, timestamp, data) VALUES (?, ?, ?)");
}

SqliteBagWriter::~SqliteBagWriter() {
  insert_message_.reset();
  sqlite3_close(db_);
}

void SqliteBagWriter::Execute(const std::string& sql) {
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr) != SQLITE_OK) Fail(path_.string(), db_, sql);
}

std::int64_t SqliteBagWriter::AddTopic(const std::string& name, const std::string& type,
                                       const std::string& offered_qos_profiles) {
  const auto insert =
      Prepare(db_, path_.string(),
              "INSERT INTO topics (name, type, serialization_format, offered_qos_profiles) VALUES (?, ?, 'cdr', ?)");
  sqlite3_bind_text(insert->statement, 1, name.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(insert->statement, 2, type.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(insert->statement, 3, offered_qos_profiles.c_str(), -1, SQLITE_TRANSIENT);
  if (sqlite3_step(insert->statement) != SQLITE_DONE) Fail(path_.string(), db_, "cannot write table topics");
  return sqlite3_last_insert_rowid(db_);
}

void SqliteBagWriter::AddMessage(std::int64_t topic_id, std::int64_t timestamp_ns, std::span<const std::uint8_t> data) {
  sqlite3_stmt* insert = insert_message_->statement;
  sqlite3_reset(insert);
  sqlite3_bind_int64(insert, 1, topic_id);
  sqlite3_bind_int64(insert, 2, timestamp_ns);
  sqlite3_bind_blob64(insert, 3, data.data(), data.size(), SQLITE_TRANSIENT);
  if (sqlite3_step(insert) != SQLITE_DONE) Fail(path_.string(), db_, "cannot write table messages");
}

void SqliteBagWriter::Finish(int metadata_version, const std::string& metadata_yaml) {
  const auto insert = Prepare(db_, path_.string(), "INSERT INTO metadata (metadata_version, metadata) VALUES (?, ?)");
  sqlite3_bind_int(insert->statement, 1, metadata_version);
  sqlite3_bind_text(insert->statement, 2, metadata_yaml.c_str(), -1, SQLITE_TRANSIENT);
  if (sqlite3_step(insert->statement) != SQLITE_DONE) Fail(path_.string(), db_, "cannot write table metadata");
  Execute("COMMIT");
}

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
