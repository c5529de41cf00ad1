#include "core/csv.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace ejecta {

std::string csvNumber(double x) {
  if (std::isnan(x)) return "nan";  // printf may write "-nan"
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[40];
  for (int digits = 9; digits < 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) return buf;
  }
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

bool parseCsvNumber(std::string_view field, double& value) {
  const std::string text(field);  // strtod needs the terminator
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size()) return false;
  return errno != ERANGE || std::fabs(value) != HUGE_VAL;  // underflow is a number; overflow is not
}

std::string csvText(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

CsvWriter::CsvWriter(const std::vector<std::string>& columns) : columns_(columns.size()) {
  for (const std::string& c : columns) field(csvText(c));
  endRow();
}

CsvWriter& CsvWriter::field(std::string_view s) {
  if (inRow_++ > 0) out_ += ',';
  out_ += s;
  return *this;
}

CsvWriter& CsvWriter::number(double x) { return field(csvNumber(x)); }
CsvWriter& CsvWriter::integer(long long n) { return field(std::to_string(n)); }
CsvWriter& CsvWriter::count(std::uint64_t n) { return field(std::to_string(n)); }
CsvWriter& CsvWriter::flag(bool b) { return field(b ? "1" : "0"); }
CsvWriter& CsvWriter::text(std::string_view s) { return field(csvText(s)); }

CsvWriter& CsvWriter::quoted(std::string_view s) {
  std::string q = csvText(s);
  if (q.empty() || q.front() != '"') q = '"' + q + '"';
  return field(q);
}

CsvWriter& CsvWriter::endRow() {
  if (inRow_ != columns_)
    throw std::logic_error("CSV row with " + std::to_string(inRow_) + " fields under a header of " +
                           std::to_string(columns_));
  out_ += '\n';
  inRow_ = 0;
  return *this;
}

}  // namespace ejecta
