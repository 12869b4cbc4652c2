#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

struct sqlite3;
struct sqlite3_stmt;

namespace slamsweep::orchestrator::inline store {

/// A prepared statement, finalized when it goes out of scope. Bind indices start at 1,
/// column indices at 0, as in the SQLite C API. Errors throw InputError naming the database file.
class SqliteStatement {
 public:
  SqliteStatement(sqlite3* db, std::string_view sql, std::filesystem::path file);
  ~SqliteStatement();
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;

  SqliteStatement& Bind(int index, std::int64_t value);
  SqliteStatement& Bind(int index, double value);
  SqliteStatement& Bind(int index, std::string_view value);
  SqliteStatement& BindNull(int index);
  /// Null -> NULL, integers -> INTEGER (unsigned beyond int64 as decimal TEXT), floats -> REAL,
  /// strings -> TEXT, booleans -> 0/1, arrays and objects -> their JSON text.
  SqliteStatement& BindJson(int index, const nlohmann::json& value);

  /// Advances to the next row; false when the statement is done.
  bool Step();
  /// Runs a statement that returns no rows (or whose rows are not needed) to completion.
  void Run();
  void Reset();

  bool IsNull(int column) const;
  std::int64_t Int64(int column) const;
  double Double(int column) const;
  std::string Text(int column) const;
  /// The column's text, empty when it is NULL.
  std::string TextOrEmpty(int column) const;
  std::optional<double> OptionalDouble(int column) const;
  /// The column as JSON: NULL -> null, INTEGER -> number, REAL -> number, TEXT -> string.
  nlohmann::json Json(int column) const;

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
  std::filesystem::path file_;
};

/// One connection to an SQLite file, closed when it goes out of scope (movable, not copyable).
/// Exists so the results store can talk to SQLite without leaking handles on the error paths.
class SqliteDb {
 public:
  /// `create` false: a missing file is an InputError instead of a new empty database.
  static SqliteDb Open(const std::filesystem::path& file, bool create);
  ~SqliteDb();
  SqliteDb(SqliteDb&& other) noexcept;
  SqliteDb& operator=(SqliteDb&& other) noexcept;
  SqliteDb(const SqliteDb&) = delete;
  SqliteDb& operator=(const SqliteDb&) = delete;

  /// Runs one or more statements without results.
  void Execute(std::string_view sql);
  /// Execute, tried again while SQLite answers "busy" without waiting (two connections that both
  /// hold a read lock and want the write lock), up to the same time as any other wait.
  void ExecuteRetryingWhileBusy(std::string_view sql);
  SqliteStatement Prepare(std::string_view sql) const;
  /// A statement to keep and run many times (the store's cache of its most used statements).
  std::unique_ptr<SqliteStatement> PrepareKept(std::string_view sql) const;
  std::int64_t LastInsertRowId() const;
  const std::filesystem::path& file() const { return file_; }

 private:
  SqliteDb(sqlite3* db, std::filesystem::path file) : db_(db), file_(std::move(file)) {}
  sqlite3* db_ = nullptr;
  std::filesystem::path file_;
};

/// BEGIN IMMEDIATE on construction (the write lock is taken up front, so a busy database waits
/// in the busy handler instead of failing on a lock upgrade); ROLLBACK unless Commit() was called.
class SqliteTransaction {
 public:
  explicit SqliteTransaction(SqliteDb& db);
  ~SqliteTransaction();
  SqliteTransaction(const SqliteTransaction&) = delete;
  SqliteTransaction& operator=(const SqliteTransaction&) = delete;
  void Commit();

 private:
  SqliteDb& db_;
  bool done_ = false;
};

/// The InputError message for an SQLite failure on `file`: the SQLite text plus what to do,
/// e.g. for a file that is not a database.
std::string DescribeSqliteError(const std::filesystem::path& file, int code, std::string_view sqlite_message,
                                std::string_view doing);

}  // namespace slamsweep::orchestrator::inline store
