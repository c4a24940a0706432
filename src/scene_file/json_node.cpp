#include "json_node.hpp"

#include <charconv>
#include <cmath>

#include "simdphys/core.hpp"

namespace simdphys::scenefile {

std::string show(double value) {
  char text[32];
  // A float (as kMaxCoordinate) printed as the float it is: 1e+18, not 999999984306749440.
  const float f = float(value);
  const auto end = double(f) == value ? std::to_chars(text, text + sizeof text, f).ptr
                                      : std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

std::string Node::where() const { return *file_ + ": " + (pointer_.empty() ? "/" : pointer_); }

void Node::fail(const std::string& problem) const { throw Error(where() + ": " + problem); }

const char* Node::typeName() const {
  switch (value_->type()) {
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::null:
      return "null";
    default:
      return "a number";
  }
}

Node Node::require(const char* key) const {
  if (auto member = find(key)) return *member;
  fail(std::string("missing field \"") + key + "\"");
}

std::optional<Node> Node::find(const char* key) const {
  if (!value_->is_object()) fail(std::string("must be an object, got ") + typeName());
  const auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  // JSON pointer escapes (RFC 6901) for keys holding '~' or '/'.
  std::string escaped;
  for (const char c : std::string_view(key))
    escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return Node(*it, pointer_ + "/" + escaped, *file_);
}

void Node::keys(std::initializer_list<const char*> known) const {
  if (!value_->is_object()) fail(std::string("must be an object, got ") + typeName());
  for (const auto& [key, value] : value_->items()) {
    bool found = false;
    for (const char* k : known) found = found || key == k;
    if (found) continue;
    std::string list;
    for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
    Node(value, pointer_ + "/" + key, *file_).fail("unknown field (known here: " + list + ")");
  }
}

std::size_t Node::size(std::size_t max) const {
  if (!value_->is_array()) fail(std::string("must be an array, got ") + typeName());
  if (value_->size() > max)
    fail("holds " + std::to_string(value_->size()) + " elements, more than the " +
         std::to_string(max) + " allowed");
  return value_->size();
}

Node Node::operator[](std::size_t i) const {
  return Node((*value_)[i], pointer_ + "/" + std::to_string(i), *file_);
}

double Node::number(double min, double max) const {
  if (!value_->is_number()) {
    if (value_->is_string())
      fail("must be a number, got the string \"" + value_->get<std::string>().substr(0, 40) +
           "\" (JSON has no NaN or infinity)");
    fail(std::string("must be a number, got ") + typeName());
  }
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail("must be finite, got " + show(v));
  if (v < min || v > max) fail("must be in [" + show(min) + ", " + show(max) + "], got " + show(v));
  return v;
}

double Node::positive(double max) const {
  const double v = number(-max, max);
  if (!(v > 0) || float(v) == 0) fail("must be positive, got " + show(v));
  return v;
}

std::int64_t Node::integer(std::int64_t min, std::int64_t max) const {
  const double v = number(-1e300, 1e300);
  if (v != std::floor(v)) fail("must be a whole number, got " + show(v));
  const bool exact = std::abs(v) < 0x1p53;  // printed as the integer it is
  if (v < double(min) || v > double(max))
    fail("must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
         (exact ? std::to_string(std::int64_t(v)) : show(v)));
  return std::int64_t(v);
}

bool Node::boolean() const {
  if (!value_->is_boolean()) fail(std::string("must be true or false, got ") + typeName());
  return value_->get<bool>();
}

std::string Node::string() const {
  if (!value_->is_string()) fail(std::string("must be a string, got ") + typeName());
  return value_->get<std::string>();
}

Vec3f Node::vec3(double min, double max) const {
  if (size() != 3) fail("must be an array of 3 numbers, got " + std::to_string(size()));
  return {float((*this)[0].number(min, max)), float((*this)[1].number(min, max)),
          float((*this)[2].number(min, max))};
}

Vec3f Node::positiveVec3(double max) const {
  if (size() != 3) fail("must be an array of 3 numbers, got " + std::to_string(size()));
  return {float((*this)[0].positive(max)), float((*this)[1].positive(max)),
          float((*this)[2].positive(max))};
}

void Node::readPositive(const char* key, float& out, double max) const {
  if (auto n = find(key)) out = float(n->positive(max));
}
void Node::read(const char* key, float& out, double min, double max) const {
  if (auto n = find(key)) out = float(n->number(min, max));
}
void Node::read(const char* key, int& out, int min, int max) const {
  if (auto n = find(key)) out = int(n->integer(min, max));
}
void Node::read(const char* key, bool& out) const {
  if (auto n = find(key)) out = n->boolean();
}
void Node::read(const char* key, Vec3f& out, double min, double max) const {
  if (auto n = find(key)) out = n->vec3(min, max);
}

}  // namespace simdphys::scenefile
