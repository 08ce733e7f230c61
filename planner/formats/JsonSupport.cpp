#include "formats/JsonSupport.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fc::formats {

namespace {

// nlohmann messages start with "[json.exception.parse_error.101] "; users need the rest.
std::string withoutExceptionTag(const std::string& message) {
    if (!message.empty() && message.front() == '[') {
        const size_t close = message.find("] ");
        if (close != std::string::npos)
            return message.substr(close + 2);
    }
    return message;
}

std::string lineAndColumnOf(const std::string& text, size_t offset) {
    size_t line = 1, column = 1;
    for (size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// "number overflow parsing '1e400'": nlohmann gives no position, so find the literal.
std::string describeNumberOverflow(const std::string& text, const std::string& message) {
    const size_t open = message.find('\'');
    const size_t close = open == std::string::npos ? open : message.find('\'', open + 1);
    if (close == std::string::npos)
        return "a number is out of range: " + withoutExceptionTag(message);
    const std::string literal = message.substr(open + 1, close - open - 1);
    std::string where;
    const size_t at = text.find(literal);
    if (at != std::string::npos)
        where = " at " + lineAndColumnOf(text, at);
    return "number " + literal + where + " is out of range (not a finite coordinate)";
}

} // namespace

nlohmann::json parseJsonDocument(const std::string& text) {
    if (text.find_first_not_of(" \t\r\n") == std::string::npos)
        throw InputError("file is empty");
    // nlohmann's parser stops at a NUL byte and calls the file truncated.
    if (const size_t nul = text.find('\0'); nul != std::string::npos)
        throw InputError("not a JSON text file (a NUL byte at offset " + std::to_string(nul) +
                         "): is it a binary file?");
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        const std::string detail = withoutExceptionTag(e.what());
        if (detail.find("unexpected end of input") != std::string::npos)
            throw InputError("truncated JSON: " + detail);
        throw InputError("invalid JSON: " + detail);
    } catch (const nlohmann::json::out_of_range& e) {
        throw InputError(describeNumberOverflow(text, e.what()));
    } catch (const nlohmann::json::exception& e) {
        throw InputError("invalid JSON: " + withoutExceptionTag(e.what()));
    }
}

std::string describeJsonValue(const nlohmann::json& value) {
    std::string text = value.dump();
    constexpr size_t kMaxLength = 40;
    if (text.size() > kMaxLength)
        text = text.substr(0, kMaxLength - 3) + "...";
    return text;
}

Ring ringFromJson(const nlohmann::json& positions, const std::string& what) {
    if (!positions.is_array())
        throw InputError(what + ": coordinates must be an array of [x, y] positions (got " +
                         describeJsonValue(positions) + ")");
    Ring ring;
    ring.reserve(positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
        const nlohmann::json& position = positions[i];
        const std::string vertex = what + ": vertex " + std::to_string(i + 1);
        if (!position.is_array() || position.size() < 2)
            throw InputError(vertex + " is not an [x, y] position (got " +
                             describeJsonValue(position) + ")");
        for (size_t axis = 0; axis < 2; ++axis) {
            if (!position[axis].is_number())
                throw InputError(vertex + " has a non-numeric coordinate (got " +
                                 describeJsonValue(position[axis]) + ")");
        }
        const Vec2 p{position[0].get<double>(), position[1].get<double>()};
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            throw InputError(vertex + " has a non-finite coordinate");
        ring.push_back(p);
    }
    if (ring.size() > 1 && ring.front() == ring.back())
        ring.pop_back();
    std::vector<std::pair<double, double>> distinct;
    distinct.reserve(ring.size());
    for (const Vec2& p : ring)
        distinct.emplace_back(p.x, p.y);
    std::sort(distinct.begin(), distinct.end());
    const size_t distinctCount = std::unique(distinct.begin(), distinct.end()) - distinct.begin();
    if (distinctCount < 3)
        throw InputError(what + " has only " + std::to_string(distinctCount) +
                         " distinct points; a ring needs at least 3");
    return ring;
}

nlohmann::ordered_json ringToJson(const Ring& ring, bool closed) {
    nlohmann::ordered_json positions = nlohmann::ordered_json::array();
    for (const Vec2& p : ring)
        positions.push_back({p.x, p.y});
    if (closed && !ring.empty())
        positions.push_back({ring.front().x, ring.front().y});
    return positions;
}

Ring orientedRing(const Ring& ring, bool counterClockwise) {
    Ring out = ring;
    const double area = signedArea(out);
    if (area != 0.0 && (area > 0.0) != counterClockwise)
        std::reverse(out.begin(), out.end());
    return out;
}

} // namespace fc::formats
