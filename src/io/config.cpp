#include "io/config.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "core/nearest_name.hpp"
#include "core/text_escape.hpp"
#include "io/text.hpp"

namespace trapdem {

struct Config::State {
  std::string source;                                   // file name for messages
  std::filesystem::path folder;                         // the file's folder, absolute (empty: parsed from text)
  toml::table document;
  std::map<std::string, std::string> override_origin;   // full key -> "--set key=value"
  std::set<std::string> used;                           // full keys asked for (tables included)
  toml::table resolved;                                 // final values of the keys asked for
  std::map<std::string, std::string> units;             // full key -> unit, for comments
  bool collecting = false;                              // collect_errors() called
  std::vector<std::string> value_errors, rule_errors;   // recorded while collecting
};

namespace {

std::vector<std::string> split_key(std::string_view key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    parts.emplace_back(key.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start));
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  return parts;
}

std::string join_key(const std::vector<std::string>& parts, std::size_t count) {
  std::string out;
  for (std::size_t i = 0; i < count; ++i) out += (i ? "." : "") + parts[i];
  return out;
}

bool is_bare_key(std::string_view key) {
  return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(first, last - first + 1));
}

const char* type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    default: return "nothing";
  }
}

// TOML text of a value (round-trips: shortest representation that reads back the same double).
std::string format_double(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  std::string s = fmt::format("{}", x);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}


std::string format_value(const toml::node& node) {
  if (auto v = node.as_floating_point()) return format_double(v->get());
  if (auto v = node.as_integer()) return std::to_string(v->get());
  if (auto v = node.as_boolean()) return v->get() ? "true" : "false";
  if (auto v = node.as_string()) return trapdem::quoted(v->get());
  if (auto a = node.as_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < a->size(); ++i) out += (i ? ", " : "") + format_value(*a->get(i));
    return out + "]";
  }
  std::ostringstream os;  // dates, times, tables: toml++'s own formatting
  node.visit([&](const auto& n) { os << n; });
  return os.str();
}

std::string describe_found(const toml::node& node) {
  std::string text = node.is_table() ? "{...}" : format_value(node);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return fmt::format("{} ({})", text, type_name(node));
}

std::string expectation(std::string_view what, std::string_view unit, const Range& range) {
  std::string out(what);
  const std::string bounds = range.describe();
  if (!bounds.empty()) out += " " + bounds;
  if (!unit.empty()) out += fmt::format(" ({})", unit);
  return out;
}

// Inserts `value` at the dotted `key` of `root`, creating tables on the way.
void insert_at(toml::table& root, std::string_view key, toml::node&& value) {
  const std::vector<std::string> parts = split_key(key);
  toml::table* table = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* next = table->get(parts[i]);
    if (!next || !next->is_table()) {
      table->insert_or_assign(parts[i], toml::table{});
      next = table->get(parts[i]);
    }
    table = next->as_table();
  }
  std::move(value).visit([&](auto&& v) { table->insert_or_assign(parts.back(), std::move(v)); });
}

// Tables nested deeper than this are refused before toml++ sees the text: it builds (and frees)
// nested tables recursively, and 50 000 levels of `[a.a.a...]` overflowed its stack (issue 14).
// The deepest key of a real configuration is 3 levels (walls.front.static_friction); a study's
// per-case settings add 3.
constexpr int kMaxNesting = 64;

// Skips a string starting at text[i] (a quote), basic or literal, single- or multi-line; returns the
// index just past its end (or text.size()), counting the newlines it passes.
std::size_t skip_string(std::string_view text, std::size_t i, int& line) {
  const char quote = text[i];
  const bool multi = text.substr(i, 3) == std::string(3, quote);
  std::size_t j = i + (multi ? 3 : 1);
  while (j < text.size()) {
    const char c = text[j];
    if (c == '\\' && quote == '"') {
      j += 2;
      continue;
    }
    if (c == '\n') {
      ++line;
      if (!multi) return j;  // unterminated: toml++ reports it
    }
    if (c == quote && (!multi || text.substr(j, 3) == std::string(3, quote))) return j + (multi ? 3 : 1);
    ++j;
  }
  return j;
}

