#include "slam/common/parameters.h"

#include <charconv>
#include <sstream>

#include "evaluator/core/input_error.h"

namespace slamsweep::slam {
namespace {

using evaluator::InputError;

template <typename Number>
Number Parse(const std::string& key, const std::string& text, std::string_view expected) {
  Number value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    throw InputError("parameter " + key + ": expected " + std::string(expected) + ", got '" + text + "'");
  }
  return value;
}

template <typename Value>
std::string Shown(const Value& value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

Parameters::Parameters(std::map<std::string, std::string> given) : given_(std::move(given)) {}

const std::string* Parameters::Given(const std::string& key) {
  const auto found = given_.find(key);
  return found == given_.end() ? nullptr : &found->second;
}

double Parameters::Real(const std::string& key, double fallback) {
  const std::string* text = Given(key);
  const double value = text ? Parse<double>(key, *text, "a number") : fallback;
  used_[key] = Shown(value);
  return value;
}

int Parameters::Integer(const std::string& key, int fallback) {
  const std::string* text = Given(key);
  const int value = text ? Parse<int>(key, *text, "an integer") : fallback;
  used_[key] = Shown(value);
  return value;
}

bool Parameters::Flag(const std::string& key, bool fallback) {
  bool value = fallback;
  if (const std::string* text = Given(key)) {
    if (*text == "true" || *text == "1" || *text == "yes") {
      value = true;
    } else if (*text == "false" || *text == "0" || *text == "no") {
      value = false;
    } else {
      throw InputError("parameter " + key + ": expected true or false, got '" + *text + "'");
    }
  }
  used_[key] = value ? "true" : "false";
  return value;
}

std::string Parameters::Text(const std::string& key, const std::string& fallback) {
  const std::string* text = Given(key);
  std::string value = text ? *text : fallback;
  used_[key] = value;
  return value;
}

std::vector<std::string> Parameters::GivenKeys() const {
  std::vector<std::string> keys;
  for (const auto& [key, value] : given_) keys.push_back(key);
  return keys;
}

void Parameters::RejectUnread(std::string_view algorithm) const {
  std::string unknown;
  for (const auto& [key, value] : given_) {
    if (used_.contains(key)) continue;
    unknown += (unknown.empty() ? "" : ", ") + key;
  }
  if (unknown.empty()) return;
  std::string accepted;
  for (const auto& [key, value] : used_) accepted += (accepted.empty() ? "" : ", ") + key;
  throw InputError("unknown parameter(s) for " + std::string(algorithm) + ": " + unknown + " (accepted: " + accepted +
                   ")");
}

}  // namespace slamsweep::slam
