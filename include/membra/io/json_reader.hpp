#pragma once
// Typed, range-checked reads from a JSON object that reject unknown keys. Every error is an
// InputError naming the JSON pointer of the offending value.
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "membra/core/input_error.hpp"

namespace membra {

// Allowed range of a number; bounds are inclusive unless marked exclusive.
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;

  static Bounds positive() { return {0.0, std::numeric_limits<double>::infinity(), true}; }
  static Bounds non_negative() { return {0.0, std::numeric_limits<double>::infinity(), false}; }
  static Bounds between(double lo, double hi) { return {lo, hi, false}; }
};

class JsonObject {
 public:
  // Checks that `j` is an object whose keys are all in `known`.
  JsonObject(const nlohmann::json& j, std::string pointer, std::vector<std::string_view> known);

  const std::string& pointer() const { return pointer_; }
  std::string pointer(std::string_view key) const { return pointer_ + "/" + std::string(key); }
  bool has(std::string_view key) const;
  const nlohmann::json& at(std::string_view key) const;

  // A number; `fallback` when absent (absent and no fallback is an error).
  double number(std::string_view key, std::optional<double> fallback, Bounds b = {}) const;
  // An integer within [lo, hi].
  long integer(std::string_view key, std::optional<long> fallback, long lo, long hi) const;
  bool boolean(std::string_view key, std::optional<bool> fallback) const;
  // A string; if `choices` is not empty it must be one of them.
  std::string string(std::string_view key, std::optional<std::string> fallback,
                     const std::vector<std::string_view>& choices = {}) const;
  // An array of exactly `count` numbers, each within b.
  std::vector<double> numbers(std::string_view key, size_t count, Bounds b = {}) const;
  // A nested object with its own known keys.
  JsonObject object(std::string_view key, std::vector<std::string_view> known) const;

 private:
  const nlohmann::json& j_;
  std::string pointer_;
};

// Checks a number against bounds; throws InputError at `pointer`.
double checked_number(const nlohmann::json& v, const std::string& pointer, Bounds b);
// A key list as strings (for the schema tests' key maps).
std::vector<std::string> to_strings(const std::vector<std::string_view>& keys);
// The JSON type name of a value, for messages ("string", "array", ...).
std::string json_type_name(const nlohmann::json& v);
// Reads and parses a JSON file. Throws InputError naming the file when it cannot be opened
// ("cannot open the <what> file ...") or is malformed (with line and column).
nlohmann::json read_json_file(const std::filesystem::path& file, const std::string& what);

}  // namespace membra