// A fast scan of the text for how deep its tables and values nest: a [header] counts its dotted
// parts, a key its dotted parts below the header and the values that hold it, an array or inline
// table one level more than what holds it. Strings and comments are skipped. Throws InputError
// "<file>:<line>: ... nested N deep" at the first place deeper than kMaxNesting.
void check_nesting(std::string_view text, const std::string& source) {
  std::vector<int> open;     // per open [ or {: the levels it adds (its key's parts + 1)
  std::vector<char> kind;    // '[' or '{'
  int nested = 0;            // sum of `open`
  int header = 0;            // parts of the current [header]
  int line = 1;
  bool key_mode = true;      // reading a key (line start, after '{' or ',' in an inline table)
  int dots = 0;              // dots in the key read so far
  int pending = 0;           // parts of the key whose value comes next
  bool line_start = true;
  auto fail = [&](int depth) {
    throw InputError(fmt::format("{}:{}: tables and arrays nested {} levels deep: expected at most {} (a generated "
                                 "or damaged file?)", source, line, depth, kMaxNesting));
  };
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      if (open.empty()) {
        key_mode = true;
        dots = 0;
        line_start = true;
      }
      ++i;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
      continue;
    }
    if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    }
    if (c == '"' || c == '\'') {
      i = skip_string(text, i, line);
      line_start = false;
      continue;
    }
    if (line_start && open.empty() && c == '[') {  // a [header] or [[header]]: its dotted parts
      int parts = 1;
      while (i < text.size() && text[i] != '\n' && text[i] != ']') {
        if (text[i] == '"' || text[i] == '\'') {
          i = skip_string(text, i, line);
          continue;
        }
        if (text[i] == '.') ++parts;
        ++i;
      }
      header = parts;
      if (header > kMaxNesting) fail(header);
      while (i < text.size() && text[i] != '\n' && text[i] != '#') ++i;
      line_start = false;
      continue;
    }
    line_start = false;
    if (key_mode) {
      if (c == '.') ++dots;
      if (c == '=') {
        pending = dots + 1;
        if (header + nested + pending > kMaxNesting) fail(header + nested + pending);
        key_mode = false;
        dots = 0;
      } else if (c == '}' && !kind.empty() && kind.back() == '{') {  // an empty inline table
        nested -= open.back();
        open.pop_back();
        kind.pop_back();
        key_mode = false;
      }
      ++i;
      continue;
    }
    if (c == '[' || c == '{') {
      const int levels = std::max(pending, 0) + 1;
      pending = 0;
      open.push_back(levels);
      kind.push_back(c);
      nested += levels;
      if (header + nested > kMaxNesting) fail(header + nested);
      key_mode = c == '{';
      dots = 0;
    } else if ((c == ']' || c == '}') && !open.empty()) {
      nested -= open.back();
      open.pop_back();
      kind.pop_back();
    } else if (c == ',' && !kind.empty()) {
      key_mode = kind.back() == '{';
      dots = 0;
      pending = 0;
    } else {
      pending = 0;
    }
    ++i;
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------------
bool Range::contains(double x) const {
  if (std::isnan(x)) return false;
  const bool above = lower_inclusive ? x >= lower : x > lower;
  const bool below = upper_inclusive ? x <= upper : x < upper;
  return above && below;
}

std::string Range::describe() const {
  const bool has_lower = std::isfinite(lower), has_upper = std::isfinite(upper);
  if (has_lower && has_upper)
    return fmt::format("in {}{}, {}{}", lower_inclusive ? '[' : '(', lower, upper, upper_inclusive ? ']' : ')');
  if (has_lower) return fmt::format("{} {}", lower_inclusive ? ">=" : ">", lower);
  if (has_upper) return fmt::format("{} {}", upper_inclusive ? "<=" : "<", upper);
  return "";
}

// ---------------------------------------------------------------------------------------------
Config Config::load_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("cannot read the configuration file {}: {}", path, std::strerror(errno)));
  std::ostringstream text;
  text << in.rdbuf();
  Config c = parse(text.str(), path);
  c.state_->folder = std::filesystem::absolute(path).parent_path();
  return c;
}

