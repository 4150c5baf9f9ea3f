// Store-internal: a prepared SQLite statement with RAII finalisation and typed binding.
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <string>

namespace corrmp {

class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int index, const std::string& value);
  Statement& bind(int index, int64_t value);
  Statement& bind(int index, double value);
  Statement& bind_null(int index);
  // Binds column `column` of `from`'s current row as it is (any type, NULL too); `from` may
  // belong to another connection.
  Statement& bind_column(int index, const Statement& from, int column);

  // Steps once; true when a row is available.
  bool step();
  // Steps to completion, then resets for reuse with new bindings.
  void run();
  void reset();

  int64_t column_int(int index) const;
  double column_double(int index) const;
  std::string column_text(int index) const;
  bool column_is_null(int index) const;

 private:
  void check(int code, const char* what) const;
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

}  // namespace corrmp
