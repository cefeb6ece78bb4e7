#pragma once
// A minimal JSON value for the documents trapdem writes and reads back (metrics.json, run.json,
// study.json, a study's summary.json): null, bool, number, string, array, object (keys kept in
// insertion order), a writer with two-space indentation and a strict parser. Non-finite numbers
// are written as null.
#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace trapdem {

class Json {
 public:
  enum class Type { null, boolean, number, string, array, object };

  Json() = default;                       // null
  Json(std::nullptr_t) {}
  Json(bool b) : type_(Type::boolean), bool_(b) {}
  Json(double x) : type_(Type::number), number_(x) {}
  Json(int x) : Json(static_cast<double>(x)) {}
  Json(long x) : Json(static_cast<double>(x)) {}
  Json(long long x) : Json(static_cast<double>(x)) {}
  Json(unsigned long x) : Json(static_cast<double>(x)) {}
  Json(unsigned x) : Json(static_cast<double>(x)) {}
  Json(std::string s) : type_(Type::string), string_(std::move(s)) {}
  Json(const char* s) : Json(std::string(s)) {}

  static Json array() { Json j; j.type_ = Type::array; return j; }
  static Json object() { Json j; j.type_ = Type::object; return j; }

  Type type() const { return type_; }
  bool is_null() const { return type_ == Type::null; }
  bool as_bool() const;
  double as_number() const;              // null reads as NaN
  const std::string& as_string() const;
  std::size_t size() const;              // elements or members

  // Arrays.
  Json& push_back(Json value);
  const Json& operator[](std::size_t index) const;
  // Objects: set (replacing an existing key) and get; get of a missing key throws.
  Json& set(const std::string& key, Json value);
  bool contains(const std::string& key) const;
  const Json& operator[](const std::string& key) const;
  const std::vector<std::pair<std::string, Json>>& members() const { return members_; }

  std::string dump(int indent = 2) const;
  // Throws InputError "<source>: offset N: ..." on malformed text.
  static Json parse(std::string_view text, const std::string& source = "JSON");

 private:
  void write(std::string& out, int indent, int depth) const;

  Type type_ = Type::null;
  bool bool_ = false;
  double number_ = 0.0;
  std::string string_;
  std::vector<Json> elements_;
  std::vector<std::pair<std::string, Json>> members_;
};

// Reading metrics documents that may lack a value: a member's number, NaN if `object` is not an
// object, lacks `key`, or holds a non-number (null) there; a member, or null.
double json_number_or_nan(const Json& object, const std::string& key);
const Json& json_member_or_null(const Json& object, const std::string& key);

}  // namespace trapdem