Config Config::parse(std::string_view text, std::string source_name) {
  auto state = std::make_shared<State>();
  state->source = std::move(source_name);
  check_nesting(text, state->source);
  try {
    state->document = toml::parse(text, state->source);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", state->source, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
  return Config(std::move(state), "");
}

const std::string& Config::source_name() const { return state_->source; }

std::string Config::full_key(std::string_view key) const { return prefix_ + std::string(key); }

void Config::apply_override(std::string_view assignment) {
  const std::string origin = fmt::format("--set {}", assignment);
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos)
    throw InputError(fmt::format("{}: expected key.path=value", origin));
  const std::string key = full_key(trim(assignment.substr(0, eq)));
  const std::string text = trim(assignment.substr(eq + 1));
  const std::vector<std::string> parts = split_key(key);
  for (const std::string& part : parts)
    if (!is_bare_key(part))
      throw InputError(fmt::format("{}: '{}' is not a key path (letters, digits, _ and - separated by dots)", origin, key));

  if (parts.size() > std::size_t(kMaxNesting))
    throw InputError(fmt::format("{}: a key {} levels deep: expected at most {}", origin, parts.size(), kMaxNesting));
  const std::string value_text = "value = " + text;
  toml::table holder;
  try {
    check_nesting(value_text, origin);
    holder = toml::parse(std::string_view(value_text), std::string_view("--set"));
  } catch (const toml::parse_error&) {
    holder.insert_or_assign("value", text);  // not TOML: a bare word is meant as a string
  } catch (const InputError&) {
    holder.insert_or_assign("value", text);  // nested too deep to be a value of ours: a string, refused by its key
  }
  if (!holder.get("value") || holder.size() != 1) {  // "1\nx = 2" and the like
    holder = toml::table{};
    holder.insert_or_assign("value", text);
  }
  toml::node& value = *holder.get("value");

  // Refuse to turn a value into a table or a table into a value: that is a wrong key, not an override.
  toml::table* table = &state_->document;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* next = table->get(parts[i]);
    if (!next) break;
    if (!next->is_table())
      throw InputError(fmt::format("{}: {} is {} in {}, not a table", origin, join_key(parts, i + 1),
                                   type_name(*next), state_->source));
    table = next->as_table();
  }
  if (const toml::node* existing = state_->document.at_path(key).node(); existing && existing->is_table() != value.is_table())
    throw InputError(fmt::format("{}: {} is {} in {}", origin, key, type_name(*existing), state_->source));
  insert_at(state_->document, key, std::move(value));
  state_->override_origin[key] = origin;
}

void Config::apply_overrides(const std::vector<std::string>& assignments) {
  for (const std::string& a : assignments) apply_override(a);
}

// ---------------------------------------------------------------------------------------------
namespace {

// Where a key's value came from: "file:line:column" or "--set key=value".
std::string location(const Config::State& s, const std::string& key, const toml::node* node) {
  const std::vector<std::string> parts = split_key(key.substr(0, key.find('[')));  // "a.b[2]": element of a.b
  for (std::size_t n = parts.size(); n > 0; --n) {
    auto it = s.override_origin.find(join_key(parts, n));
    if (it != s.override_origin.end()) return it->second;
  }
  if (node && node->source().begin)
    return fmt::format("{}:{}:{}", s.source, node->source().begin.line, node->source().begin.column);
  return s.source;
}

// The node at a dotted key, or nullptr. An intermediate that is not a table is an error.
const toml::node* find(const Config::State& s, const std::string& key) {
  const std::vector<std::string> parts = split_key(key);
  const toml::table* table = &s.document;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const toml::node* node = table->get(parts[i]);
    if (!node) return nullptr;
    if (i + 1 == parts.size()) return node;
    if (!node->is_table()) {
      const std::string partial = join_key(parts, i + 1);
      throw InputError(fmt::format("{}: {} = {}: expected a table (it holds {})", location(s, partial, node), partial,
                                   describe_found(*node), key));
    }
    table = node->as_table();
  }
  return nullptr;
}

