#include "common/csv/csv_reader.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>

namespace fedsim::csv {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const CsvError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CsvReader, ReadsHeaderRowsQuotesCommentsAndBlankLines) {
  std::istringstream in(
      "# a comment\n"
      "name, value ,note\n"
      "\n"
      "alpha, 1.5, \"a, b\"\n"
      "# another\n"
      "beta,-2e3,\"say \"\"hi\"\"\"\n"
      "gamma,+4,\"two\nlines\"\n");
  CsvReader reader(in, "test.csv");
  EXPECT_EQ(reader.header(), (std::vector<std::string>{"name", "value", "note"}));
  CsvRow row;
  ASSERT_TRUE(reader.next(row));
  EXPECT_EQ(row.line(), 4);
  EXPECT_EQ(row.text("name"), "alpha");
  EXPECT_EQ(row.number("value"), 1.5);
  EXPECT_EQ(row.text("note"), "a, b");
  ASSERT_TRUE(reader.next(row));
  EXPECT_EQ(row.line(), 6);
  EXPECT_EQ(row.number(1), -2000.0);
  EXPECT_EQ(row.text(2), "say \"hi\"");
  ASSERT_TRUE(reader.next(row));
  EXPECT_EQ(row.number("value"), 4.0);
  EXPECT_EQ(row.text("note"), "two\nlines");
  EXPECT_FALSE(reader.next(row));
}

TEST(CsvReader, ErrorsNameFileLineAndColumn) {
  std::istringstream ragged("a,b\n1,2\n3\n");
  CsvReader r1(ragged, "ragged.csv");
  CsvRow row;
  ASSERT_TRUE(r1.next(row));
  EXPECT_EQ(error_of([&] { r1.next(row); }), "ragged.csv:3: 1 fields, the header has 2");

  std::istringstream bad("a,b\n1,x2\n");
  CsvReader r2(bad, "bad.csv");
  ASSERT_TRUE(r2.next(row));
  EXPECT_EQ(error_of([&] { row.number("b"); }), "bad.csv:2: column 'b': not a number: 'x2'");
  EXPECT_EQ(error_of([&] { row.number("c"); }), "bad.csv: no column 'c' (the header has a, b)");

  for (const char* text : {"nan", "inf", "-inf", "1e999"}) {
    std::istringstream in(std::string("a\n") + text + "\n");
    CsvReader r(in, "nf.csv");
    ASSERT_TRUE(r.next(row));
    EXPECT_NE(error_of([&] { row.number("a"); }), "no error") << text;
  }
  std::istringstream range("a\n5\n");
  CsvReader r3(range, "range.csv");
  ASSERT_TRUE(r3.next(row));
  EXPECT_EQ(row.number_in("a", 0, 5), 5.0);
  EXPECT_NE(error_of([&] { row.number_in("a", 0, 4); }).find("range.csv:2: column 'a'"),
            std::string::npos);

  std::istringstream open_quote("a\n\"never closed\n");
  CsvReader r4(open_quote, "q.csv");
  EXPECT_EQ(error_of([&] { r4.next(row); }), "q.csv:2: unterminated quote");

  std::istringstream twice("a,a\n");
  EXPECT_EQ(error_of([&] { CsvReader r(twice, "dup.csv"); }), "dup.csv:1: header names 'a' twice");
  std::istringstream empty("");
  EXPECT_EQ(error_of([&] { CsvReader r(empty, "empty.csv"); }), "empty.csv: empty (no header line)");
  EXPECT_EQ(error_of([] { CsvReader::open("/nonexistent/x.csv"); }),
            "/nonexistent/x.csv: cannot open");
}

TEST(CsvReader, TrailingCommentsAreDroppedOutsideQuotes) {
  std::istringstream in("a,b  # header comment\n1,\"x # not a comment\" # a comment\n  # whole line\n");
  CsvReader reader(in, "c.csv");
  EXPECT_EQ(reader.header(), (std::vector<std::string>{"a", "b"}));
  CsvRow row;
  ASSERT_TRUE(reader.next(row));
  EXPECT_EQ(row.text("b"), "x # not a comment");
  EXPECT_FALSE(reader.next(row));
}

TEST(CsvReader, IntegersRejectFractions) {
  std::istringstream in("n\n12\n1.5\n");
  CsvReader r(in, "int.csv");
  CsvRow row;
  ASSERT_TRUE(r.next(row));
  EXPECT_EQ(row.integer("n"), 12);
  ASSERT_TRUE(r.next(row));
  EXPECT_EQ(error_of([&] { row.integer("n"); }), "int.csv:3: column 'n': not an integer: '1.5'");
}

TEST(NumericTable, LoadsColumnsFromAFile) {
  const std::string path = testing::TempDir() + "/numeric_table_test.csv";
  {
    std::ofstream out(path);
    out << "t,x\n0,1\n0.5,2\n";
  }
  const NumericTable table = NumericTable::load(path);
  EXPECT_EQ(table.rows(), 2u);
  EXPECT_EQ(table.column("x"), (std::vector<double>{1.0, 2.0}));
  EXPECT_TRUE(table.has("t"));
  EXPECT_FALSE(table.has("y"));
  EXPECT_THROW(table.column("y"), std::out_of_range);
  std::remove(path.c_str());
}

TEST(SplitCsvLine, TrimsUnquotedFieldsAndKeepsQuotedBlanks) {
  EXPECT_EQ(split_csv_line(" a , \" b \",c"), (std::vector<std::string>{"a", " b ", "c"}));
  EXPECT_EQ(split_csv_line(""), (std::vector<std::string>{""}));
  EXPECT_EQ(split_csv_line("a,,"), (std::vector<std::string>{"a", "", ""}));
  EXPECT_THROW(split_csv_line("\"open"), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::csv
