#include "core/json.hpp"

#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "core/errors.hpp"
#include "core/text_escape.hpp"

namespace trapdem {

bool Json::as_bool() const {
  if (type_ != Type::boolean) throw InputError("JSON: not a boolean");
  return bool_;
}

double Json::as_number() const {
  if (type_ == Type::null) return std::numeric_limits<double>::quiet_NaN();
  if (type_ != Type::number) throw InputError("JSON: not a number");
  return number_;
}

const std::string& Json::as_string() const {
  if (type_ != Type::string) throw InputError("JSON: not a string");
  return string_;
}

std::size_t Json::size() const { return type_ == Type::array ? elements_.size() : members_.size(); }

Json& Json::push_back(Json value) {
  if (type_ != Type::array) throw InputError("JSON: push_back on a non-array");
  elements_.push_back(std::move(value));
  return elements_.back();
}

const Json& Json::operator[](std::size_t index) const {
  if (type_ != Type::array || index >= elements_.size()) throw InputError(fmt::format("JSON: no element {}", index));
  return elements_[index];
}

Json& Json::set(const std::string& key, Json value) {
  if (type_ != Type::object) throw InputError("JSON: set on a non-object");
  for (auto& [k, v] : members_) {
    if (k == key) return v = std::move(value);
  }
  members_.emplace_back(key, std::move(value));
  return members_.back().second;
}

bool Json::contains(const std::string& key) const {
  for (const auto& m : members_) {
    if (m.first == key) return true;
  }
  return false;
}

const Json& Json::operator[](const std::string& key) const {
  for (const auto& [k, v] : members_) {
    if (k == key) return v;
  }
  throw InputError("JSON: no member '" + key + "'");
}

namespace {


}  // namespace

void Json::write(std::string& out, int indent, int depth) const {
  const std::string pad(static_cast<std::size_t>(indent * (depth + 1)), ' ');
  const std::string pad_end(static_cast<std::size_t>(indent * depth), ' ');
  switch (type_) {
    case Type::null: out += "null"; break;
    case Type::boolean: out += bool_ ? "true" : "false"; break;
    case Type::number:
      if (!std::isfinite(number_)) out += "null";
      else if (number_ == std::floor(number_) && std::abs(number_) < 1e15) out += fmt::format("{}", static_cast<long long>(number_));
      else out += fmt::format("{}", number_);  // shortest round-trip representation
      break;
    case Type::string: out += quoted(string_); break;
    case Type::array: {
      // Arrays of numbers stay on one line.
      bool flat = true;
      for (const auto& e : elements_) flat = flat && (e.type_ != Type::array && e.type_ != Type::object);
      out += '[';
      for (std::size_t k = 0; k < elements_.size(); ++k) {
        if (k) out += flat ? ", " : ",";
        if (!flat) out += "\n" + pad;
        elements_[k].write(out, indent, depth + 1);
      }
      if (!flat && !elements_.empty()) out += "\n" + pad_end;
      out += ']';
      break;
    }
    case Type::object:
      out += '{';
      for (std::size_t k = 0; k < members_.size(); ++k) {
        if (k) out += ',';
        out += "\n" + pad;
        out += quoted(members_[k].first);
        out += ": ";
        members_[k].second.write(out, indent, depth + 1);
      }
      if (!members_.empty()) out += "\n" + pad_end;
      out += '}';
      break;
  }
}

std::string Json::dump(int indent) const {
  std::string out;
  write(out, indent, 0);
  out += '\n';
  return out;
}

namespace {

class Parser {
 public:
  Parser(std::string_view text, const std::string& source) : s_(text), source_(source) {}

