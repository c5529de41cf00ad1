// The one CSV writer (core/csv) and its reader: numbers that read back exactly (and print as
// "%.9g" did where that already round-trips), NaN and infinities, quoting, rows checked against
// the header.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/csv.hpp"

namespace ejecta {
namespace {

TEST(Csv, NumbersRoundTripAndKeepShortForms) {
  // Short forms are those "%.9g" gave, so existing outputs do not change where they were exact.
  EXPECT_EQ(csvNumber(0.0), "0");
  EXPECT_EQ(csvNumber(3000.0), "3000");
  EXPECT_EQ(csvNumber(0.1), "0.1");
  EXPECT_EQ(csvNumber(0.0005), "0.0005");
  EXPECT_EQ(csvNumber(-2.5e9), "-2.5e+09");
  EXPECT_EQ(csvNumber(1.5e-12), "1.5e-12");
  // Values "%.9g" would have rounded come back exactly.
  for (double x : {1.0 / 3.0, std::nextafter(1.0, 2.0), 6.02214076e23 * (1 + 1e-12), -std::sqrt(2.0),
                   std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min()}) {
    const std::string s = csvNumber(x);
    EXPECT_EQ(std::strtod(s.c_str(), nullptr), x) << s;  // stod rejects denormals (ERANGE)
  }
  EXPECT_EQ(csvNumber(1.0 / 3.0), "0.3333333333333333");  // the shortest exact form
}

TEST(Csv, NumbersReadBackAsWritten) {
  // Every value csvNumber writes reads back exactly, subnormals too (strtod flags them ERANGE).
  for (double x : {0.0, -2.5e9, 1.0 / 3.0, std::numeric_limits<double>::max(),
                   std::numeric_limits<double>::denorm_min(), -3.198679804e-319,
                   std::numeric_limits<double>::infinity()}) {
    double v = 0.0;
    EXPECT_TRUE(parseCsvNumber(csvNumber(x), v)) << csvNumber(x);
    EXPECT_EQ(v, x) << csvNumber(x);
  }
  double v = 0.0;
  EXPECT_TRUE(parseCsvNumber("nan", v));
  EXPECT_TRUE(std::isnan(v));
  EXPECT_TRUE(parseCsvNumber("1e-400", v));  // below the smallest subnormal: 0, still a number
  EXPECT_EQ(v, 0.0);
  for (const char* bad : {"", "12x", "1e999", "-1e999", " ", "1,5"})
    EXPECT_FALSE(parseCsvNumber(bad, v)) << bad;
}

TEST(Csv, NotANumberAndInfinities) {
  // As printf wrote them in every existing output (and std::stod reads them back); -NaN too.
  EXPECT_EQ(csvNumber(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(csvNumber(-std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(csvNumber(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(csvNumber(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_TRUE(std::isnan(std::stod(csvNumber(std::nan("")))));
}

TEST(Csv, QuotesTextOnlyWhenNeeded) {
  EXPECT_EQ(csvText("side0"), "side0");
  EXPECT_EQ(csvText("a,b"), "\"a,b\"");
  EXPECT_EQ(csvText("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csvText("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csvText(""), "");
}

TEST(Csv, WritesHeaderAndRows) {
  CsvWriter csv({"patch", "area_m2", "feasible", "runs", "note"});
  csv.text("side0").number(0.25).flag(true).integer(7).quoted("fine").endRow();
  csv.text("a,b").number(std::nan("")).flag(false).count(12).quoted("").endRow();
  EXPECT_EQ(csv.str(),
            "patch,area_m2,feasible,runs,note\n"
            "side0,0.25,1,7,\"fine\"\n"
            "\"a,b\",nan,0,12,\"\"\n");
  EXPECT_EQ(csv.columns(), 5u);
}

TEST(Csv, RejectsRowsOfTheWrongWidth) {
  CsvWriter csv({"time_s", "q"});
  csv.number(1.0);
  EXPECT_THROW(csv.endRow(), std::logic_error);
  CsvWriter wide({"x"});
  wide.number(1.0).number(2.0);
  EXPECT_THROW(wide.endRow(), std::logic_error);
}

}  // namespace
}  // namespace ejecta
