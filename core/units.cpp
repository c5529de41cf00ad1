#include "core/units.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

namespace ejecta {

namespace {

struct NamedDimension {
  Dimension dim;
  std::string_view description;  // "a density"
  std::string_view unit;         // "kg/m^3"
};

constexpr std::array<NamedDimension, 16> kNamedDimensions{{
    {Dimension::None, "a plain number", ""},
    {Dimension::Length, "a length", "m"},
    {Dimension::Mass, "a mass", "kg"},
    {Dimension::Time, "a time", "s"},
    {Dimension::Temperature, "a temperature", "K"},
    {Dimension::Angle, "an angle", "rad"},
    {Dimension::Velocity, "a velocity", "m/s"},
    {Dimension::Acceleration, "an acceleration", "m/s^2"},
    {Dimension::Density, "a density", "kg/m^3"},
    {Dimension::Pressure, "a pressure", "Pa"},
    {Dimension::Energy, "an energy", "J"},
    {Dimension::SpecificEnergy, "a specific energy", "J/kg"},
    {Dimension::Area, "an area", "m^2"},
    {Dimension::Volume, "a volume", "m^3"},
    {Dimension::Force, "a force", "N"},
    {Dimension::Power, "a power", "W"},
}};

const NamedDimension* findNamed(Dimension d) {
  for (const NamedDimension& n : kNamedDimensions)
    if (n.dim == d) return &n;
  return nullptr;
}

// Base unit symbols. `prefixable`: SI prefixes may be attached ("km", "MJ", "Mbar").
struct UnitDef {
  std::string_view symbol;
  double factor;  // SI value of one unit
  Dimension dim;
  bool prefixable;
};

// 1 t of TNT = 4.184e9 J (the conventional definition: 1 kt = 4.184e12 J, 1 Mt = 4.184e15 J).
constexpr double kTonTnt = 4.184e9;
constexpr double kTonne = 1e3;
// 1 psi = 1 lbf/in^2 = 6894.757293168361 Pa, exact from the international pound-force and inch
// (NIST SP 811 (2008), app. B.9); 1 ksi = 1000 psi.
constexpr double kPsi = 6894.757293168361;
constexpr double kKsi = 6.894757293168361e6;
constexpr double kDegree = std::numbers::pi / 180.0;
// 1 cc = 1 cm^3, as in "g/cc".
constexpr double kCubicCentimetre = 1e-6;

constexpr std::array<UnitDef, 17> kUnits{{
    {"m", 1.0, Dimension::Length, true},
    {"g", 1e-3, Dimension::Mass, true},
    {"s", 1.0, Dimension::Time, true},
    {"K", 1.0, Dimension::Temperature, false},
    {"J", 1.0, Dimension::Energy, true},
    {"Pa", 1.0, Dimension::Pressure, true},
    {"bar", 1e5, Dimension::Pressure, true},
    {"atm", 101325.0, Dimension::Pressure, false},
    {"N", 1.0, Dimension::Force, true},
    {"W", 1.0, Dimension::Power, true},
    {"psi", kPsi, Dimension::Pressure, false},
    {"ksi", kKsi, Dimension::Pressure, false},
    {"rad", 1.0, Dimension::Angle, true},
    {"deg", kDegree, Dimension::Angle, false},
    {"cc", kCubicCentimetre, Dimension::Volume, false},
    {"tonne", kTonne, Dimension::Mass, false},
    // "t": tonne or ton of TNT; the factor here is the mass reading, see resolveT below.
    {"t", kTonne, Dimension::Mass, true},
}};

struct Prefix {
  std::string_view symbol;
  double factor;
};

constexpr std::array<Prefix, 11> kPrefixes{{
    {"p", 1e-12},
    {"n", 1e-9},
    {"u", 1e-6},
    {"\xCE\xBC", 1e-6},  // U+03BC Greek small letter mu
    {"\xC2\xB5", 1e-6},  // U+00B5 micro sign
    {"m", 1e-3},
    {"c", 1e-2},
    {"k", 1e3},
    {"M", 1e6},
    {"G", 1e9},
    {"T", 1e12},
}};

struct Unit {
  double factor = 1.0;
  Dimension dim;
  bool usesTon = false;  // contains the ambiguous "t"
};

// One unit symbol, possibly prefixed. `tonAsTnt` picks the reading of "t".
std::optional<Unit> lookupSymbol(std::string_view sym, bool tonAsTnt) {
  auto make = [tonAsTnt](const UnitDef& def, double prefix) {
    if (def.symbol == "t" && tonAsTnt) return Unit{prefix * kTonTnt, Dimension::Energy, true};
    return Unit{prefix * def.factor, def.dim, def.symbol == "t"};
  };
  // An exact symbol wins over a prefix reading ("m" is metre, "Pa" is pascal).
  for (const UnitDef& def : kUnits)
    if (def.symbol == sym) return make(def, 1.0);
  for (const Prefix& p : kPrefixes) {
    if (sym.size() <= p.symbol.size() || sym.substr(0, p.symbol.size()) != p.symbol) continue;
    const std::string_view rest = sym.substr(p.symbol.size());
    for (const UnitDef& def : kUnits)
      if (def.prefixable && def.symbol == rest) return make(def, p.factor);
  }
  return std::nullopt;
}

bool isSymbolChar(char c) {
  const auto u = static_cast<unsigned char>(c);
  return (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || u >= 0x80;  // UTF-8 for mu
}
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isSpace(char c) { return c == ' ' || c == '\t'; }

// Reads an optional integer exponent ("^3", "^-1", "3", "-2") at text[pos].
int readExponent(std::string_view text, std::size_t& pos, std::string_view whole) {
  if (pos < text.size() && text[pos] == '^')
    ++pos;
  else if (pos >= text.size() || !(isDigit(text[pos]) || text[pos] == '-'))
    return 1;
  const std::size_t start = pos;
  if (pos < text.size() && (text[pos] == '-' || text[pos] == '+')) ++pos;
  while (pos < text.size() && isDigit(text[pos])) ++pos;
  int value = 0;
  const char* first = text.data() + start + (text[start] == '+' ? 1 : 0);
  const auto [ptr, ec] = std::from_chars(first, text.data() + pos, value);
  if (ec != std::errc() || ptr != text.data() + pos)
    throw UnitError("bad exponent in '" + std::string(whole) + "'");
  return value;
}

// Evaluates a unit expression such as "km/s", "g/cm^3", "J / kg / K", "kg m^-3".
Unit parseUnitExpression(std::string_view text, bool tonAsTnt, std::string_view whole) {
  Unit result;
  std::size_t pos = 0;
  bool divide = false;
  bool expectFactor = true;  // after '*' or '/' a unit must follow
  bool sawFactor = false;
  while (pos < text.size()) {
    const char c = text[pos];
    if (isSpace(c)) {
      ++pos;
      continue;
    }
    if (c == '*' || c == '/') {
      if (expectFactor && sawFactor)
        throw UnitError("two operators in a row in '" + std::string(whole) + "'");
      if (!sawFactor)
        throw UnitError("unit starts with '" + std::string(1, c) + "' in '" + std::string(whole) +
                        "'");
      divide = (c == '/');
      expectFactor = true;
      ++pos;
      continue;
    }
    if (!isSymbolChar(c))
      throw UnitError("unexpected '" + std::string(1, c) + "' in '" + std::string(whole) + "'");
    const std::size_t start = pos;
    while (pos < text.size() && isSymbolChar(text[pos])) ++pos;
    const std::string_view sym = text.substr(start, pos - start);
    const std::optional<Unit> unit = lookupSymbol(sym, tonAsTnt);
    if (!unit)
      throw UnitError("unknown unit '" + std::string(sym) + "' in '" + std::string(whole) + "'");
    int power = readExponent(text, pos, whole);
    if (divide) power = -power;
    result.factor *= std::pow(unit->factor, power);
    result.dim = result.dim * unit->dim.pow(power);
    result.usesTon = result.usesTon || unit->usesTon;
    divide = false;  // only the factor right after '/' divides
    expectFactor = false;
    sawFactor = true;
  }
  if (expectFactor && sawFactor)
    throw UnitError("unit ends with an operator in '" + std::string(whole) + "'");
  return result;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
  return s;
}

// Splits "<number><rest>" and returns the number.
double readNumber(std::string_view text, std::string_view& rest) {
  std::size_t skip = (!text.empty() && text.front() == '+') ? 1 : 0;
  double value = 0.0;
  const char* begin = text.data() + skip;
  const auto [ptr, ec] = std::from_chars(begin, text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range)
    throw UnitError("the number in '" + std::string(text) +
                    "' is outside the range of a double (about 1e-308 to 1e308)");
  if (ec != std::errc() || ptr == begin)
    throw UnitError("'" + std::string(text) + "' does not start with a number");
  if (!std::isfinite(value)) throw UnitError("'" + std::string(text) + "' is not finite");
  rest = text.substr(static_cast<std::size_t>(ptr - text.data()));
  return value;
}

}  // namespace

std::string siUnit(Dimension d) {
  if (const NamedDimension* n = findNamed(d)) return std::string(n->unit);
  std::string out;
  auto term = [&out](std::string_view sym, int power) {
    if (power == 0) return;
    if (!out.empty()) out += ' ';
    out += sym;
    if (power != 1) out += '^' + std::to_string(power);
  };
  term("kg", d.mass);
  term("m", d.length);
  term("s", d.time);
  term("K", d.temperature);
  term("rad", d.angle);
  return out;
}

std::string describeDimension(Dimension d) {
  if (const NamedDimension* n = findNamed(d)) {
    std::string out(n->description);
    if (!n->unit.empty()) out += " (" + std::string(n->unit) + ")";
    return out;
  }
  return "a quantity in " + siUnit(d);
}

std::string formatQuantity(double siValue, Dimension d) {
  std::ostringstream os;
  os << siValue;
  const std::string unit = siUnit(d);
  if (!unit.empty()) os << ' ' << unit;
  return os.str();
}

double parseQuantity(std::string_view text, Dimension expected) {
  const std::string_view whole = trim(text);
  std::string_view rest;
  const double number = readNumber(whole, rest);
  rest = trim(rest);
  if (rest.empty()) return number;  // a bare number is SI already
  // Degrees Celsius are an offset scale, not a factor: only a temperature standing alone may be
  // written in them ("20 degC" = 293.15 K, the ITS-90 offset); inside a compound unit they
  // would be ambiguous (a difference or a level?), so there K is asked for.
  if (rest == "degC" || rest == "\u00b0C") {
    if (expected != Dimension::Temperature)
      throw UnitError("expected " + describeDimension(expected) + ", got a temperature in '" +
                      std::string(whole) + "'");
    return number + 273.15;
  }
  if (rest.find("degC") != std::string_view::npos || rest.find("\u00b0C") != std::string_view::npos)
    throw UnitError("degrees Celsius are an offset scale, allowed only as a temperature on its "
                    "own (\"20 degC\"); write '" + std::string(whole) + "' with K");

  Unit unit = parseUnitExpression(rest, false, whole);
  if (unit.dim != expected && unit.usesTon) {
    // "t" read as tonne did not fit; the ton-of-TNT reading may (e.g. "100 kt" as an energy).
    const Unit tnt = parseUnitExpression(rest, true, whole);
    if (tnt.dim == expected) unit = tnt;
  }
  if (unit.dim != expected)
    throw UnitError("expected " + describeDimension(expected) + ", got " +
                    describeDimension(unit.dim) + " in '" + std::string(whole) + "'");
  return number * unit.factor;
}

}  // namespace ejecta