[[noreturn]] void wrong(const Config::State& s, const std::string& key, const toml::node& node, const std::string& expected) {
  throw InputError(fmt::format("{}: {} = {}: expected {}", location(s, key, &node), key, describe_found(node), expected));
}

[[noreturn]] void missing(const Config::State& s, const std::string& key, const std::string& expected) {
  throw InputError(fmt::format("{}: missing required key {}: expected {}", s.source, key, expected));
}

void record(Config::State& s, const std::string& key, toml::node&& value, std::string_view unit) {
  s.used.insert(key);
  insert_at(s.resolved, key, std::move(value));
  if (!unit.empty()) s.units[key] = std::string(unit);
}

double number_of(const Config::State& s, const std::string& key, const toml::node& node, std::string_view unit,
                 const Range& range) {
  double x;
  if (auto f = node.as_floating_point()) x = f->get();
  else if (auto i = node.as_integer()) x = static_cast<double>(i->get());
  else wrong(s, key, node, expectation("a number", unit, range));
  // TOML has inf and nan; no key of ours means either (an unbounded range included): refused here,
  // once for every float key, rather than by each key's range.
  if (!std::isfinite(x)) wrong(s, key, node, expectation("a finite number", unit, range));
  if (!range.contains(x)) wrong(s, key, node, expectation("a number", unit, range));
  return x;
}

std::int64_t integer_of(const Config::State& s, const std::string& key, const toml::node& node, const Range& range) {
  auto i = node.as_integer();
  if (!i) wrong(s, key, node, expectation("an integer", {}, range));
  if (!range.contains(static_cast<double>(i->get()))) wrong(s, key, node, expectation("an integer", {}, range));
  return i->get();
}

template <class T>
T element_of(const Config::State& s, const std::string& key, const toml::node& node, std::string_view unit,
             const Range& range) {
  if constexpr (std::is_same_v<T, double>) return number_of(s, key, node, unit, range);
  else if constexpr (std::is_same_v<T, std::int64_t>) return integer_of(s, key, node, range);
  else {
    static_assert(std::is_same_v<T, std::string>, "get_vector<T>: T is double, std::int64_t or std::string");
    auto str = node.as_string();
    if (!str) wrong(s, key, node, "a string");
    return str->get();
  }
}

template <class T>
const char* element_name() {
  if constexpr (std::is_same_v<T, double>) return "numbers";
  else if constexpr (std::is_same_v<T, std::int64_t>) return "integers";
  else return "strings";
}

