#include "metrics/RoomBreakdown.h"

#include "geometry/Geometry.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace fc {

namespace {

constexpr double kPiece = 0.25; // m

// Index of the first room containing p, or rooms.size() for none; bounding boxes first.
class RoomLocator {
public:
    explicit RoomLocator(const std::vector<Room>& rooms) : rooms_(rooms) {
        for (const Room& room : rooms)
            boxes_.push_back(boundsOf(room.outline));
    }
    size_t roomOf(Vec2 p) const {
        for (size_t i = 0; i < rooms_.size(); ++i)
            if (inside(boxes_[i], p) && pointInRing(rooms_[i].outline, p))
                return i;
        return rooms_.size();
    }

private:
    static bool inside(const BoundingBox& box, Vec2 p) {
        return p.x >= box.minX && p.x <= box.maxX && p.y >= box.minY && p.y <= box.maxY;
    }
    const std::vector<Room>& rooms_;
    std::vector<BoundingBox> boxes_;
};

} // namespace

std::vector<RoomVisit> roomBreakdown(const Plan& plan, const CoveragePath& path,
                                     const RobotProfile& robot,
                                     const Decomposition* decomposition) {
    const size_t outside = plan.rooms.size();
    std::vector<RoomVisit> rows(outside + 1);
    for (size_t i = 0; i < outside; ++i)
        rows[i].room = plan.rooms[i].name;
    if (decomposition) {
        std::map<std::string, double> areas;
        for (const Cell& cell : decomposition->cells)
            if (cell.room >= 0 && cell.room < static_cast<int>(decomposition->roomNames.size()))
                areas[decomposition->roomNames[cell.room]] += ringArea(cell.outline());
        for (size_t i = 0; i < outside; ++i)
            rows[i].area = areas[rows[i].room];
    }
    const RoomLocator locator(plan.rooms);
    int nextOrder = 1;
    const double threshold = std::cos(45.0 * M_PI / 180.0); // as countTurns
    bool haveHeading = false;
    Vec2 heading;
    for (size_t i = 1; i < path.points.size(); ++i) {
        const Vec2 a = path.points[i - 1], b = path.points[i];
        const double length = distance(a, b);
        if (length <= 1e-9)
            continue;
        const Vec2 direction = (b - a) * (1.0 / length);
        if (haveHeading && dot(heading, direction) <= threshold + 1e-12)
            ++rows[locator.roomOf(a)].turns;
        heading = direction;
        haveHeading = true;
        const bool sweeping =
            i - 1 < path.kinds.size() && path.kinds[i - 1] != SegmentKind::Transit;
        const int pieces = std::max(1, static_cast<int>(std::ceil(length / kPiece)));
        for (int k = 0; k < pieces; ++k) {
            const Vec2 mid = a + (b - a) * ((k + 0.5) / pieces);
            RoomVisit& row = rows[locator.roomOf(mid)];
            row.length += length / pieces;
            if (sweeping && row.order == 0 && &row != &rows[outside])
                row.order = nextOrder++;
        }
    }
    for (RoomVisit& row : rows)
        row.time = (robot.speed > 0 ? row.length / robot.speed : 0.0) + row.turns * robot.turnTime;
    RoomVisit outsideRow = rows[outside];
    rows.pop_back();
    std::stable_sort(rows.begin(), rows.end(), [](const RoomVisit& x, const RoomVisit& y) {
        const int ox = x.order ? x.order : 1 << 30, oy = y.order ? y.order : 1 << 30;
        return ox < oy;
    });
    if (outsideRow.length > 0 || outsideRow.turns > 0)
        rows.push_back(outsideRow);
    return rows;
}

} // namespace fc
