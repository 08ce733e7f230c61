// Minimal command-line parsing: "--name value" options and positional arguments.
#pragma once

#include "model/Plan.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fc::cli {

class Arguments {
public:
    // flags: option names that take no value (e.g. "--help").
    Arguments(int argc, char** argv, int first, const std::vector<std::string>& flags);

    const std::vector<std::string>& positional() const { return positional_; }
    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::optional<std::string> text(const std::string& name) const;
    // Parsed values; throw InputError naming the option when malformed.
    std::optional<double> number(const std::string& name) const;
    std::optional<long long> integer(const std::string& name) const;
    std::optional<Vec2> point(const std::string& name) const;     // "X,Y"
    std::vector<std::string> list(const std::string& name) const; // "A,B"
    // Throws InputError for options not in the allowed list, then for a last option given
    // without its value.
    void allowOnly(const std::vector<std::string>& allowed) const;
    // A copy with option `name` set to `value` (nullopt: removed).
    Arguments with(const std::string& name, const std::optional<std::string>& value) const;

private:
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
    std::optional<std::string> missingValue_; // the last option, given without its value
};

std::vector<std::string> splitList(const std::string& text, char separator = ',');

} // namespace fc::cli