// A look-up's reading: its value, or (while collecting errors) the fallback with the refusal
// recorded. The key counts as used either way (it is a known key).
template <class Read, class T>
T guarded(Config::State& s, Read&& read, T fallback) {
  if (!s.collecting) return read();
  try {
    return read();
  } catch (const InputError& e) {
    // Once: every look-up below a value that should be a table meets the same refusal (find()'s
    // message then ends with the key looked up, " (it holds box.width)": compared without it).
    const std::string_view message = e.what();
    const std::string_view gist = message.substr(0, message.find(" (it holds "));
    const bool seen = std::any_of(s.value_errors.begin(), s.value_errors.end(), [&](const std::string& m) {
      return std::string_view(m).substr(0, m.find(" (it holds ")) == gist;
    });
    if (!seen) s.value_errors.emplace_back(message);
    return fallback;
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------------
double Config::get_double(std::string_view key, double default_value, std::string_view unit, Range range) {
  const std::string k = full_key(key);
  state_->used.insert(k);  // even if the value is then refused: it is a known key
  const double x = guarded(*state_, [&] {
    const toml::node* node = find(*state_, k);
    return node ? number_of(*state_, k, *node, unit, range) : default_value;
  }, default_value);
  record(*state_, k, toml::value<double>(x), unit);
  return x;
}

std::int64_t Config::get_int(std::string_view key, std::int64_t default_value, Range range) {
  const std::string k = full_key(key);
  state_->used.insert(k);  // even if the value is then refused: it is a known key
  const std::int64_t x = guarded(*state_, [&] {
    const toml::node* node = find(*state_, k);
    return node ? integer_of(*state_, k, *node, range) : default_value;
  }, default_value);
  record(*state_, k, toml::value<std::int64_t>(x), {});
  return x;
}

bool Config::get_bool(std::string_view key, bool default_value) {
  const std::string k = full_key(key);
  state_->used.insert(k);  // even if the value is then refused: it is a known key
  const bool x = guarded(*state_, [&] {
    const toml::node* node = find(*state_, k);
    if (!node) return default_value;
    auto b = node->as_boolean();
    if (!b) wrong(*state_, k, *node, "a boolean (true or false)");
    return b->get();
  }, default_value);
  record(*state_, k, toml::value<bool>(x), {});
  return x;
}

std::string Config::get_string(std::string_view key, std::string_view default_value) {
  const std::string k = full_key(key);
  state_->used.insert(k);  // even if the value is then refused: it is a known key
  const std::string x = guarded(*state_, [&] {
    const toml::node* node = find(*state_, k);
    return node ? element_of<std::string>(*state_, k, *node, {}, {}) : std::string(default_value);
  }, std::string(default_value));
  record(*state_, k, toml::value<std::string>(x), {});
  return x;
}

std::string Config::get_choice(std::string_view key, std::string_view default_value,
                               const std::vector<std::string>& choices) {
  const std::string k = full_key(key);
  std::string listed;
  for (const std::string& c : choices) listed += (listed.empty() ? "" : ", ") + trapdem::quoted(c);
  const std::string expected = "one of " + listed;
  state_->used.insert(k);  // even if the value is then refused: it is a known key
  const std::string x = guarded(*state_, [&] {
    const toml::node* node = find(*state_, k);
    if (!node) return std::string(default_value);
    auto str = node->as_string();
    if (!str || std::find(choices.begin(), choices.end(), str->get()) == choices.end()) wrong(*state_, k, *node, expected);
    return std::string(str->get());
  }, std::string(default_value));
  record(*state_, k, toml::value<std::string>(x), {});
  return x;
}

template <class T>
std::vector<T> Config::get_vector(std::string_view key, const std::vector<T>& default_value, std::string_view unit,
                                  Range range) {
  const std::string k = full_key(key);
  state_->used.insert(k);  // even if the value is then refused: it is a known key
  const std::vector<T> out = guarded(*state_, [&] {
    const toml::node* node = find(*state_, k);
    if (!node) return default_value;
    auto array = node->as_array();
    if (!array) wrong(*state_, k, *node, fmt::format("an array of {}", element_name<T>()));
    std::vector<T> values;
    for (std::size_t i = 0; i < array->size(); ++i)
      values.push_back(element_of<T>(*state_, fmt::format("{}[{}]", k, i), *array->get(i), unit, range));
    return values;
  }, default_value);
  toml::array resolved;
  for (const T& x : out) resolved.push_back(x);
  record(*state_, k, std::move(resolved), unit);
  return out;
}

template std::vector<double> Config::get_vector(std::string_view, const std::vector<double>&, std::string_view, Range);
template std::vector<std::int64_t> Config::get_vector(std::string_view, const std::vector<std::int64_t>&,
                                                      std::string_view, Range);
template std::vector<std::string> Config::get_vector(std::string_view, const std::vector<std::string>&,
                                                     std::string_view, Range);

double Config::require_double(std::string_view key, std::string_view unit, Range range) {
  return guarded(*state_, [&] {
    if (!has(key)) missing(*state_, full_key(key), expectation("a number", unit, range));
    return get_double(key, 0.0, unit, range);
  }, 0.0);
}

std::int64_t Config::require_int(std::string_view key, Range range) {
  return guarded(*state_, [&] {
    if (!has(key)) missing(*state_, full_key(key), expectation("an integer", {}, range));
    return get_int(key, 0, range);
  }, std::int64_t{0});
}

bool Config::require_bool(std::string_view key) {
  return guarded(*state_, [&] {
    if (!has(key)) missing(*state_, full_key(key), "a boolean (true or false)");
    return get_bool(key, false);
  }, false);
}

std::string Config::require_string(std::string_view key) {
  return guarded(*state_, [&] {
    if (!has(key)) missing(*state_, full_key(key), "a string");
    return get_string(key, "");
  }, std::string());
}

std::string Config::require_path(std::string_view key) {
  const std::string text = require_string(key);
  if (text.empty() || std::filesystem::path(text).is_absolute()) return text;
  const std::string k = full_key(key);
  // Overridden: the key itself or a table above it set by an override (location() reads it alike).
  bool overridden = false;
  const std::vector<std::string> parts = split_key(k);
  for (std::size_t n = parts.size(); n > 0 && !overridden; --n)
    overridden = state_->override_origin.count(join_key(parts, n)) > 0;
  const std::filesystem::path base =
      overridden || state_->folder.empty() ? std::filesystem::current_path() : state_->folder;
  const std::string absolute = (base / text).lexically_normal().string();
  record(*state_, k, toml::value<std::string>(absolute), {});
  return absolute;
}

template <class T>
std::vector<T> Config::require_vector(std::string_view key, std::string_view unit, Range range) {
  return guarded(*state_, [&] {
    if (!has(key))
      missing(*state_, full_key(key), expectation(fmt::format("an array of {}", element_name<T>()), unit, range));
    return get_vector<T>(key, {}, unit, range);
  }, std::vector<T>{});
}

std::vector<std::vector<double>> Config::require_rows(std::string_view key, std::size_t columns,
                                                      std::string_view row_meaning) {
  const std::string k = full_key(key);
  const std::string expected = fmt::format("an array of rows, each [{}]", row_meaning);
  state_->used.insert(k);
  return guarded(*state_, [&] {
  if (!has(key)) missing(*state_, k, expected);
  const toml::node* node = find(*state_, k);
  auto array = node->as_array();
  if (!array || array->empty()) wrong(*state_, k, *node, expected);
  std::vector<std::vector<double>> rows;
  toml::array resolved;
  for (std::size_t r = 0; r < array->size(); ++r) {
    const std::string row_key = fmt::format("{}[{}]", k, r);
    auto row = array->get(r)->as_array();
    if (!row || row->size() != columns) wrong(*state_, row_key, *array->get(r), fmt::format("[{}]", row_meaning));
    std::vector<double> values;
    toml::array resolved_row;
    for (std::size_t c = 0; c < columns; ++c) {
      values.push_back(number_of(*state_, fmt::format("{}[{}]", row_key, c), *row->get(c), {}, Range::any()));
      resolved_row.push_back(values.back());
    }
    rows.push_back(std::move(values));
    resolved.push_back(std::move(resolved_row));
  }
  record(*state_, k, std::move(resolved), {});
  return rows;
  }, std::vector<std::vector<double>>{});
}

template std::vector<double> Config::require_vector(std::string_view, std::string_view, Range);
template std::vector<std::int64_t> Config::require_vector(std::string_view, std::string_view, Range);
template std::vector<std::string> Config::require_vector(std::string_view, std::string_view, Range);

Config Config::get_table(std::string_view key) {
  const std::string k = full_key(key);
  state_->used.insert(k);  // even if the value is then refused: it is a known key
  guarded(*state_, [&] {
    const toml::node* node = find(*state_, k);
    if (node && !node->is_table()) wrong(*state_, k, *node, "a table");
    return true;
  }, false);
  return Config(state_, k + ".");
}

bool Config::has(std::string_view key) const {
  return guarded(*state_, [&] { return find(*state_, full_key(key)) != nullptr; }, false);
}

std::vector<std::string> Config::keys(std::string_view table_key) const {
  const toml::table* table = &state_->document;
  const std::string k = table_key.empty() ? (prefix_.empty() ? "" : prefix_.substr(0, prefix_.size() - 1))
                                          : full_key(table_key);
  if (!k.empty()) {
    const toml::node* node = find(*state_, k);
    if (!node) return {};
    if (!node->is_table()) wrong(*state_, k, *node, "a table");
    table = node->as_table();
  }
  // toml++ keeps a table sorted by name: restore the document's order from the source positions
  // (nodes made by overrides have none, line 0, and go last in name order).
  std::vector<std::pair<toml::source_position, std::string>> entries;
  const std::string prefix = k.empty() ? "" : k + ".";
  for (const auto& [name, node] : *table) {
    toml::source_position at = name.source().begin;
    if (!at) at = node.source().begin;
    if (!at || state_->override_origin.count(prefix + std::string(name.str())))
      at = {std::numeric_limits<toml::source_index>::max(), 0};
    entries.emplace_back(at, std::string(name.str()));
  }
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    return a.first.line != b.first.line ? a.first.line < b.first.line : a.first.column < b.first.column;
  });
  std::vector<std::string> out;
  for (auto& e : entries) out.push_back(std::move(e.second));
  return out;
}

