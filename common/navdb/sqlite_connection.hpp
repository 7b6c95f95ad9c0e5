// A thin RAII layer over the SQLite C API for the navigation database: a connection and its
// prepared statements. Errors throw std::runtime_error naming the database file and SQLite's
// message.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

struct sqlite3;
struct sqlite3_stmt;

namespace fedsim::nav {

class SqliteConnection;

/// A prepared statement; reset() before re-binding. Column and bind indices as in SQLite
/// (bind from 1, columns from 0).
class SqliteStatement {
 public:
  SqliteStatement() = default;
  SqliteStatement(const SqliteConnection& connection, std::string_view sql);
  SqliteStatement(SqliteStatement&& other) noexcept;
  SqliteStatement& operator=(SqliteStatement&& other) noexcept;
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;
  ~SqliteStatement();

  void bind(int index, double value);
  void bind(int index, std::int64_t value);
  void bind(int index, std::string_view value);
  void bind_null(int index);
  /// Steps; true when a row is available, false when done. Throws on an error.
  bool step();
  /// Resets for a new execution and clears the bindings.
  void reset();
  /// Runs a statement that returns no rows, then resets it.
  void run();

  double column_double(int index) const;
  std::int64_t column_int64(int index) const;
  std::string column_text(int index) const;
  bool column_is_null(int index) const;

 private:
  [[noreturn]] void fail(const std::string& what) const;
  sqlite3_stmt* statement_ = nullptr;
  const SqliteConnection* connection_ = nullptr;
};

class SqliteConnection {
 public:
  /// Opens an existing file read-only (throws naming the path if SQLite cannot).
  static SqliteConnection open_read_only(const std::string& path);
  /// Creates (or truncates) a database file for writing.
  static SqliteConnection create(const std::string& path);

  SqliteConnection(SqliteConnection&& other) noexcept;
  SqliteConnection& operator=(SqliteConnection&& other) noexcept;
  SqliteConnection(const SqliteConnection&) = delete;
  SqliteConnection& operator=(const SqliteConnection&) = delete;
  ~SqliteConnection();

  /// Runs one or more SQL statements without results.
  void exec(std::string_view sql) const;
  sqlite3* handle() const { return db_; }
  const std::string& path() const { return path_; }
  /// "<path>: <what>: <SQLite's last message>".
  [[noreturn]] void fail(const std::string& what) const;

 private:
  SqliteConnection(sqlite3* db, std::string path) : db_(db), path_(std::move(path)) {}
  sqlite3* db_ = nullptr;
  std::string path_;
};

}  // namespace fedsim::nav
