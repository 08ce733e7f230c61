#include "canvas/Snapper.h"

#include "document/Conversions.h"
#include "document/Document.h"

#include <cmath>
#include <optional>

namespace fc::ui {

namespace {

void considerRing(const Ring& ring, Vec2 p, double& bestDistance, std::optional<Vec2>& best) {
    for (Vec2 v : ring) {
        const double d = distance(v, p);
        if (d < bestDistance) {
            bestDistance = d;
            best = v;
        }
    }
}

} // namespace

QPointF Snapper::snap(QPointF position, const Document* document, double gridStep,
                      double metresPerPixel) const {
    if (snapToVertices && document) {
        const Vec2 p = toVec2(position);
        double bestDistance = vertexTolerancePixels * metresPerPixel;
        std::optional<Vec2> best;
        const Plan& plan = document->plan();
        considerRing(plan.boundary, p, bestDistance, best);
        for (const Ring& obstacle : plan.obstacles)
            considerRing(obstacle, p, bestDistance, best);
        for (const Room& room : plan.rooms)
            considerRing(room.outline, p, bestDistance, best);
        if (best)
            return toQt(*best);
    }
    if (snapToGrid && gridStep > 0)
        return {std::round(position.x() / gridStep) * gridStep,
                std::round(position.y() / gridStep) * gridStep};
    return position;
}

QPointF snapToRightAngle(QPointF position, QPointF last, std::optional<QPointF> previous) {
    Vec2 along(1, 0);
    if (previous && *previous != last) {
        const Vec2 d = toVec2(last - *previous);
        along = d * (1.0 / norm(d));
    }
    const Vec2 across(-along.y, along.x);
    const Vec2 offset = toVec2(position - last);
    const Vec2 onAlong = along * dot(offset, along), onAcross = across * dot(offset, across);
    // Keep the larger component: the cursor is closer to that line.
    return last + toQt(norm(onAlong) >= norm(onAcross) ? onAlong : onAcross);
}

} // namespace fc::ui
