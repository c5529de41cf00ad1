#pragma once
// What the radiation input files (geometry files, thermal studies, Whipple shield files) read
// beyond core's table reader (core/table_reader.hpp): 3-vectors, directions, positive and
// bounded values, lists of quantities, the shape-only keys. One copy, so the three readers cannot
// drift apart in what they accept or how they word an error.
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/table_reader.hpp"
#include "radiation/mesh.hpp"

namespace ejecta::radiation::input {

using config::TableReader;

// The TOML document of `text`; a syntax error is raised as "SOURCE:LINE: TOML syntax error: why".
toml::table parseToml(const std::string& text, const std::string& source, config::Context::Raise raise);

// A parsed input file with the Context its readers report through (the Context points into the
// tree, so the document stays where it was made).
class InputDocument {
 public:
  InputDocument(const std::string& text, const std::string& source, const config::SchemaTables& schema,
                config::Context::Raise raise)
      : root_(parseToml(text, source, raise)), ctx_(source, root_, schema, raise) {}
  InputDocument(const InputDocument&) = delete;
  InputDocument& operator=(const InputDocument&) = delete;
  const config::Context& context() const { return ctx_; }
  TableReader top() const { return TableReader(ctx_, root_, "", ""); }

 private:
  toml::table root_;
  config::Context ctx_;
};
// The whole file; a file that cannot be read is raised as "PATH: cannot open the <what>".
std::string readInputFile(const std::filesystem::path& path, const std::string& what,
                          config::Context::Raise raise);

// The table at `k` of `t` (empty when the key is absent: its defaults apply), read against the
// schema entry named `k` (a top-level table).
TableReader subTable(const TableReader& t, std::string_view k);

// A study's [study] table: its name (default: the file's stem) and description.
void readStudyTitle(const TableReader& top, std::string& name, std::string& description);

// [x, y, z], each a number (SI) or a quantity string of dimension `dim`.
std::optional<Vec3> optVec3(const TableReader& t, std::string_view k, Dimension dim);
Vec3 requireVec3(const TableReader& t, std::string_view k, Dimension dim);
Vec3 vec3At(const TableReader& t, const toml::node& n, const std::string& fullKey, Dimension dim);
// A dimensionless direction (not normalised); `fallback` when absent; the zero vector is rejected.
Vec3 direction(const TableReader& t, std::string_view k, const Vec3& fallback);

// A quantity that must be > 0 ("must be > 0"); optPositive gives `fallback` when absent.
double requirePositive(const TableReader& t, std::string_view k, Dimension dim);
double optPositive(const TableReader& t, std::string_view k, Dimension dim, double fallback);
// A dimensionless number in [lo, hi]; `range` words the bounds for the message ("(0, 1]").
double numberIn(const TableReader& t, std::string_view k, double fallback, double lo, double hi,
                const char* range);
// An integer in [lo, hi], `fallback` when absent.
long long integerIn(const TableReader& t, std::string_view k, long long fallback, long long lo,
                    long long hi);
// An array of quantities (empty when absent).
std::vector<double> quantityList(const TableReader& t, std::string_view k, Dimension dim);
std::vector<std::string> stringList(const TableReader& t, std::string_view k);

// Keys that only some shapes take: reject the others, so a mistyped shape cannot silently drop
// dimensions.
void onlyFor(const TableReader& t, std::initializer_list<std::string_view> keys, bool allowed,
             const std::string& shape);
// The `mesh` key as a path, relative paths taken from `base` (the input file's folder).
std::filesystem::path meshPath(const TableReader& t, const std::filesystem::path& base);

}  // namespace ejecta::radiation::input
