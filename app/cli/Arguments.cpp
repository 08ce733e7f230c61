#include "Arguments.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace fc::cli {

Arguments::Arguments(int argc, char** argv, int first, const std::vector<std::string>& flags) {
    for (int i = first; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg.rfind("--", 0) != 0 || arg == "--") {
            positional_.push_back(arg);
            continue;
        }
        const auto eq = arg.find('=');
        if (eq != std::string::npos) {
            values_[arg.substr(0, eq)] = arg.substr(eq + 1);
        } else if (std::find(flags.begin(), flags.end(), arg) != flags.end()) {
            values_[arg] = "";
        } else if (i + 1 < argc) {
            values_[arg] = argv[++i];
        } else {
            // Reported by allowOnly, after an unknown name (a mistyped last option is
            // unknown, not missing its value).
            values_[arg] = "";
            missingValue_ = arg;
        }
    }
}

std::optional<std::string> Arguments::text(const std::string& name) const {
    auto it = values_.find(name);
    if (it == values_.end())
        return std::nullopt;
    return it->second;
}

static double parseNumber(const std::string& name, const std::string& s) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v))
        throw InputError("option " + name + " expects a finite number, got \"" + s + "\"");
    return v;
}

std::optional<double> Arguments::number(const std::string& name) const {
    const auto t = text(name);
    if (!t)
        return std::nullopt;
    return parseNumber(name, *t);
}

std::optional<long long> Arguments::integer(const std::string& name) const {
    const auto t = text(name);
    if (!t)
        return std::nullopt;
    char* end = nullptr;
    const long long v = std::strtoll(t->c_str(), &end, 10);
    if (t->empty() || end != t->c_str() + t->size())
        throw InputError("option " + name + " expects an integer, got \"" + *t + "\"");
    return v;
}

std::optional<Vec2> Arguments::point(const std::string& name) const {
    const auto t = text(name);
    if (!t)
        return std::nullopt;
    const auto parts = splitList(*t);
    if (parts.size() != 2)
        throw InputError("option " + name + " expects X,Y, got \"" + *t + "\"");
    return Vec2{parseNumber(name, parts[0]), parseNumber(name, parts[1])};
}

std::vector<std::string> Arguments::list(const std::string& name) const {
    const auto t = text(name);
    return t ? splitList(*t) : std::vector<std::string>{};
}

void Arguments::allowOnly(const std::vector<std::string>& allowed) const {
    for (const auto& [name, value] : values_)
        if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
            throw InputError("unknown option " + name);
    if (missingValue_)
        throw InputError("option " + *missingValue_ + " needs a value");
}

Arguments Arguments::with(const std::string& name, const std::optional<std::string>& value) const {
    Arguments copy = *this;
    if (value)
        copy.values_[name] = *value;
    else
        copy.values_.erase(name);
    return copy;
}

std::vector<std::string> splitList(const std::string& text, char separator) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : text) {
        if (c == separator) {
            out.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    out.push_back(cur);
    for (std::string& s : out) {
        const auto b = s.find_first_not_of(" \t");
        const auto e = s.find_last_not_of(" \t");
        s = b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
    }
    out.erase(std::remove(out.begin(), out.end(), std::string()), out.end());
    return out;
}

} // namespace fc::cli
