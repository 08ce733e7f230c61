// Small plan builders shared by the planner tests.
#pragma once

#include "model/Plan.h"

namespace fc::test {

inline Ring rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// The same plan moved by `offset` (e.g. to UTM-sized coordinates).
inline Plan shifted(Plan plan, Vec2 offset) {
    for (Vec2& p : plan.boundary)
        p = p + offset;
    for (Ring& obstacle : plan.obstacles)
        for (Vec2& p : obstacle)
            p = p + offset;
    for (Room& room : plan.rooms)
        for (Vec2& p : room.outline)
            p = p + offset;
    return plan;
}

} // namespace fc::test