  Json document() {
    Json v = value();
    skip();
    if (i_ != s_.size()) fail("text after the value");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(fmt::format("{}: offset {}: {}", source_, i_, what));
  }
  void skip() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
  }
  bool literal(std::string_view word) {
    if (s_.substr(i_, word.size()) == word) {
      i_ += word.size();
      return true;
    }
    return false;
  }
  std::string string() {
    if (i_ >= s_.size() || s_[i_] != '"') fail("expected a string");
    ++i_;
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      char c = s_[i_++];
      if (c == '\\') {
        if (i_ >= s_.size()) fail("unterminated escape");
        const char e = s_[i_++];
        switch (e) {
          case 'n': out += '\n'; break;
          case 't': out += '\t'; break;
          case 'r': out += '\r'; break;
          case 'b': out += '\b'; break;
          case 'f': out += '\f'; break;
          case 'u': {
            if (i_ + 4 > s_.size()) fail("short \\u escape");
            unsigned code = 0;
            const auto [end, ec] = std::from_chars(s_.data() + i_, s_.data() + i_ + 4, code, 16);
            if (ec != std::errc() || end != s_.data() + i_ + 4) fail("expected four hex digits after \\u");
            i_ += 4;
            if (code < 0x80) out += static_cast<char>(code);
            else out += '?';
            break;
          }
          default: out += e;
        }
      } else {
        out += c;
      }
    }
    if (i_ >= s_.size()) fail("unterminated string");
    ++i_;
    return out;
  }
  // Objects and arrays nest at most this deep: the parser (and a Json's destructor) recurse once
  // per level, and a damaged or hostile file must not reach the end of the stack (issue 14).
  static constexpr int kMaxDepth = 256;
  struct Nesting {
    Parser& p;
    explicit Nesting(Parser& parser) : p(parser) {
      if (++p.depth_ > kMaxDepth) p.fail(fmt::format("objects and arrays nested deeper than {}", kMaxDepth));
    }
    ~Nesting() { --p.depth_; }
  };

  Json value() {
    skip();
    if (i_ >= s_.size()) fail("unexpected end");
    const char c = s_[i_];
    if (c == '{' || c == '[') return nested(c);
    return scalar(c);
  }
  Json nested(char c) {
    const Nesting level(*this);
    if (c == '{') {
      ++i_;
      Json o = Json::object();
      skip();
      if (i_ < s_.size() && s_[i_] == '}') { ++i_; return o; }
      while (true) {
        skip();
        std::string key = string();
        skip();
        if (i_ >= s_.size() || s_[i_] != ':') fail("expected ':'");
        ++i_;
        o.set(key, value());
        skip();
        if (i_ < s_.size() && s_[i_] == ',') { ++i_; continue; }
        if (i_ < s_.size() && s_[i_] == '}') { ++i_; return o; }
        fail("expected ',' or '}'");
      }
    }
    if (c == '[') {
      ++i_;
      Json a = Json::array();
      skip();
      if (i_ < s_.size() && s_[i_] == ']') { ++i_; return a; }
      while (true) {
        a.push_back(value());
        skip();
        if (i_ < s_.size() && s_[i_] == ',') { ++i_; continue; }
        if (i_ < s_.size() && s_[i_] == ']') { ++i_; return a; }
        fail("expected ',' or ']'");
      }
    }
    return scalar(c);
  }
  Json scalar(char c) {
    if (c == '"') return Json(string());
    if (literal("null")) return Json();
    if (literal("true")) return Json(true);
    if (literal("false")) return Json(false);
    double x = 0.0;
    const auto [ptr, ec] = std::from_chars(s_.data() + i_, s_.data() + s_.size(), x);
    if (ec != std::errc()) fail("expected a value");
    i_ = static_cast<std::size_t>(ptr - s_.data());
    return Json(x);
  }

  std::string_view s_;
  const std::string& source_;
  std::size_t i_ = 0;
  int depth_ = 0;  // objects and arrays open at i_
};

}  // namespace

Json Json::parse(std::string_view text, const std::string& source) { return Parser(text, source).document(); }

double json_number_or_nan(const Json& object, const std::string& key) {
  if (object.type() != Json::Type::object || !object.contains(key)) return std::numeric_limits<double>::quiet_NaN();
  const Json& v = object[key];
  return v.type() == Json::Type::number ? v.as_number() : std::numeric_limits<double>::quiet_NaN();
}

const Json& json_member_or_null(const Json& object, const std::string& key) {
  static const Json null;
  if (object.type() != Json::Type::object || !object.contains(key)) return null;
  return object[key];
}

}  // namespace trapdem
