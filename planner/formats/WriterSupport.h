// Internal helpers shared by the path, zone and drawing writers (not a public interface).
#pragma once

#include "formats/PathIO.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fc::formats {

// `value` rounded to `decimals` places, without "-0.0"; non-finite values pass through.
double rounded(double value, int decimals);
// Fixed-point text with trailing zeros trimmed ("12.5", "4.0"); keeps sub-millimetre
// precision for UTM-sized coordinates, where %g would drop digits.
std::string fixedNumber(double value, int decimals);
// Compact (indent -1) or indented JSON text; invalid UTF-8 is replaced, never thrown.
std::string dumped(const nlohmann::ordered_json& value, int indent);
// Heading (radians, counter-clockwise from +x) of travel from each point to the next.
// Zero-length steps and the last point keep the previous heading.
std::vector<double> headingsOf(const Polyline& points);
// Kind of the segment leaving point i; the last point keeps the kind of the last segment.
const char* kindAt(const CoveragePath& path, size_t i);
// "EPSG:25832" or "local metres (no coordinate reference)": the frame every export states.
std::string frameDescription(const std::optional<int>& epsg);
// Area of a ring (shoelace), always >= 0.
double ringArea(const Ring& ring);

} // namespace fc::formats
