#include "membra/io/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "membra/core/did_you_mean.hpp"

namespace membra {

std::vector<std::string> to_strings(const std::vector<std::string_view>& keys) {
  return {keys.begin(), keys.end()};
}

std::string json_type_name(const nlohmann::json& v) {
  if (v.is_number()) return "number";
  return v.type_name();
}

double checked_number(const nlohmann::json& v, const std::string& pointer, Bounds b) {
  if (!v.is_number()) throw InputError(pointer, "expected a number, got " + json_type_name(v));
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw InputError(pointer, "must be finite");
  const bool low = b.min_exclusive ? !(x > b.min) : !(x >= b.min);
  if (low || x > b.max) {
    std::ostringstream msg;
    msg << "must be ";
    if (std::isfinite(b.min) && std::isfinite(b.max))
      msg << "in " << (b.min_exclusive ? "(" : "[") << b.min << ", " << b.max << "]";
    else if (std::isfinite(b.min))
      msg << (b.min_exclusive ? "> " : ">= ") << b.min;
    else
      msg << "<= " << b.max;
    msg << ", got " << x;
    throw InputError(pointer, msg.str());
  }
  return x;
}

JsonObject::JsonObject(const nlohmann::json& j, std::string pointer,
                       std::vector<std::string_view> known)
    : j_(j), pointer_(std::move(pointer)) {
  if (!j.is_object())
    throw InputError(pointer_.empty() ? "/" : pointer_,
                     "expected an object, got " + json_type_name(j));
  for (const auto& [key, value] : j.items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string list;
    for (auto k : known) list += (list.empty() ? "" : ", ") + std::string(k);
    throw InputError(this->pointer(key), "unknown key '" + key + "'" + did_you_mean(key, known) +
                                             "; known here: " + list);
  }
}

bool JsonObject::has(std::string_view key) const {
  return j_.contains(std::string(key));
}

const nlohmann::json& JsonObject::at(std::string_view key) const {
  if (!has(key)) throw InputError(pointer(key), "is required");
  return j_.at(std::string(key));
}

double JsonObject::number(std::string_view key, std::optional<double> fallback, Bounds b) const {
  if (!has(key) && fallback) return *fallback;
  return checked_number(at(key), pointer(key), b);
}

long JsonObject::integer(std::string_view key, std::optional<long> fallback, long lo,
                         long hi) const {
  if (!has(key) && fallback) return *fallback;
  const auto& v = at(key);
  if (!v.is_number_integer() &&
      !(v.is_number_float() && std::floor(v.get<double>()) == v.get<double>()))
    throw InputError(pointer(key), "expected an integer, got " + json_type_name(v) +
                                       (v.is_number() ? " " + v.dump() : ""));
  const double x = v.get<double>();
  if (x < static_cast<double>(lo) || x > static_cast<double>(hi))
    throw InputError(pointer(key), "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                                       "], got " + v.dump());
  return static_cast<long>(x);
}

bool JsonObject::boolean(std::string_view key, std::optional<bool> fallback) const {
  if (!has(key) && fallback) return *fallback;
  const auto& v = at(key);
  if (!v.is_boolean())
    throw InputError(pointer(key), "expected true or false, got " + json_type_name(v));
  return v.get<bool>();
}

std::string JsonObject::string(std::string_view key, std::optional<std::string> fallback,
                               const std::vector<std::string_view>& choices) const {
  if (!has(key) && fallback) return *fallback;
  const auto& v = at(key);
  if (!v.is_string()) throw InputError(pointer(key), "expected a string, got " + json_type_name(v));
  std::string s = v.get<std::string>();
  if (!choices.empty() && std::find(choices.begin(), choices.end(), s) == choices.end()) {
    std::string list;
    for (auto c : choices) list += (list.empty() ? "" : ", ") + std::string(c);
    throw InputError(pointer(key), "'" + s + "' is not one of: " + list + did_you_mean(s, choices));
  }
  return s;
}

std::vector<double> JsonObject::numbers(std::string_view key, size_t count, Bounds b) const {
  const auto& v = at(key);
  if (!v.is_array() || v.size() != count)
    throw InputError(
        pointer(key),
        "expected an array of " + std::to_string(count) + " numbers, got " +
            (v.is_array() ? "an array of " + std::to_string(v.size()) : json_type_name(v)));
  std::vector<double> out;
  for (size_t i = 0; i < count; ++i)
    out.push_back(checked_number(v[i], pointer(key) + "/" + std::to_string(i), b));
  return out;
}

JsonObject JsonObject::object(std::string_view key, std::vector<std::string_view> known) const {
  return JsonObject(at(key), pointer(key), std::move(known));
}

nlohmann::json read_json_file(const std::filesystem::path& file, const std::string& what) {
  const std::string name = file.string();
  std::ifstream in(file);
  if (!in)
    throw InputError(name, "cannot open the " + what + " file (does it exist and is it readable?)");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(name, std::string("malformed JSON: ") + e.what());
  }
}

}  // namespace membra