bool Config::is_table(std::string_view key) const {
  const toml::node* node = find(*state_, full_key(key));
  return node && node->is_table();
}

std::string Config::require_value_text(std::string_view key) {
  const std::string k = full_key(key);
  state_->used.insert(k);
  const toml::node* node = find(*state_, k);
  if (!node) missing(*state_, k, "a value");
  if (node->is_table()) wrong(*state_, k, *node, "a value (number, string, boolean or array), not a table");
  return format_value(*node);
}

InputError Config::error(std::string_view key, std::string_view expected) const {
  const std::string k = full_key(key);
  if (const toml::node* node = find(*state_, k))
    return InputError(fmt::format("{}: {} = {}: expected {}", location(*state_, k, node), k, describe_found(*node), expected));
  if (const toml::node* resolved = state_->resolved.at_path(k).node())
    return InputError(fmt::format("{}: {} = {} (the default): expected {}", state_->source, k, describe_found(*resolved),
                                  expected));
  return InputError(fmt::format("{}: {}: expected {}", state_->source, k, expected));
}

void Config::collect_errors() { state_->collecting = true; }

void Config::fail(std::string_view key, std::string_view expected) {
  InputError e = error(key, expected);
  if (!state_->collecting) throw e;
  state_->rule_errors.emplace_back(e.what());
}

