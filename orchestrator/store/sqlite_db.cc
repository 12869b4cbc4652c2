#include "orchestrator/store/sqlite_db.h"

#include <sqlite3.h>

#include <chrono>
#include <limits>
#include <thread>
#include <utility>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline store {
namespace {

using evaluator::InputError;

// Every writer of a results store (several orchestrators on one output folder, merges) waits
// this long for the others before giving up; a run is recorded in milliseconds.
constexpr int kBusyTimeoutMs = 10'000;

}  // namespace

std::string DescribeSqliteError(const std::filesystem::path& file, int code, std::string_view sqlite_message,
                                std::string_view doing) {
  const int primary = code & 0xff;
  std::string advice;
  if (primary == SQLITE_NOTADB || primary == SQLITE_CORRUPT) {
    advice = "; it is not a usable slamsweep results database: move it away (or restore a backup) and run again";
  } else if (primary == SQLITE_BUSY || primary == SQLITE_LOCKED) {
    advice = "; another process held the database for more than 10 s: wait for it and run again";
  } else if (primary == SQLITE_CANTOPEN || primary == SQLITE_PERM || primary == SQLITE_READONLY) {
    advice = "; check that the folder exists and is writable";
  } else if (primary == SQLITE_FULL || primary == SQLITE_IOERR) {
    advice = "; check free disk space and the file system";
  }
  return fmt::format("{}: {}: {}{}", file.string(), doing, sqlite_message, advice);
}

SqliteStatement::SqliteStatement(sqlite3* db, std::string_view sql, std::filesystem::path file)
    : db_(db), file_(std::move(file)) {
  const int rc = sqlite3_prepare_v2(db_, sql.data(), static_cast<int>(sql.size()), &stmt_, nullptr);
  if (rc != SQLITE_OK) {
    throw InputError(DescribeSqliteError(file_, rc, sqlite3_errmsg(db_), fmt::format("preparing '{}'", sql)));
  }
}

SqliteStatement::~SqliteStatement() { sqlite3_finalize(stmt_); }

SqliteStatement& SqliteStatement::Bind(int index, std::int64_t value) {
  sqlite3_bind_int64(stmt_, index, value);
  return *this;
}

SqliteStatement& SqliteStatement::Bind(int index, double value) {
  sqlite3_bind_double(stmt_, index, value);
  return *this;
}

SqliteStatement& SqliteStatement::Bind(int index, std::string_view value) {
  sqlite3_bind_text64(stmt_, index, value.data(), value.size(), SQLITE_TRANSIENT, SQLITE_UTF8);
  return *this;
}

SqliteStatement& SqliteStatement::BindNull(int index) {
  sqlite3_bind_null(stmt_, index);
  return *this;
}

SqliteStatement& SqliteStatement::BindJson(int index, const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null:
    case nlohmann::json::value_t::discarded:
      return BindNull(index);
    case nlohmann::json::value_t::number_integer:
      return Bind(index, value.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: {
      const auto u = value.get<std::uint64_t>();
      // SQLite integers are signed 64-bit; a larger seed keeps its exact digits as text.
      if (u > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        return Bind(index, std::string_view(std::to_string(u)));
      }
      return Bind(index, static_cast<std::int64_t>(u));
    }
    case nlohmann::json::value_t::number_float:
      return Bind(index, value.get<double>());
    case nlohmann::json::value_t::boolean:
      return Bind(index, static_cast<std::int64_t>(value.get<bool>() ? 1 : 0));
    case nlohmann::json::value_t::string:
      return Bind(index, std::string_view(value.get_ref<const std::string&>()));
    default:
      return Bind(index, std::string_view(value.dump()));
  }
}

bool SqliteStatement::Step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  throw InputError(DescribeSqliteError(file_, sqlite3_extended_errcode(db_), sqlite3_errmsg(db_),
                                       fmt::format("running '{}'", sqlite3_sql(stmt_))));
}

void SqliteStatement::Run() {
  while (Step()) {
  }
}

void SqliteStatement::Reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

bool SqliteStatement::IsNull(int column) const { return sqlite3_column_type(stmt_, column) == SQLITE_NULL; }

std::int64_t SqliteStatement::Int64(int column) const { return sqlite3_column_int64(stmt_, column); }

double SqliteStatement::Double(int column) const { return sqlite3_column_double(stmt_, column); }

