// Reading IfcSpace / IfcBuildingStorey names from the STEP text (see IfcNames.h).
#include "importers/IfcNames.h"

#include <cstdint>
#include <vector>

namespace fc::building {

namespace {

void appendUtf8(std::string& out, uint32_t code) {
    if (code < 0x80) {
        out += static_cast<char>(code);
    } else if (code < 0x800) {
        out += static_cast<char>(0xC0 | (code >> 6));
        out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
        out += static_cast<char>(0xE0 | (code >> 12));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (code >> 18));
        out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
    }
}

int hexValue(char c) {
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

// Hex digits at s[i..i+n) as a number, or -1.
long hexNumber(const std::string& s, size_t i, size_t n) {
    if (i + n > s.size())
        return -1;
    long value = 0;
    for (size_t k = 0; k < n; ++k) {
        const int digit = hexValue(s[i + k]);
        if (digit < 0)
            return -1;
        value = value * 16 + digit;
    }
    return value;
}

std::string decodeStepString(const std::string& raw) {
    std::string out;
    for (size_t i = 0; i < raw.size();) {
        if (raw.compare(i, 3, "\\S\\") == 0 && i + 3 < raw.size()) {
            appendUtf8(out, static_cast<unsigned char>(raw[i + 3]) + 128u);
            i += 4;
        } else if (raw.compare(i, 3, "\\X\\") == 0 && hexNumber(raw, i + 3, 2) >= 0) {
            appendUtf8(out, static_cast<uint32_t>(hexNumber(raw, i + 3, 2)));
            i += 5;
        } else if (raw.compare(i, 4, "\\X2\\") == 0) {
            size_t k = i + 4;
            for (long unit; (unit = hexNumber(raw, k, 4)) >= 0; k += 4)
                appendUtf8(out, static_cast<uint32_t>(unit));
            i = raw.compare(k, 4, "\\X0\\") == 0 ? k + 4 : k;
        } else if (raw.compare(i, 2, "\\\\") == 0) {
            out += '\\';
            i += 2;
        } else {
            out += raw[i++];
        }
    }
    return out;
}

// The top-level arguments of the entity whose '(' is at `open`; strings unquoted and decoded,
// everything else as written. Empty when the entity does not close.
std::vector<std::string> entityArguments(const std::string& text, size_t open) {
    std::vector<std::string> args(1);
    int depth = 0;
    for (size_t i = open + 1; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\'') {
            std::string raw;
            for (++i; i < text.size(); ++i) {
                if (text[i] == '\'' && i + 1 < text.size() && text[i + 1] == '\'')
                    raw += text[++i];
                else if (text[i] == '\'')
                    break;
                else
                    raw += text[i];
            }
            args.back() += decodeStepString(raw);
        } else if (c == '(') {
            ++depth;
        } else if (c == ')') {
            if (depth-- == 0)
                return args;
        } else if (c == ',' && depth == 0) {
            args.emplace_back();
        } else if (c == ';') {
            break;
        } else if (depth == 0 && c != ' ' && c != '\n' && c != '\r') {
            args.back() += c;
        }
    }
    return {};
}

} // namespace

std::map<std::string, IfcNames> readIfcNames(const std::string& stepText) {
    std::map<std::string, IfcNames> names;
    for (const std::string keyword : {"IFCSPACE(", "IFCBUILDINGSTOREY("}) {
        for (size_t at = stepText.find(keyword); at != std::string::npos;
             at = stepText.find(keyword, at + 1)) {
            if (at > 0 && stepText[at - 1] != '=' && stepText[at - 1] != ' ')
                continue;
            const auto args = entityArguments(stepText, at + keyword.size() - 1);
            if (args.size() < 8 || args[0].size() != 22)
                continue;
            names[args[0]] = {args[2] == "$" ? "" : args[2], args[7] == "$" ? "" : args[7]};
        }
    }
    return names;
}

std::string ifcGuidOfNode(const std::string& nodeName) {
    if (nodeName.size() < 24 || nodeName[nodeName.size() - 23] != '_')
        return "";
    return nodeName.substr(nodeName.size() - 22);
}

} // namespace fc::building