bool Config::has_errors() const { return !state_->value_errors.empty() || !state_->rule_errors.empty(); }

// ---------------------------------------------------------------------------------------------
namespace {

// Derived values live under this table in resolved.toml; reading such a file back must not fail.
constexpr const char* kDerivedTable = "derived";

struct Unknown {
  std::string key;
  const toml::node* node;
};

// Depth first in the document's (name) order, with an explicit stack: the depth of user data does
// not reach the call stack (check_nesting bounds it too).
void collect_unused(const Config::State& s, const toml::table& root, std::vector<Unknown>& out) {
  struct Level {
    const toml::table* table;
    toml::table::const_iterator next;
    std::string prefix;
  };
  std::vector<Level> stack;
  stack.push_back({&root, root.begin(), ""});
  while (!stack.empty()) {
    Level& level = stack.back();
    if (level.next == level.table->end()) {
      stack.pop_back();
      continue;
    }
    const auto entry = level.next++;  // toml++'s iterator holds the pair it dereferences to: keep it
    const auto& [name, node] = *entry;
    const std::string key = level.prefix + std::string(name.str());
    if (key == kDerivedTable) continue;  // output of an earlier run (resolved.toml read again)
    if (const toml::table* sub = node.as_table(); sub && !sub->empty()) {
      stack.push_back({sub, sub->begin(), key + "."});  // invalidates `level`
    } else if (!s.used.count(key)) {
      out.push_back({key, &node});
    }
  }
}

// A known key close to an unknown one (a typo): same table, small edit distance.
std::string suggestion(const Config::State& s, const std::string& unknown) {
  const std::size_t dot = unknown.rfind('.');
  const std::string parent = dot == std::string::npos ? "" : unknown.substr(0, dot + 1);
  const std::string leaf = unknown.substr(parent.size());
  std::vector<std::string> siblings;  // the known keys beside it, by their last part
  for (const std::string& known : s.used) {
    if (known.compare(0, parent.size(), parent) != 0) continue;
    const std::string known_leaf = known.substr(parent.size());
    if (known_leaf.find('.') == std::string::npos) siblings.push_back(known_leaf);
  }
  const std::string best = nearest_name(leaf, siblings);
  return best.empty() ? "" : parent + best;
}

}  // namespace

