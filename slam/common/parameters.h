#pragma once

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace slamsweep::slam {

/// A driver's key=value parameters, read by type with the upstream default as fallback. Every key
/// read is remembered, so that RejectUnread can refuse a misspelt name before the first scan
/// instead of silently running with the default.
class Parameters {
 public:
  explicit Parameters(std::map<std::string, std::string> given);

  double Real(const std::string& key, double fallback);
  int Integer(const std::string& key, int fallback);
  /// true/false, 1/0, yes/no.
  bool Flag(const std::string& key, bool fallback);
  std::string Text(const std::string& key, const std::string& fallback);
  bool Has(const std::string& key) const { return given_.contains(key); }
  /// The names given on the command line, for an algorithm whose options are an open set it
  /// validates itself (Cartographer's Lua paths); each still has to be read to count as known.
  std::vector<std::string> GivenKeys() const;

  /// InputError "unknown parameter(s) for <algorithm>: a, b (accepted: ...)" when a given key was never read.
  void RejectUnread(std::string_view algorithm) const;
  /// Every key read so far with the value used (given or default), for the driver's log.
  const std::map<std::string, std::string>& Used() const { return used_; }

 private:
  const std::string* Given(const std::string& key);

  std::map<std::string, std::string> given_;
  std::map<std::string, std::string> used_;
};

}  // namespace slamsweep::slam
