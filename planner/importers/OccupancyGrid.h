// Internal to the occupancy-map importer (RosMapImport.cpp): the map as a three-state grid,
// its cleaning (MapCleaning.cpp) and its room segmentation (RoomSegmentation.cpp). OpenCV
// stays in those two .cpp files.
#pragma once

#include "importers/Import.h"

#include <cstdint>
#include <vector>

namespace fc::importing {

// One byte per cell, image order (row 0 at the top).
enum : unsigned char { kOccupied = 0, kFree = 1, kUnknown = 2 };

struct OccupancyGrid {
    int width = 0, height = 0;
    double resolution = 0; // m per cell
    std::vector<unsigned char> cells;
};

// The cells to trace as floor (1) or not (0), and what each cleaning step removed:
// unknown cells as walls (or floor), obstacle specks below the speckle area made floor, the
// free space closed and then opened by discs, free islands below the fragment area dropped.
std::vector<unsigned char> cleanOccupancyGrid(const OccupancyGrid& grid,
                                              const MapCleaningOptions& options,
                                              double robotDiameter, MapCleaningReport& report);

// Splits the free cells (1) into rooms at their narrow places: the room label (1..n) of
// every free cell, 0 elsewhere. `rooms` receives n.
std::vector<std::int32_t> segmentRooms(const std::vector<unsigned char>& free, int width,
                                       int height, double resolution,
                                       const RoomSegmentationOptions& options, int& rooms);

// Every cell labelled with the label of its nearest labelled (> 0) cell: the rooms' territories
// tile the whole map, walls included, so that a room cut by the floor ends on its walls.
std::vector<std::int32_t> labelTerritories(const std::vector<std::int32_t>& labels, int width,
                                           int height);

} // namespace fc::importing