std::vector<std::string> Config::unused_keys() const {
  std::vector<Unknown> unknown;
  collect_unused(*state_, state_->document, unknown);
  std::vector<std::string> out;
  for (const Unknown& u : unknown) out.push_back(u.key);
  return out;
}

namespace {

// The unknown keys' part of a report ("" if none).
std::string unknown_keys_message(const Config::State& s) {
  std::vector<Unknown> unknown;
  collect_unused(s, s.document, unknown);
  if (unknown.empty()) return "";
  std::string message = fmt::format("{}: {} unknown key{} (misspelt, or not used by this program):", s.source,
                                    unknown.size(), unknown.size() == 1 ? "" : "s");
  for (const Unknown& u : unknown) {
    message += fmt::format("\n  {}: unknown key {}", location(s, u.key, u.node), u.key);
    const std::string close = suggestion(s, u.key);
    if (!close.empty()) message += fmt::format(" (did you mean {}?)", close);
  }
  return message;
}

}  // namespace

void Config::report_unused() const {
  const std::string message = unknown_keys_message(*state_);
  if (!message.empty()) throw InputError(message);
}

void Config::throw_errors() const {
  std::vector<std::string> parts;
  if (std::string unknown = unknown_keys_message(*state_); !unknown.empty()) parts.push_back(std::move(unknown));
  for (const auto* errors : {&state_->value_errors, &state_->rule_errors})
    parts.insert(parts.end(), errors->begin(), errors->end());
  if (parts.empty()) return;
  std::string message = parts.front();
  for (std::size_t i = 1; i < parts.size(); ++i) message += "\n" + parts[i];
  throw InputError(message);
}

// ---------------------------------------------------------------------------------------------
void Config::add_derived(std::string_view key, double value, std::string_view unit) {
  insert_at(state_->resolved, key, toml::value<double>(value));
  if (!unit.empty()) state_->units[std::string(key)] = std::string(unit);
}

void Config::add_derived(std::string_view key, std::int64_t value, std::string_view unit) {
  insert_at(state_->resolved, key, toml::value<std::int64_t>(value));
  if (!unit.empty()) state_->units[std::string(key)] = std::string(unit);
}

void Config::add_derived(std::string_view key, std::string_view value) {
  insert_at(state_->resolved, key, toml::value<std::string>(std::string(value)));
}

namespace {

std::string key_text(std::string_view key) { return is_bare_key(key) ? std::string(key) : quoted(key); }

// Values of a table first, then its sub-tables under [headers]: the layout people write by hand.
void emit_table(const Config::State& s, const toml::table& table, const std::string& path, std::string& out) {
  bool has_values = false;
  for (const auto& [name, node] : table) has_values |= !node.is_table();
  if (has_values && !path.empty()) out += fmt::format("\n[{}]\n", path);
  for (const auto& [name, node] : table) {
    if (node.is_table()) continue;
    const std::string full = (path.empty() ? "" : path + ".") + std::string(name.str());
    std::string line = fmt::format("{} = {}", key_text(name.str()), format_value(node));
    if (auto it = s.units.find(full); it != s.units.end()) line += "  # " + it->second;
    out += line + "\n";
  }
  for (const auto& [name, node] : table) {
    if (!node.is_table()) continue;
    const std::string sub = (path.empty() ? "" : path + ".") + key_text(name.str());
    emit_table(s, *node.as_table(), sub, out);
  }
}

}  // namespace

std::string Config::resolved_toml() const {
  std::string out = fmt::format("# Resolved configuration of {}: every parameter the run read, defaults filled in.\n",
                                state_->source);
  emit_table(*state_, state_->resolved, "", out);
  return out;
}

}  // namespace trapdem
