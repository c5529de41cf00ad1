#include "radiation/study_input.hpp"

#include <fstream>
#include <sstream>

namespace ejecta::radiation::input {

namespace fs = std::filesystem;

toml::table parseToml(const std::string& text, const std::string& source, config::Context::Raise raise) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    raise(source + ":" + std::to_string(e.source().begin.line) +
          ": TOML syntax error: " + std::string(e.description()));
    throw InputError("unreachable: Raise returned");
  }
}

std::string readInputFile(const fs::path& path, const std::string& what, config::Context::Raise raise) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) raise(path.string() + ": is a directory, not a " + what);
  std::ifstream in(path, std::ios::binary);
  if (!in) raise(path.string() + ": cannot open the " + what);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TableReader subTable(const TableReader& t, std::string_view k) {
  static const toml::table empty;
  const toml::table* sub = t.optTable(k);
  return TableReader(t.context(), sub ? *sub : empty, t.key(k), t.key(k));
}

void readStudyTitle(const TableReader& top, std::string& name, std::string& description) {
  const TableReader study = subTable(top, "study");
  // Without a name, the file's: its stem, or a shipped file's ("shipped scene 'whipple/haiv'"
  // gives haiv, not its closing quote).
  std::string stem = fs::path(top.context().source()).stem().string();
  while (!stem.empty() && stem.back() == '\'') stem.pop_back();
  name = study.optString("name").value_or(stem);
  description = study.optString("description").value_or("");
}

Vec3 vec3At(const TableReader& t, const toml::node& n, const std::string& fullKey, Dimension dim) {
  const toml::array* a = n.as_array();
  if (!a || a->size() != 3) {
    std::string got = ", got ";
    got += a ? std::to_string(a->size()) + " components" : config::typeName(n);
    t.context().fail(&n, fullKey, "expected an array of 3 numbers [x, y, z]" + got);
  }
  Vec3 v{};
  for (std::size_t i = 0; i < 3; ++i) v[i] = t.quantityOf(*a->get(i), fullKey + "[" + std::to_string(i) + "]", dim);
  return v;
}

std::optional<Vec3> optVec3(const TableReader& t, std::string_view k, Dimension dim) {
  const toml::node* n = t.find(k);
  if (!n) return std::nullopt;
  return vec3At(t, *n, t.key(k), dim);
}

Vec3 requireVec3(const TableReader& t, std::string_view k, Dimension dim) {
  return vec3At(t, t.require(k), t.key(k), dim);
}

Vec3 direction(const TableReader& t, std::string_view k, const Vec3& fallback) {
  const std::optional<Vec3> v = optVec3(t, k, Dimension::None);
  if (!v) return fallback;
  if (vec3::norm(*v) == 0.0) t.fail(k, "must not be the zero vector");
  return *v;
}

double requirePositive(const TableReader& t, std::string_view k, Dimension dim) {
  const double x = t.requireQuantity(k, dim);
  if (!(x > 0.0)) t.fail(k, "must be > 0");
  return x;
}

double optPositive(const TableReader& t, std::string_view k, Dimension dim, double fallback) {
  return t.has(k) ? requirePositive(t, k, dim) : fallback;
}

double numberIn(const TableReader& t, std::string_view k, double fallback, double lo, double hi,
                const char* range) {
  const double x = t.optQuantity(k, Dimension::None).value_or(fallback);
  if (!(x >= lo && x <= hi)) t.fail(k, std::string("must be in ") + range);
  return x;
}

long long integerIn(const TableReader& t, std::string_view k, long long fallback, long long lo, long long hi) {
  const std::optional<long> v = t.optInteger(k);
  if (!v) return fallback;
  if (*v < lo || *v > hi) t.fail(k, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return *v;
}

std::vector<double> quantityList(const TableReader& t, std::string_view k, Dimension dim) {
  std::vector<double> out;
  const toml::node* n = t.find(k);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) t.fail(k, "expected an array, got " + config::typeName(*n));
  for (std::size_t i = 0; i < a->size(); ++i)
    out.push_back(t.quantityOf(*a->get(i), t.key(k) + "[" + std::to_string(i) + "]", dim));
  return out;
}

std::vector<std::string> stringList(const TableReader& t, std::string_view k) {
  return t.optStringArray(k).value_or(std::vector<std::string>{});
}

void onlyFor(const TableReader& t, std::initializer_list<std::string_view> keys, bool allowed,
             const std::string& shape) {
  if (allowed) return;
  for (std::string_view k : keys)
    if (t.has(k)) t.fail(k, "not used by shape '" + shape + "'");
}

fs::path meshPath(const TableReader& t, const fs::path& base) {
  const fs::path p = t.requireString("mesh");
  if (p.empty()) t.fail("mesh", "must not be empty");
  return p.is_absolute() ? p : base / p;
}

}  // namespace ejecta::radiation::input
