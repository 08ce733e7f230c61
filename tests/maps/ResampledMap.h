// Real occupancy maps as another robot's SLAM would have drawn them (issue 15): the cleaning's
// defaults are meant for 2-10 cm maps of buildings drawn at any angle, and the real maps in
// tests/data/real-maps are 4-5 cm and upright.
#pragma once

#include <string>

namespace fc::test {

enum class Resample {
    Finer,    // cells half the size: each cell four
    Coarser,  // twice the size: occupied where any of the four is, else free where any is,
              // else unknown (walls stay closed)
    Turned30, // the building turned by 30 degrees about the map's centre (nearest cell)
};

// Reads the ROS map YAML (trinary: 254 free, 0 occupied, else unknown), writes the
// resampled map as STEM.pgm + STEM.yaml into `folder` (STEM: the image's stem, "-finer",
// "-coarser" or "-turned") and returns that YAML's path. Throws fc::InputError on an
// unreadable map.
std::string resampledMap(const std::string& yamlPath, Resample how, const std::string& folder);

} // namespace fc::test
