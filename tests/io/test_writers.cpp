// Base64, CSV history, JSON and progress output.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "abut/io/csv_history.hpp"
#include "abut/io/json_writer.hpp"
#include "abut/io/progress.hpp"
#include "abut/io/vtu_writer.hpp"
#include "test_files.hpp"

namespace abut {
namespace {

using testing::file_text;

std::string base64_of(std::string_view text) {
  return base64_encode(std::as_bytes(std::span<const char>(text.data(), text.size())));
}

std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("abut_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(Base64, MatchesTheTestVectorsOfRfc4648) {
  // RFC 4648, section 10 "Test Vectors".
  EXPECT_EQ(base64_of(""), "");
  EXPECT_EQ(base64_of("f"), "Zg==");
  EXPECT_EQ(base64_of("fo"), "Zm8=");
  EXPECT_EQ(base64_of("foo"), "Zm9v");
  EXPECT_EQ(base64_of("foob"), "Zm9vYg==");
  EXPECT_EQ(base64_of("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64_of("foobar"), "Zm9vYmFy");
}

TEST(Base64, UsesTheLastTwoAlphabetCharacters) {
  // Bits 111110 111111 1111(00) are the values 62, 63, 60: '+', '/', '8' (RFC 4648, Table 1).
  const std::byte bytes[] = {std::byte{0xFB}, std::byte{0xFF}};
  EXPECT_EQ(base64_encode(bytes), "+/8=");
}

TEST(CsvHistory, WritesHeaderAndFlushedRows) {
  const auto dir = scratch_dir("csv");
  const auto path = dir / "parts.csv";
  CsvHistory csv(path, {"part", "kinetic_energy", "mass, total"});
  EXPECT_EQ(file_text(path), "time,part,kinetic_energy,\"mass, total\"\n");

  csv.write_row(0.1 + 0.2, {std::int64_t{3}, 0.1234567890123, 12345678901.5});
  // Time keeps every digit (0.1 + 0.2 is 0.30000000000000004 in binary64); reals get 10
  // significant digits as printf("%.10g"); the part id is an exact integer. Read while the
  // writer is still open: each row is flushed.
  EXPECT_EQ(file_text(path),
            "time,part,kinetic_energy,\"mass, total\"\n"
            "0.30000000000000004,3,0.123456789,1.23456789e+10\n");

  csv.write_row(1e-3, {std::int64_t{-7}, -0.0, 2.5e-300});
  EXPECT_EQ(file_text(path),
            "time,part,kinetic_energy,\"mass, total\"\n"
            "0.30000000000000004,3,0.123456789,1.23456789e+10\n"
            "0.001,-7,-0,2.5e-300\n");

  EXPECT_THROW(csv.write_row(2e-3, {1.0, 2.0}), std::invalid_argument);
  std::filesystem::remove_all(dir);
}

TEST(CsvHistory, ReportsAFileThatCannotBeCreated) {
  EXPECT_THROW(CsvHistory("/nonexistent_abut_dir/energy.csv", {"kinetic"}), std::runtime_error);
}

TEST(JsonWriter, EscapesAsRfc8259Section7Requires) {
  EXPECT_EQ(JsonWriter::quoted("plain"), "\"plain\"");
  EXPECT_EQ(JsonWriter::quoted("say \"hi\"\\"), R"("say \"hi\"\\")");
  EXPECT_EQ(JsonWriter::quoted("a\nb\tc\r\b\f"), R"("a\nb\tc\r\b\f")");
  EXPECT_EQ(JsonWriter::quoted(std::string("\x01\x1f", 2)), R"("\u0001\u001f")");
  EXPECT_EQ(JsonWriter::quoted("/ \x7f \xc3\xa9"), "\"/ \x7f \xc3\xa9\"");  // need no escape
}

TEST(JsonWriter, WritesNestedDocument) {
  JsonWriter json;
  json.begin_object()
      .member("name", "rubber sphere")
      .member("cycles", 1234)
      .member("stable", true)
      .member("end_time", 0.1 + 0.2)
      .member("unstable_value", std::numeric_limits<double>::quiet_NaN())
      .key("parts")
      .begin_array()
      .begin_object()
      .member("id", std::int64_t{-5})
      .member("mass", 2.5e-9)
      .end_object()
      .value(false)
      .null()
      .end_array()
      .key("empty")
      .begin_object()
      .end_object()
      .end_object();
  ASSERT_TRUE(json.complete());
  EXPECT_EQ(json.text(),
            "{\n"
            "  \"name\": \"rubber sphere\",\n"
            "  \"cycles\": 1234,\n"
            "  \"stable\": true,\n"
            "  \"end_time\": 0.30000000000000004,\n"
            "  \"unstable_value\": null,\n"
            "  \"parts\": [\n"
            "    {\n"
            "      \"id\": -5,\n"
            "      \"mass\": 2.5e-09\n"
            "    },\n"
            "    false,\n"
            "    null\n"
            "  ],\n"
            "  \"empty\": {}\n"
            "}");
}

TEST(JsonWriter, RealsReadBackExactly) {
  const double third = 1.0 / 3.0;
  JsonWriter json;
  json.value(third);
  EXPECT_EQ(std::strtod(json.text().c_str(), nullptr), third);
}

TEST(JsonWriter, RejectsMalformedUse) {
  JsonWriter a;
  a.begin_object();
  EXPECT_THROW(a.value(1), std::logic_error);                   // no key
  EXPECT_THROW(a.end_array(), std::logic_error);                // wrong bracket
  EXPECT_THROW(static_cast<void>(a.text()), std::logic_error);  // not complete
  a.key("k");
  EXPECT_THROW(a.end_object(), std::logic_error);  // key without value
  JsonWriter b;
  b.begin_array();
  EXPECT_THROW(b.key("k"), std::logic_error);  // key in an array
  JsonWriter c;
  c.value(1);
  EXPECT_THROW(c.value(2), std::logic_error);  // second top-level value
}

TEST(JsonWriter, WritesFileAtomically) {
  const auto dir = scratch_dir("json");
  JsonWriter json;
  json.begin_array().value("x").end_array();
  json.write_file(dir / "summary.json");
  EXPECT_EQ(file_text(dir / "summary.json"), "[\n  \"x\"\n]\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "summary.json.tmp"));
  std::filesystem::remove_all(dir);
}

TEST(ProgressReporter, PrintsPlainLinesEveryTenth) {
  std::ostringstream out;
  double wall = 0.0;
  ProgressReporter progress(0.0, 1e-3, out, false, [&] { return wall; });
  for (int k = 1; k <= 100; ++k) {
    wall = k;  // one wall second per cycle
    progress.update(k * 1e-5, k);
  }
  progress.finish(1e-3, 100);
  // At cycle 10k, 10k seconds have passed and 100 - 10k remain at that rate.
  EXPECT_EQ(out.str(),
            "  10%  t=1.00e-04  cycle 10  ETA 0:01:30\n"
            "  20%  t=2.00e-04  cycle 20  ETA 0:01:20\n"
            "  30%  t=3.00e-04  cycle 30  ETA 0:01:10\n"
            "  40%  t=4.00e-04  cycle 40  ETA 0:01:00\n"
            "  50%  t=5.00e-04  cycle 50  ETA 0:00:50\n"
            "  60%  t=6.00e-04  cycle 60  ETA 0:00:40\n"
            "  70%  t=7.00e-04  cycle 70  ETA 0:00:30\n"
            "  80%  t=8.00e-04  cycle 80  ETA 0:00:20\n"
            "  90%  t=9.00e-04  cycle 90  ETA 0:00:10\n"
            " 100%  t=1.00e-03  cycle 100  wall 0:01:40\n");
}

TEST(ProgressReporter, PrintsOneLineWhenAStepCrossesSeveralTenths) {
  std::ostringstream out;
  double wall = 0.0;
  ProgressReporter progress(1.0, 2.0, out, false, [&] { return wall; });
  wall = 7200.0;
  progress.update(1.05, 1);  // below 10 %: nothing
  progress.update(1.35, 2);  // 35 %: one line
  wall = 7300.0;
  progress.update(1.5, 3);  // stops early: final line from finish
  progress.finish(1.5, 3);
  EXPECT_EQ(out.str(),
            "  35%  t=1.35e+00  cycle 2  ETA 3:42:51\n"
            "  50%  t=1.50e+00  cycle 3  ETA 2:01:40\n"
            "  50%  t=1.50e+00  cycle 3  wall 2:01:40\n");
}

TEST(ProgressReporter, RedrawsTheTerminalBarAtMostTenTimesASecond) {
  std::ostringstream out;
  double wall = 0.0;
  ProgressReporter progress(0.0, 1.0, out, true, [&] { return wall; });
  for (int k = 0; k < 100; ++k) {
    wall = k / 32.0;  // 1/32 s per cycle: the first cycle >= 0.1 s after a draw is the 4th
    progress.update(k / 100.0, k);
  }
  progress.finish(1.0, 100);
  const std::string text = out.str();
  // Draws at cycles 0, 4, ..., 96 (25) and the final one.
  EXPECT_EQ(std::count(text.begin(), text.end(), '\r'), 26);
  // The final redraw carries the wall time and ends the line; nothing repeats it.
  EXPECT_TRUE(
      text.ends_with("\r[##############################] 100%  t=1.00e+00  cycle 100  "
                     "wall 0:00:03\n"))
      << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
}

TEST(ProgressReporter, RejectsAnEmptyTimeRange) {
  std::ostringstream out;
  EXPECT_THROW(ProgressReporter(1.0, 1.0, out, false), std::invalid_argument);
}

}  // namespace
}  // namespace abut
