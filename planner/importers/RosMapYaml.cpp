// The ROS map_server YAML (a flat mapping of scalars and [a, b, c] lists) and the PGM image
// format (P2 ASCII, P5 binary): small, fully specified formats read here so that hostile
// input is bounded and every defect names the key or the header field.
#include "importers/ImportSupport.h"

#include <cmath>
#include <sstream>

namespace fc::importing {

namespace {

std::string trim(const std::string& s) {
    const size_t first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos)
        return {};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::string unquoted(const std::string& value) {
    if (value.size() >= 2 && (value.front() == '"' || value.front() == '\'') &&
        value.back() == value.front())
        return value.substr(1, value.size() - 2);
    return value;
}

// Drops a "# comment" that is not inside quotes.
std::string withoutComment(const std::string& line) {
    char quote = 0;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quote) {
            if (c == quote)
                quote = 0;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '#' && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t')) {
            return line.substr(0, i);
        }
    }
    return line;
}

double number(const std::string& key, const std::string& value) {
    try {
        size_t used = 0;
        const double v = std::stod(value, &used);
        if (used == value.size() && std::isfinite(v))
            return v;
    } catch (const std::exception&) {
    }
    throw InputError(key + ": \"" + value + "\" is not a number");
}

std::vector<double> numbers(const std::string& key, const std::string& value, size_t count) {
    if (value.size() < 2 || value.front() != '[' || value.back() != ']')
        throw InputError(key + ": expected a list [" + (count == 3 ? "x, y, yaw" : "...") + "]");
    std::vector<double> out;
    std::stringstream items(value.substr(1, value.size() - 2));
    std::string item;
    while (std::getline(items, item, ','))
        out.push_back(number(key, trim(item)));
    if (out.size() != count)
        throw InputError(key + ": expected " + std::to_string(count) + " numbers, found " +
                         std::to_string(out.size()));
    return out;
}

bool boolean(const std::string& key, const std::string& value) {
    if (value == "0" || value == "false" || value == "False" || value == "no")
        return false;
    if (value == "1" || value == "true" || value == "True" || value == "yes")
        return true;
    throw InputError(key + ": \"" + value + "\" is not 0/1 or true/false");
}

} // namespace

RosMapInfo parseRosMapYaml(const std::string& text) {
    if (text.size() > (1u << 20))
        throw InputError("map YAML larger than 1 MiB");
    RosMapInfo info;
    bool hasResolution = false, hasOrigin = false;
    std::optional<double> amclX, amclY;
    std::stringstream in(text);
    std::string raw;
    for (int lineNumber = 1; std::getline(in, raw); ++lineNumber) {
        const std::string line = withoutComment(raw);
        if (trim(line).empty() || trim(line) == "---" || line[0] == ' ' || line[0] == '\t')
            continue; // blank, document marker, or nested under a key this format ignores
        const size_t colon = line.find(':');
        if (colon == std::string::npos)
            throw InputError("line " + std::to_string(lineNumber) + ": expected \"key: value\"");
        const std::string key = trim(line.substr(0, colon));
        const std::string value = unquoted(trim(line.substr(colon + 1)));
        if (key == "image") {
            info.image = value;
        } else if (key == "resolution") {
            info.resolution = number(key, value);
            hasResolution = true;
        } else if (key == "origin") {
            const std::vector<double> v = numbers(key, value, 3);
            info.origin = {v[0], v[1]};
            info.yaw = v[2];
            hasOrigin = true;
        } else if (key == "occupied_thresh") {
            info.occupiedThresh = number(key, value);
        } else if (key == "free_thresh") {
            info.freeThresh = number(key, value);
        } else if (key == "negate") {
            info.negate = boolean(key, value);
        } else if (key == "mode") {
            info.mode = value;
        } else if (key == "start_pose") {
            const std::vector<double> v = numbers(key, value, 3);
            info.start = Vec2{v[0], v[1]};
        } else if (key == "initial_pose_x") {
            amclX = number(key, value);
        } else if (key == "initial_pose_y") {
            amclY = number(key, value);
        }
    }
    if (info.image.empty())
        throw InputError("no \"image:\" key: not a ROS map_server map");
    if (!hasResolution || !(info.resolution > 0 && info.resolution < 1e4))
        throw InputError("resolution: missing or not a positive size in metres");
    if (info.resolution < 0.001 || info.resolution > 1.0)
        throw InputError("resolution: " + std::to_string(info.resolution) +
                         " m per cell is not an occupancy map's (1 mm to 1 m)");
    if (!hasOrigin)
        throw InputError("origin: missing (expected [x, y, yaw])");
    // Beyond any map frame, UTM included (northings stay below 10,000 km).
    if (std::abs(info.origin.x) > 2e7 || std::abs(info.origin.y) > 2e7 || std::abs(info.yaw) > 100)
        throw InputError("origin: [" + std::to_string(info.origin.x) + ", " +
                         std::to_string(info.origin.y) + ", " + std::to_string(info.yaw) +
                         "] is far outside any map frame");
    if (!(info.freeThresh >= 0 && info.freeThresh < info.occupiedThresh &&
          info.occupiedThresh <= 1))
        throw InputError("thresholds: need 0 <= free_thresh < occupied_thresh <= 1");
    if (info.mode != "trinary" && info.mode != "scale" && info.mode != "raw")
        throw InputError("mode: \"" + info.mode + "\" (expected trinary, scale or raw)");
    if (!info.start && amclX && amclY)
        info.start = Vec2{*amclX, *amclY};
    return info;
}

