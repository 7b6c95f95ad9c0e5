#include "common/navdb/sqlite_connection.hpp"

#include <sqlite3.h>

#include <stdexcept>
#include <utility>

namespace fedsim::nav {

// ---- SqliteConnection -------------------------------------------------------------------------

namespace {

std::string open_message(sqlite3* db, int code) {
  return db ? sqlite3_errmsg(db) : sqlite3_errstr(code);
}

/// The handle of `path` opened with `flags`; throws std::runtime_error "<path>: <failure>:
/// <SQLite's reason>" (the half-open handle closed) when SQLite refuses.
sqlite3* open_or_throw(const std::string& path, int flags, const char* failure) {
  sqlite3* db = nullptr;
  const int code = sqlite3_open_v2(path.c_str(), &db, flags, nullptr);
  if (code != SQLITE_OK) {
    const std::string message = open_message(db, code);
    sqlite3_close(db);
    throw std::runtime_error(path + ": " + failure + ": " + message);
  }
  return db;
}

}  // namespace

SqliteConnection SqliteConnection::open_read_only(const std::string& path) {
  return SqliteConnection(
      open_or_throw(path, SQLITE_OPEN_READONLY | SQLITE_OPEN_NOMUTEX, "cannot open as SQLite"),
      path);
}

SqliteConnection SqliteConnection::create(const std::string& path) {
  return SqliteConnection(
      open_or_throw(path, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX,
                    "cannot create"),
      path);
}

SqliteConnection::SqliteConnection(SqliteConnection&& other) noexcept
    : db_(std::exchange(other.db_, nullptr)), path_(std::move(other.path_)) {}

SqliteConnection& SqliteConnection::operator=(SqliteConnection&& other) noexcept {
  if (this != &other) {
    sqlite3_close(db_);
    db_ = std::exchange(other.db_, nullptr);
    path_ = std::move(other.path_);
  }
  return *this;
}

SqliteConnection::~SqliteConnection() { sqlite3_close(db_); }

void SqliteConnection::exec(std::string_view sql) const {
  char* message = nullptr;
  const std::string text(sql);
  if (sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
    const std::string error = message ? message : "unknown error";
    sqlite3_free(message);
    throw std::runtime_error(path_ + ": " + error + " (in: " + text.substr(0, 80) + ")");
  }
}

void SqliteConnection::fail(const std::string& what) const {
  throw std::runtime_error(path_ + ": " + what + ": " + sqlite3_errmsg(db_));
}

// ---- SqliteStatement --------------------------------------------------------------------------

SqliteStatement::SqliteStatement(const SqliteConnection& connection, std::string_view sql)
    : connection_(&connection) {
  if (sqlite3_prepare_v3(connection.handle(), sql.data(), static_cast<int>(sql.size()),
                         SQLITE_PREPARE_PERSISTENT, &statement_, nullptr) != SQLITE_OK) {
    connection.fail("cannot prepare '" + std::string(sql.substr(0, 80)) + "'");
  }
}

SqliteStatement::SqliteStatement(SqliteStatement&& other) noexcept
    : statement_(std::exchange(other.statement_, nullptr)),
      connection_(std::exchange(other.connection_, nullptr)) {}

SqliteStatement& SqliteStatement::operator=(SqliteStatement&& other) noexcept {
  if (this != &other) {
    sqlite3_finalize(statement_);
    statement_ = std::exchange(other.statement_, nullptr);
    connection_ = std::exchange(other.connection_, nullptr);
  }
  return *this;
}

SqliteStatement::~SqliteStatement() { sqlite3_finalize(statement_); }

void SqliteStatement::fail(const std::string& what) const {
  if (connection_) connection_->fail(what);
  throw std::runtime_error("SQLite: " + what);
}

void SqliteStatement::bind(int index, double value) {
  if (sqlite3_bind_double(statement_, index, value) != SQLITE_OK) fail("bind");
}

void SqliteStatement::bind(int index, std::int64_t value) {
  if (sqlite3_bind_int64(statement_, index, value) != SQLITE_OK) fail("bind");
}

void SqliteStatement::bind(int index, std::string_view value) {
  if (sqlite3_bind_text(statement_, index, value.data(), static_cast<int>(value.size()),
                        SQLITE_TRANSIENT) != SQLITE_OK) {
    fail("bind");
  }
}

void SqliteStatement::bind_null(int index) {
  if (sqlite3_bind_null(statement_, index) != SQLITE_OK) fail("bind");
}

bool SqliteStatement::step() {
  const int code = sqlite3_step(statement_);
  if (code == SQLITE_ROW) return true;
  if (code == SQLITE_DONE) return false;
  fail("query failed");
}

void SqliteStatement::reset() {
  sqlite3_reset(statement_);
  sqlite3_clear_bindings(statement_);
}

void SqliteStatement::run() {
  step();
  reset();
}

double SqliteStatement::column_double(int index) const {
  return sqlite3_column_double(statement_, index);
}

std::int64_t SqliteStatement::column_int64(int index) const {
  return sqlite3_column_int64(statement_, index);
}

std::string SqliteStatement::column_text(int index) const {
  const unsigned char* text = sqlite3_column_text(statement_, index);
  return text ? std::string(reinterpret_cast<const char*>(text)) : std::string();
}

bool SqliteStatement::column_is_null(int index) const {
  return sqlite3_column_type(statement_, index) == SQLITE_NULL;
}

}  // namespace fedsim::nav
