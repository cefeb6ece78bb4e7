#pragma once
// A resumed run must be the run that was started (issue 14): the checkpoint carries the whole
// resolved configuration the run was started with and its digest, and a resume compares them
// with the configuration it would run, key by key.
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace trapdem {

class Config;

// The resolved configuration's values as TOML (Config::resolved_toml() without its header comment,
// which names the file read): equal texts, equal runs.
std::string resolved_values(const Config& config);

// A 64-bit FNV-1a digest of `text`, as 16 hex digits.
std::string config_digest(std::string_view text);

// Every value of a TOML text by its dotted key, as TOML value text ("0.5", "[0.0, 0.001]"), the
// output-only [derived] table left out; `name` stands for the text in messages.
std::map<std::string, std::string> value_leaves(std::string_view toml, const char* name);

struct ConfigChange {
  std::string key;      // dotted
  std::string before;   // TOML value text in the run that was started, or "(absent)"
  std::string after;    // in the configuration now
};

// A run's resolved configuration as this trapdem reads it (its resolved_values()): `resolved` read
// and checked as a run's configuration, so that a key added to trapdem since the text was written
// comes in at its default (a new key's default keeps the old behaviour) and the two texts compare
// key by key. Throws InputError, naming `name`, for a text this trapdem does not read (a key
// retired since, a value out of range).
std::string as_read_now(std::string_view resolved, const char* name);

// The keys whose values differ between two resolved_values() texts, in key order; the
// output-only [derived] table is left out (it follows from the keys).
std::vector<ConfigChange> config_changes(std::string_view started, std::string_view now);

}  // namespace trapdem