std::string SqliteStatement::Text(int column) const {
  const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, column));
  if (text == nullptr) return {};
  return std::string(text, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column)));
}

std::string SqliteStatement::TextOrEmpty(int column) const { return IsNull(column) ? "" : Text(column); }

std::optional<double> SqliteStatement::OptionalDouble(int column) const {
  if (IsNull(column)) return std::nullopt;
  return Double(column);
}

nlohmann::json SqliteStatement::Json(int column) const {
  switch (sqlite3_column_type(stmt_, column)) {
    case SQLITE_INTEGER:
      return Int64(column);
    case SQLITE_FLOAT:
      return Double(column);
    case SQLITE_NULL:
      return nullptr;
    default:
      return Text(column);
  }
}

SqliteDb SqliteDb::Open(const std::filesystem::path& file, bool create) {
  if (!create && !std::filesystem::exists(file)) {
    throw InputError(
        fmt::format("{}: no such results database (expected the results.sqlite of a slamsweep output "
                    "directory)",
                    file.string()));
  }
  sqlite3* db = nullptr;
  const int flags = SQLITE_OPEN_READWRITE | (create ? SQLITE_OPEN_CREATE : 0) | SQLITE_OPEN_NOMUTEX;
  const int rc = sqlite3_open_v2(file.c_str(), &db, flags, nullptr);
  if (rc != SQLITE_OK) {
    const std::string message = db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
    sqlite3_close(db);
    throw InputError(DescribeSqliteError(file, rc, message, "cannot open"));
  }
  sqlite3_extended_result_codes(db, 1);
  sqlite3_busy_timeout(db, kBusyTimeoutMs);
  return SqliteDb(db, file);
}

SqliteDb::~SqliteDb() { sqlite3_close(db_); }

SqliteDb::SqliteDb(SqliteDb&& other) noexcept : db_(std::exchange(other.db_, nullptr)), file_(std::move(other.file_)) {}

SqliteDb& SqliteDb::operator=(SqliteDb&& other) noexcept {
  if (this != &other) {
    sqlite3_close(db_);
    db_ = std::exchange(other.db_, nullptr);
    file_ = std::move(other.file_);
  }
  return *this;
}

void SqliteDb::Execute(std::string_view sql) {
  char* error = nullptr;
  const std::string text(sql);
  const int rc = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &error);
  if (rc != SQLITE_OK) {
    const std::string message = error != nullptr ? error : sqlite3_errstr(rc);
    sqlite3_free(error);
    throw InputError(DescribeSqliteError(file_, sqlite3_extended_errcode(db_), message,
                                         fmt::format("running '{}'", text.substr(0, 60))));
  }
}

void SqliteDb::ExecuteRetryingWhileBusy(std::string_view sql) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(kBusyTimeoutMs);
  const std::string text(sql);
  while (true) {
    char* error = nullptr;
    const int rc = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &error);
    if (rc == SQLITE_OK) return;
    const std::string message = error != nullptr ? error : sqlite3_errstr(rc);
    sqlite3_free(error);
    if ((rc & 0xff) != SQLITE_BUSY || std::chrono::steady_clock::now() >= deadline) {
      throw InputError(DescribeSqliteError(file_, sqlite3_extended_errcode(db_), message,
                                           fmt::format("running '{}'", text.substr(0, 60))));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

SqliteStatement SqliteDb::Prepare(std::string_view sql) const { return SqliteStatement(db_, sql, file_); }

std::unique_ptr<SqliteStatement> SqliteDb::PrepareKept(std::string_view sql) const {
  return std::make_unique<SqliteStatement>(db_, sql, file_);
}

std::int64_t SqliteDb::LastInsertRowId() const { return sqlite3_last_insert_rowid(db_); }

SqliteTransaction::SqliteTransaction(SqliteDb& db) : db_(db) { db_.Execute("BEGIN IMMEDIATE"); }

SqliteTransaction::~SqliteTransaction() {
  if (done_) return;
  try {
    db_.Execute("ROLLBACK");
  } catch (const std::exception&) {
    // Rolling back can only fail when SQLite already rolled back on its own (I/O error, full disk);
    // the original exception is the one worth reporting.
  }
}

void SqliteTransaction::Commit() {
  db_.Execute("COMMIT");
  done_ = true;
}

}  // namespace slamsweep::orchestrator::inline store