GreyImage readPgm(const std::string& bytes) {
    size_t at = 0;
    // The next header token (whitespace separated, "#" comments skipped).
    auto token = [&]() {
        while (at < bytes.size()) {
            if (bytes[at] == '#')
                while (at < bytes.size() && bytes[at] != '\n')
                    ++at;
            else if (std::isspace(static_cast<unsigned char>(bytes[at])))
                ++at;
            else
                break;
        }
        const size_t start = at;
        while (at < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[at])) &&
               at - start < 32)
            ++at;
        return bytes.substr(start, at - start);
    };
    auto integer = [&](const char* what) {
        const std::string t = token();
        if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos)
            throw InputError(std::string("PGM ") + what + ": \"" + t + "\" is not a number");
        return std::stol(t);
    };
    const std::string magic = token();
    if (magic != "P2" && magic != "P5" && magic != "P1" && magic != "P4")
        throw InputError("not a PGM or PBM image (expected P1, P2, P4 or P5)");
    const bool bitmap = magic == "P1" || magic == "P4"; // PBM: 1 is black
    GreyImage image;
    const long width = integer("width"), height = integer("height");
    const long maxval = bitmap ? 1 : integer("maxval");
    if (width < 1 || height < 1 || maxval < 1 || maxval > 65535)
        throw InputError("PGM header: bad size or maxval");
    if (static_cast<long long>(width) * height > kMaxMapPixels)
        throw InputError("map image larger than " + std::to_string(kMaxMapPixels) + " pixels");
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    auto scaled = [&](long v) {
        return static_cast<unsigned char>(std::lround(255.0 * std::min(v, maxval) / maxval));
    };
    if (magic == "P4") { // rows of packed bits, each row padded to a whole byte
        ++at;
        const size_t rowBytes = (static_cast<size_t>(width) + 7) / 8;
        if (bytes.size() < at + rowBytes * static_cast<size_t>(height))
            throw InputError("PBM data truncated");
        image.grey.resize(pixels);
        for (long y = 0; y < height; ++y)
            for (long x = 0; x < width; ++x) {
                const auto byte = static_cast<unsigned char>(bytes[at + y * rowBytes + x / 8]);
                image.grey[y * width + x] = (byte >> (7 - x % 8)) & 1 ? 0 : 255;
            }
    } else if (magic == "P1") { // one digit per pixel, whitespace optional
        image.grey.resize(pixels);
        for (size_t i = 0; i < pixels; ++i) {
            while (at < bytes.size() &&
                   (std::isspace(static_cast<unsigned char>(bytes[at])) || bytes[at] == '#')) {
                if (bytes[at] == '#')
                    while (at < bytes.size() && bytes[at] != '\n')
                        ++at;
                else
                    ++at;
            }
            if (at >= bytes.size() || (bytes[at] != '0' && bytes[at] != '1'))
                throw InputError("PBM data truncated or not 0/1");
            image.grey[i] = bytes[at++] == '1' ? 0 : 255;
        }
    } else if (magic == "P5") {
        ++at; // the single whitespace after maxval
        const size_t size = maxval > 255 ? 2 : 1;
        if (bytes.size() < at + pixels * size)
            throw InputError("PGM data truncated");
        image.grey.resize(pixels);
        for (size_t i = 0; i < pixels; ++i) {
            const auto* p = reinterpret_cast<const unsigned char*>(bytes.data() + at + i * size);
            image.grey[i] = scaled(size == 2 ? p[0] * 256 + p[1] : p[0]);
        }
    } else {
        if (bytes.size() - at < pixels) // at least one digit per pixel
            throw InputError("PGM data truncated");
        image.grey.resize(pixels);
        for (size_t i = 0; i < pixels; ++i)
            image.grey[i] = scaled(integer("pixel"));
    }
    return image;
}

} // namespace fc::importing
