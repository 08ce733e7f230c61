// Occupancy maps rendered from vector plans with simulated SLAM noise (issue 15), seeded, so
// that map cleaning and room segmentation are tested against a known ground truth: the
// plan's free area and its rooms.
#pragma once

#include "model/Plan.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fc::test {

struct NoisyMapOptions {
    double resolution = 0.05; // m per cell
    std::uint64_t seed = 1;
    double wallThickness = 0.1; // m of occupied cells along every wall; beyond: unknown
    double speckle = 0.004;     // share of free cells that become 1-4 cell obstacle specks
    double ragged = 0.35;       // chance that a cell on a wall edge flips free <-> occupied
    double missing = 0.0015;    // share of free cells that start an unknown blob (r 1-3 cells)
    double strayFree = 0.002;   // share of unknown cells seen free (lone laser returns)
};

// A ROS map_server map: 254 free, 0 occupied, 205 unknown; row 0 at the top; the lower-left
// cell's corner at `origin`.
struct NoisyMap {
    int width = 0, height = 0;
    double resolution = 0.05;
    Vec2 origin;
    std::vector<unsigned char> pixels;

    // Writes NAME.pgm and NAME.yaml into `folder`; returns the YAML's path.
    std::string write(const std::string& folder, const std::string& name) const;
};

NoisyMap renderNoisyMap(const Plan& plan, const NoisyMapOptions& options = {});

// Intersection over union of the free cells of a true room (drawn outline) and the best
// matching found room, for each true room, measured on a raster of `resolution` over the
// plan's free space (rooms as given; free space outside every room is left out).
std::vector<double> roomIoUs(const Plan& truth, const std::vector<Room>& found,
                             double resolution = 0.05);

} // namespace fc::test
