#pragma once
// The one CSV writer of the outputs written by hand (flux.csv, sizing.csv, wall_<patch>.csv,
// ble.csv, the view-factor tables): a header row, then rows of numbers and text, each row
// checked to have the header's width; and the reader of the numbers it writes.
//
// Numbers are written as printf's "%.9g" when that reads back as the same double (so 0.1,
// 3000 and 0.0005 print as before), else with as many more significant digits, up to 17, as it
// takes to read back exactly: every value round-trips. NaN is written "nan" and infinities
// "inf"/"-inf", as printf writes them and as every existing output did: std::stod, numpy and
// the chart scripts read them back; an empty field would read as a missing column instead.
// Text is quoted (RFC 4180: quotes doubled) only when it holds a comma, a quote or a line break.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ejecta {

std::string csvNumber(double x);
std::string csvText(std::string_view text);

// Reads a whole field as strtod does, as csvNumber writes it: "nan", "inf" and subnormal numbers
// included (strtod flags those ERANGE though it reads them exactly: a pressure of 3e-319 Pa where
// a shock has not arrived is a number; one below the smallest subnormal reads as 0). False for
// an empty field, text after the number, or a magnitude above the largest double.
bool parseCsvNumber(std::string_view field, double& value);

class CsvWriter {
 public:
  explicit CsvWriter(const std::vector<std::string>& columns);

  CsvWriter& number(double x);
  CsvWriter& integer(long long n);
  CsvWriter& count(std::uint64_t n);
  CsvWriter& flag(bool b);                   // 1 or 0
  CsvWriter& text(std::string_view s);       // quoted when needed
  CsvWriter& quoted(std::string_view s);     // always quoted (free text such as notes)
  // Ends the row; throws std::logic_error when it does not have the header's width.
  CsvWriter& endRow();

  std::size_t columns() const { return columns_; }
  const std::string& str() const { return out_; }

 private:
  CsvWriter& field(std::string_view s);
  std::string out_;
  std::size_t columns_ = 0, inRow_ = 0;
};

}  // namespace ejecta
