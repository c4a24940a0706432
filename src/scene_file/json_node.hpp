// A place in a scene file's JSON: the value, its JSON pointer and the file's name, so every
// problem is reported as "file: /pointer: what is wrong". Typed reads check the JSON type, that
// numbers are finite and in range, and each object's keys against the ones its section knows.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>

#include "simdphys/math.hpp"

namespace simdphys::scenefile {

using Json = nlohmann::json;

class Node {
 public:
  Node(const Json& value, std::string pointer, const std::string& file)
      : value_(&value), pointer_(std::move(pointer)), file_(&file) {}

  const Json& json() const { return *value_; }
  const std::string& pointer() const { return pointer_; }
  const std::string& file() const { return *file_; }
  [[noreturn]] void fail(const std::string& problem) const;
  // "file: /pointer", the prefix of fail()'s messages: the `where` of the library's checks.
  std::string where() const;

  // Objects. require(): the member or "missing field"; find(): the member if present. keys():
  // every member must be one of these (an unknown key is a typo the user wants to hear of).
  Node require(const char* key) const;
  std::optional<Node> find(const char* key) const;
  void keys(std::initializer_list<const char*> known) const;
  // Arrays: the element count (checked to be an array, of at most `max` elements) and an element.
  std::size_t size(std::size_t max = SIZE_MAX) const;
  Node operator[](std::size_t i) const;

  // Scalars, each checked: a finite number in [min, max], an integer in [min, max], a bool, a
  // string, or one of a set of names.
  double number(double min = -kMaxCoordinate, double max = kMaxCoordinate) const;
  std::int64_t integer(std::int64_t min, std::int64_t max) const;
  bool boolean() const;
  std::string string() const;
  double positive(double max = kMaxCoordinate) const;  // a finite number in (0, max]
  Vec3f vec3(double min = -kMaxCoordinate, double max = kMaxCoordinate) const;
  Vec3f positiveVec3(double max = kMaxCoordinate) const;

  // A member read into `out` if present (else `out` keeps its default), with the checks above.
  void read(const char* key, float& out, double min = -kMaxCoordinate,
            double max = kMaxCoordinate) const;
  void readPositive(const char* key, float& out, double max = kMaxCoordinate) const;
  void read(const char* key, int& out, int min, int max) const;
  void read(const char* key, bool& out) const;
  void read(const char* key, Vec3f& out, double min = -kMaxCoordinate,
            double max = kMaxCoordinate) const;

 private:
  const char* typeName() const;
  const Json* value_;
  std::string pointer_;
  const std::string* file_;
};

// A number as the errors print it: shortest round trip.
std::string show(double value);

}  // namespace simdphys::scenefile
