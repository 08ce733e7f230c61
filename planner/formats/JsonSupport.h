// Internal helpers shared by the plan and project readers/writers (not a public interface).
#pragma once

#include "model/Plan.h"

#include <nlohmann/json.hpp>
#include <string>

namespace fc::formats {

// Parses a JSON document; throws InputError for an empty file, truncated or invalid JSON
// (with the line and column) and numbers out of the double range.
nlohmann::json parseJsonDocument(const std::string& text);

// A short, one-line rendering of a JSON value for error messages.
std::string describeJsonValue(const nlohmann::json& value);

// Reads a ring given as an array of [x, y] positions. The closing vertex, when repeated,
// is dropped. `what` names the ring in messages ("boundary", "obstacle 3 (feature 5)").
// Throws InputError for non-numeric or non-finite coordinates and fewer than 3 distinct
// points.
Ring ringFromJson(const nlohmann::json& positions, const std::string& what);

// [[x, y], ...]; `closed` repeats the first vertex at the end (GeoJSON).
nlohmann::ordered_json ringToJson(const Ring& ring, bool closed);

// A copy of the ring, reversed if needed to run counter-clockwise (ccw = true) or clockwise.
Ring orientedRing(const Ring& ring, bool counterClockwise);

} // namespace fc::formats
