#pragma once
// A strict parameter dictionary over a TOML document (in the spirit of pbrt-v4's
// ParameterDictionary): typed look-ups with defaults, range checks, and a final report of every
// key nobody asked for. Every message names the file, line and column, the full dotted key, what
// was found and what was expected, e.g.
//   run.toml:12:9: box.width = -0.3 (a float): expected a number > 0 (m)
//
// Usage: load, apply --set overrides, read every parameter (each look-up marks its key as used and
// records the final value), then report_unused() and save resolved_toml() with the results.
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"

namespace trapdem {

// An interval of allowed numbers, with its description for messages ("> 0", "in (0, 1]").
struct Range {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_inclusive = true;
  bool upper_inclusive = true;

  bool contains(double x) const;
  std::string describe() const;   // "" for the unbounded range

  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), false, true}; }       // > 0
  static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity(), true, true}; }    // >= 0
  static Range unit_open_closed() { return {0.0, 1.0, false, true}; }                                   // (0, 1]
  static Range unit_closed() { return {0.0, 1.0, true, true}; }                                         // [0, 1]
  static Range closed(double lo, double hi) { return {lo, hi, true, true}; }                            // [lo, hi]
  static Range open_closed(double lo, double hi) { return {lo, hi, false, true}; }                      // (lo, hi]
  static Range at_least(double lo) { return {lo, std::numeric_limits<double>::infinity(), true, true}; }
};

// One configuration document, or a view of one of its tables (get_table): views share the
// document, the record of used keys and the resolved values.
class Config {
 public:
  // Parses a TOML file or text; `source_name` stands for the file name in messages.
  // Throws InputError ("<file>:<line>:<column>: <what the parser says>") on a syntax error and
  // FileError if the file cannot be read.
  static Config load_file(const std::string& path);
  static Config parse(std::string_view text, std::string source_name);

  // Applies "dotted.key=value" on top of the document (for --set and parameter studies). The value
  // is read as a TOML value (1e-3, true, "text", [1, 2]); if it is not valid TOML it is taken as a
  // bare string (--set stage=lowering). Missing tables are created. Messages about such a key name
  // the override instead of a file line. Throws InputError on a malformed assignment.
  void apply_override(std::string_view assignment);
  void apply_overrides(const std::vector<std::string>& assignments);

  // Typed look-ups. `key` may be dotted ("box.width"), relative to this view. A missing key gives
  // the default; a present one must have the right type (a float key accepts an integer) and lie
  // in `range`. `unit` documents the value (SI) in messages and in the resolved output.
  double get_double(std::string_view key, double default_value, std::string_view unit = {}, Range range = {});
  std::int64_t get_int(std::string_view key, std::int64_t default_value, Range range = {});
  bool get_bool(std::string_view key, bool default_value);
  std::string get_string(std::string_view key, std::string_view default_value);
  // A string that must be one of `choices` (model names and the like).
  std::string get_choice(std::string_view key, std::string_view default_value, const std::vector<std::string>& choices);
  // Arrays of numbers (T = double or std::int64_t) or strings (T = std::string); every element is
  // checked against `range` (numbers only).
  template <class T>
  std::vector<T> get_vector(std::string_view key, const std::vector<T>& default_value, std::string_view unit = {},
                            Range range = {});

  // Required variants: a missing key is an error naming what is expected.
  double require_double(std::string_view key, std::string_view unit = {}, Range range = {});
  std::int64_t require_int(std::string_view key, Range range = {});
  bool require_bool(std::string_view key);
  std::string require_string(std::string_view key);
  // A required path (a file or folder the configuration names, e.g. packing.from), returned
  // absolute. A relative path written in a configuration file is taken from that file's folder (as
  // an #include is), so the file works from any working folder; one given by an override (--set)
  // or in a document parsed from text is taken from the working folder. The resolved output records
  // the absolute path, so that a resolved.toml run again from elsewhere names the same file.
  std::string require_path(std::string_view key);
  template <class T>
  std::vector<T> require_vector(std::string_view key, std::string_view unit = {}, Range range = {});

  // A view of a sub-table (it need not exist: its look-ups then give their defaults). Throws if
  // `key` holds something other than a table.
  // A table of number rows with `columns` entries each (a grading: [[d, percent], ...]);
  // `row_meaning` names the columns for the error message ("diameter in m, percent passing").
  std::vector<std::vector<double>> require_rows(std::string_view key, std::size_t columns, std::string_view row_meaning);

  Config get_table(std::string_view key);
  bool has(std::string_view key) const;
  bool is_table(std::string_view key) const;   // present and a table
  // The names of a table's entries as written, in the order the document writes them (for tables
  // keyed by user names, e.g. materials or a study's cases); entries added by overrides come last.
  std::vector<std::string> keys(std::string_view table_key = {}) const;
  // The value of a key that must be present and not a table, as TOML text ("0.5", "\"demo\"",
  // "[0.0, 0.01]"), marked as used: to carry a value from one document into another as an override
  // (a study's per-case settings). Throws InputError if missing or a table.
  std::string require_value_text(std::string_view key);

  // An InputError for a rule that spans several keys (trapdoor wider than the box, time step above
  // the critical one): "<file>:<line>:<col>: <full key> = <value>: expected <expected>".
  InputError error(std::string_view key, std::string_view expected) const;

  // Errors together: after collect_errors(), a look-up whose value is refused (wrong type, out of
  // range, missing) records its message and gives the default, and fail() records a rule
  // violation, so that reading goes on and every key is seen. throw_errors() then reports them in
  // one InputError: unknown keys first, then wrong values, then rule violations. Without
  // collect_errors() (the default), look-ups and fail() throw at once.
  void collect_errors();
  void fail(std::string_view key, std::string_view expected);  // a rule violation (see error())
  bool has_errors() const;  // a value or rule error recorded so far (unknown keys not counted)
  void throw_errors() const;

  // Throws InputError listing every key of the document that no look-up asked for, each with its
  // file:line:column (and a close match among the known keys, if any). Call after reading all.
  void report_unused() const;
  std::vector<std::string> unused_keys() const;   // full dotted keys, document order

  // Adds a value computed from the configuration to the resolved output (e.g. "derived.time_step").
  // Keys are absolute (the view's prefix is not applied). The top-level table "derived" is
  // output only: report_unused() ignores it, so a resolved.toml can be run again as it is.
  void add_derived(std::string_view key, double value, std::string_view unit = {});
  void add_derived(std::string_view key, std::int64_t value, std::string_view unit = {});
  void add_derived(std::string_view key, std::string_view value);

  // Every looked-up key with its final value (defaults filled in) and the derived values, as TOML
  // text with units as trailing comments. Parsing it back gives the same values.
  std::string resolved_toml() const;

  const std::string& source_name() const;
  const std::string& prefix() const { return prefix_; }  // "" or "box." for a view

  struct State;  // the shared document (config.cpp)

 private:
  Config(std::shared_ptr<State> state, std::string prefix) : state_(std::move(state)), prefix_(std::move(prefix)) {}
  std::string full_key(std::string_view key) const;
  std::shared_ptr<State> state_;
  std::string prefix_;
};

}  // namespace trapdem
